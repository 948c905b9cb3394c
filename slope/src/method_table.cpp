// The methods of slices as one table (method_table.hpp): keys, solvers, slice forces, lambda, work sharing.
#include "method_table.hpp"

#include <cmath>

namespace slope::detail {

void general_forces(const SliceTable& t, MethodWorkspace& ws, bool half_sine, double F, double lambda,
                    std::vector<SliceForces>& forces);

namespace {

// Ordinary (Fellenius) and Bishop simplified base forces; no interslice forces are reported (Bishop's are
// horizontal and not solved for).
void moment_method_forces(const SliceTable& t, bool bishop, double F, std::vector<SliceForces>& forces) {
  forces.assign(static_cast<std::size_t>(t.count), SliceForces{});
  for (int i = 0; i < t.count; ++i) {
    const double c = t.cos_a[i];
    const double s = t.sin_a[i];
    double effective_normal;
    if (!bishop) {
      effective_normal = t.vertical[i] * c - t.horizontal[i] * s - t.pore_force[i];
    } else {
      const double m = c + s * t.tan_phi[i] / F;
      effective_normal = (t.vertical[i] - t.pore_force[i] * c - t.cohesion_force[i] * s / F) / m;
    }
    SliceForces& f = forces[static_cast<std::size_t>(i)];
    f.normal = effective_normal + t.pore_force[i];
    f.shear = (t.cohesion_force[i] + effective_normal * t.tan_phi[i]) / F;
    f.pore_force = t.pore_force[i];
  }
}

Outcome solve_ordinary(const SliceTable& t, MethodWorkspace&, double) { return ordinary_method(t); }
Outcome solve_bishop(const SliceTable& t, MethodWorkspace& ws, double guess) { return bishop_method(t, ws, guess); }
Outcome solve_janbu(const SliceTable& t, MethodWorkspace& ws, double guess) { return janbu_method(t, ws, guess); }
Outcome solve_spencer(const SliceTable& t, MethodWorkspace& ws, double guess) {
  return general_limit_equilibrium(t, ws, false, guess);
}
Outcome solve_half_sine(const SliceTable& t, MethodWorkspace& ws, double guess) {
  return general_limit_equilibrium(t, ws, true, guess);
}

// Janbu (1973): the simplified value times the empirical f0; the uncorrected value is kept for the slice forces.
Outcome janbu_corrected_from_janbu(const SliceTable& t, Outcome out) {
  if (!out.ok()) return out;
  out.value = out.factor_of_safety;
  out.factor_of_safety *= janbu_correction_factor(t);
  // f0 = 1 + b1 (d/L - 1.4 (d/L)^2) turns negative for d/L above about 1.6 (far outside Janbu's chart): never
  // report such a product as a factor of safety.
  if (!(out.factor_of_safety > 0.0) || !std::isfinite(out.factor_of_safety)) out.failure = Failure::not_positive;
  return out;
}

void ordinary_forces(const SliceTable& t, MethodWorkspace&, const Outcome& o, std::vector<SliceForces>& f) {
  moment_method_forces(t, false, o.factor_of_safety, f);
}
void bishop_forces(const SliceTable& t, MethodWorkspace&, const Outcome& o, std::vector<SliceForces>& f) {
  moment_method_forces(t, true, o.factor_of_safety, f);
}
void janbu_forces(const SliceTable& t, MethodWorkspace& ws, const Outcome& o, std::vector<SliceForces>& f) {
  general_forces(t, ws, false, o.factor_of_safety, 0.0, f);
}
void janbu_corrected_forces(const SliceTable& t, MethodWorkspace& ws, const Outcome& o, std::vector<SliceForces>& f) {
  general_forces(t, ws, false, o.value, 0.0, f);  // the forces of the uncorrected equilibrium
}
void spencer_forces(const SliceTable& t, MethodWorkspace& ws, const Outcome& o, std::vector<SliceForces>& f) {
  general_forces(t, ws, false, o.factor_of_safety, o.lambda, f);
}
void half_sine_forces(const SliceTable& t, MethodWorkspace& ws, const Outcome& o, std::vector<SliceForces>& f) {
  general_forces(t, ws, true, o.factor_of_safety, o.lambda, f);
}

constexpr std::array<MethodRow, method_count> rows{{
    // method, key, solve, forces, has_lambda, solution_of, from_solution, warm_start
    {Method::ordinary, "ordinary", solve_ordinary, ordinary_forces, false, Method::ordinary, nullptr, {}},
    {Method::bishop, "bishop", solve_bishop, bishop_forces, false, Method::bishop, nullptr, {}},
    {Method::janbu, "janbu", solve_janbu, janbu_forces, false, Method::janbu, nullptr, {}},
    {Method::janbu_corrected, "janbu_corrected", solve_janbu, janbu_corrected_forces, false, Method::janbu,
     janbu_corrected_from_janbu, {}},
    {Method::spencer, "spencer", solve_spencer, spencer_forces, true, Method::spencer, nullptr, {Method::bishop}},
    {Method::morgenstern_price, "morgenstern_price", solve_half_sine, half_sine_forces, true,
     Method::morgenstern_price, nullptr, {Method::spencer, Method::bishop}},
    {Method::morgenstern_price_constant, "morgenstern_price_constant", solve_spencer, spencer_forces, true,
     Method::spencer, nullptr, {Method::bishop}},
}};

}  // namespace

const std::array<MethodRow, method_count>& method_table() { return rows; }

std::size_t method_index(Method method) {
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (rows[k].method == method) return k;
  return 0;  // unreachable: every enumerator has a row (checked by the keys round-trip test)
}

const MethodRow& method_row(Method method) { return rows[method_index(method)]; }

Outcome evaluate_method(SliceTable& table, Method method, MethodWorkspace& ws, double guess) {
  const MethodRow& row = method_row(method);
  const Outcome solution = solve_row(method_row(row.solution_of), table, ws, guess);
  return row.from_solution ? row.from_solution(table, solution) : solution;
}

void slice_forces(const SliceTable& t, Method method, const Outcome& outcome, MethodWorkspace& ws,
                  std::vector<SliceForces>& forces) {
  method_row(method).forces(t, ws, outcome, forces);
}

}  // namespace slope::detail
