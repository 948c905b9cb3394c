// Method keys, dispatch and the public factor_of_safety().
#include "slope/methods.hpp"

#include <array>
#include <cmath>
#include <sstream>

#include "method_kernels.hpp"

namespace slope {

namespace {
constexpr std::array<std::pair<Method, std::string_view>, 7> method_keys{{
    {Method::ordinary, "ordinary"},
    {Method::bishop, "bishop"},
    {Method::janbu, "janbu"},
    {Method::janbu_corrected, "janbu_corrected"},
    {Method::spencer, "spencer"},
    {Method::morgenstern_price, "morgenstern_price"},
    {Method::morgenstern_price_constant, "morgenstern_price_constant"},
}};
}  // namespace

std::string_view method_key(Method method) {
  for (const auto& [m, key] : method_keys)
    if (m == method) return key;
  return "unknown";
}

std::optional<Method> method_from_key(std::string_view key) {
  for (const auto& [m, k] : method_keys)
    if (k == key) return m;
  return std::nullopt;
}

const std::vector<Method>& all_methods() {
  static const std::vector<Method> methods{Method::ordinary, Method::bishop, Method::janbu, Method::janbu_corrected,
                                           Method::spencer, Method::morgenstern_price,
                                           Method::morgenstern_price_constant};
  return methods;
}

namespace detail {

void general_forces(const SliceTable& t, MethodWorkspace& ws, bool half_sine, double F, double lambda,
                    std::vector<SliceForces>& forces);

Outcome evaluate_method(const SliceTable& table, Method method, MethodWorkspace& ws, double guess) {
  switch (method) {
    case Method::ordinary: return ordinary_method(table);
    case Method::bishop: return bishop_method(table, ws);
    case Method::janbu: return janbu_method(table, ws);
    case Method::janbu_corrected: {
      Outcome out = janbu_method(table, ws);
      if (out.ok()) {
        out.value = out.factor_of_safety;  // the uncorrected value, for the slice forces
        out.factor_of_safety *= janbu_correction_factor(table);
        // f0 = 1 + b1 (d/L - 1.4 (d/L)^2) turns negative for d/L above about 1.6 (far outside Janbu's chart):
        // never report such a product as a factor of safety.
        if (!(out.factor_of_safety > 0.0) || !std::isfinite(out.factor_of_safety)) out.failure = Failure::not_positive;
      }
      return out;
    }
    case Method::spencer:
    case Method::morgenstern_price_constant: return general_limit_equilibrium(table, ws, false, guess);
    case Method::morgenstern_price: return general_limit_equilibrium(table, ws, true, guess);
  }
  return Outcome{0.0, 0.0, 0, Failure::not_converged};
}

void slice_forces(const SliceTable& t, Method method, const Outcome& outcome, MethodWorkspace& ws,
                  std::vector<SliceForces>& forces) {
  const double F = outcome.factor_of_safety;
  switch (method) {
    case Method::ordinary:
    case Method::bishop: {
      forces.assign(static_cast<std::size_t>(t.count), SliceForces{});
      for (int i = 0; i < t.count; ++i) {
        const double c = t.cos_a[i];
        const double s = t.sin_a[i];
        double effective_normal;
        if (method == Method::ordinary) {
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
      return;
    }
    case Method::janbu: general_forces(t, ws, false, F, 0.0, forces); return;
    case Method::janbu_corrected: general_forces(t, ws, false, outcome.value, 0.0, forces); return;
    case Method::spencer:
    case Method::morgenstern_price_constant: general_forces(t, ws, false, F, outcome.lambda, forces); return;
    case Method::morgenstern_price: general_forces(t, ws, true, F, outcome.lambda, forces); return;
  }
}

std::string describe_failure(const Outcome& outcome, const SliceTable& table) {
  std::ostringstream out;
  out.precision(3);
  auto slice_text = [&](int i) {
    if (i < 0 || i >= table.count) return;
    out << " at slice " << i + 1 << " of " << table.count << " (x = " << table.base_x[i]
        << " m, base angle " << std::atan2(table.sin_a[i], table.cos_a[i]) * 180.0 / M_PI << " deg)";
  };
  switch (outcome.failure) {
    case Failure::none: return {};
    case Failure::no_driving_moment:
      out << "no driving moment: the loads do not turn the mass toward its exit (driving moment <= 0)";
      break;
    case Failure::no_driving_force:
      out << "no driving force: the loads do not push the mass toward its exit (sum of V tan(a) + H <= 0)";
      break;
    case Failure::m_alpha:
      out << "m_alpha = cos(a) + sin(a) tan(phi')/F ";
      if (std::isfinite(outcome.value)) out << "= " << outcome.value << " ";
      out << "falls below 0.2";
      slice_text(outcome.slice);
      out << "; the surface is rejected (Whitman & Bailey 1967: the normal force near the toe becomes unreliable)";
      break;
    case Failure::not_converged:
      out << "the factor-of-safety iteration did not converge (for Spencer / Morgenstern-Price: no (F, lambda) "
             "satisfies force and moment equilibrium together)";
      if (outcome.iterations > 0) out << " (" << outcome.iterations << " iterations)";
      break;
    case Failure::not_positive: out << "no positive finite factor of safety balances this surface"; break;
    case Failure::lambda_out_of_range:
      out << "the only (F, lambda) root found has lambda = " << outcome.value
          << ", beyond |lambda| <= " << maximum_lambda << " (an interslice force steeper than about 72 degrees): "
          << "no physical solution";
      break;
    case Failure::negative_strength:
      if (std::isfinite(outcome.value))
        out << "the (F, lambda = " << outcome.value << ") root needs a negative shear strength c' l + N' tan(phi')";
      else
        out << "the solution needs a negative shear strength c' l + N' tan(phi')";
      slice_text(outcome.slice);
      out << " (effective normal tension beyond the Mohr-Coulomb limit): not a physical solution";
      break;
    case Failure::singular_recursion:
      out << "the interslice force recursion breaks down (1 + lambda f k / m_a <= 0 or non-finite forces)";
      slice_text(outcome.slice);
      break;
  }
  return out.str();
}

}  // namespace detail

FsResult factor_of_safety(const SlipMass& mass, Method method, bool with_forces) {
  FsResult result;
  if (mass.slices.empty()) {
    result.error = "the slip mass has no slices";
    return result;
  }
  detail::SliceTable table;
  detail::mass_to_table(mass, table);
  detail::MethodWorkspace ws;
  const detail::Outcome outcome = detail::evaluate_method(table, method, ws);
  result.iterations = outcome.iterations;
  if (!outcome.ok()) {
    result.error = std::string(method_key(method)) + ": " + detail::describe_failure(outcome, table);
    return result;
  }
  result.factor_of_safety = outcome.factor_of_safety;
  result.lambda = outcome.lambda;
  if (with_forces) detail::slice_forces(table, method, outcome, ws, result.forces);
  return result;
}

}  // namespace slope
