// A method's solution on slice bases with non-linear strength envelopes (method_table.hpp, solve_row): the methods
// of slices take a cohesion and a friction per base, so each base gets the envelope's tangent at its effective
// normal stress (the instantaneous c_i and phi_i, as Slide2 and SLOPE/W do), and the stresses of the solution start
// the next solve. At the fixed point every base carries tau(sigma_n') of its envelope at its own sigma_n'.
#include <algorithm>
#include <cmath>
#include <limits>

#include "method_table.hpp"
#include "slope/strength.hpp"

namespace slope::detail {

namespace {

constexpr int maximum_envelope_iterations = 200;

bool has_envelope(const SliceTable& t, int i) {
  const int e = t.envelope[i];
  return e >= 0 && static_cast<std::size_t>(e) < t.envelopes->size();
}

// The tangent of each base's envelope at its effective normal stress sigma[i], as the base's c' and tan(phi');
// hints[i]: where base i's last evaluation ended, for the next to start there.
void apply_envelopes(SliceTable& t, const std::vector<double>& sigma, std::vector<EnvelopeHint>& hints) {
  for (int i = 0; i < t.count; ++i) {
    if (!has_envelope(t, i)) continue;
    const auto k = static_cast<std::size_t>(i);
    const EnvelopePoint p = envelope_at((*t.envelopes)[static_cast<std::size_t>(t.envelope[i])], sigma[i], &hints[k]);
    t.tan_phi[i] = p.slope;
    t.cohesion[i] = p.shear - sigma[i] * p.slope;
    t.cohesion_force[i] = t.cohesion[i] * t.base_length[i];
  }
}

// The row's solution with the envelopes' tangents at the solution's own normal stresses.
Outcome solve_envelopes(const MethodRow& row, SliceTable& t, MethodWorkspace& ws, double guess) {
  if (!t.has_envelopes) return row.solve(t, ws, guess);
  std::vector<double>& sigma = ws.envelope_normal;
  // The start: the stresses of the last solution on this surface (another method's, or this one's at other loads),
  // else the Ordinary method's effective normal stresses, which do not depend on the strength. Either way the
  // iteration ends at this method's own stresses; a start nearer to them saves passes.
  if (ws.envelope_surface != t.surface_id || sigma.size() != static_cast<std::size_t>(t.count)) {
    sigma.assign(static_cast<std::size_t>(t.count), 0.0);
    ws.envelope_hint.assign(static_cast<std::size_t>(t.count), EnvelopeHint{});
    for (int i = 0; i < t.count; ++i)
      sigma[i] = (t.vertical[i] * t.cos_a[i] - t.horizontal[i] * t.sin_a[i] - t.pore_force[i]) / t.base_length[i];
  }
  ws.envelope_surface = 0;  // set again once this solution's stresses are in sigma
  struct ContinuationScope {  // no continuation before the first pass and after the last
    MethodWorkspace::RootContinuation& c;
    explicit ContinuationScope(MethodWorkspace::RootContinuation& r) : c(r) { c = {}; }
    ~ContinuationScope() { c = {}; }
  } scope(ws.continuation);
  Outcome out;
  int solver_iterations = 0;
  for (int pass = 0; pass < maximum_envelope_iterations; ++pass) {
    apply_envelopes(t, sigma, ws.envelope_hint);
    out = row.solve(t, ws, guess);
    solver_iterations += out.iterations;
    if (!out.ok()) return out;
    // Spencer's and Morgenstern-Price's solve has just swept the solution's forces into ws.forces (its check of
    // the solution); the other methods' are found here.
    if (!row.has_lambda) row.forces(t, ws, out, ws.envelope_forces);
    const std::vector<SliceForces>& forces = row.has_lambda ? ws.forces : ws.envelope_forces;
    double change = 0.0, scale = 0.0;
    for (int i = 0; i < t.count; ++i) {
      if (!has_envelope(t, i)) continue;
      const SliceForces& f = forces[static_cast<std::size_t>(i)];
      const double next = (f.normal - f.pore_force) / t.base_length[i];
      change = std::max(change, std::fabs(next - sigma[i]));
      scale = std::max(scale, std::fabs(next));
      sigma[i] = next;
    }
    // The solution's stresses are those its tangents were taken at, to 1e-6: each base's strength is then its
    // envelope's to second order in the difference (the factor of safety to about 1e-12).
    if (change <= 1e-6 * scale) {
      ws.envelope_surface = t.surface_id;
      out.iterations = solver_iterations;
      return out;
    }
    guess = out.factor_of_safety;
    if (row.has_lambda) {  // the next pass's root is near this one's
      ws.continuation.active = true;
      ws.continuation.factor_of_safety = out.factor_of_safety;
      ws.continuation.lambda = out.lambda;
    }
  }
  out.failure = Failure::not_converged;
  out.iterations = solver_iterations;
  return out;
}

// Passive reinforcement enters divided by the factor of safety: G(F) is the row's solution with the passive forces
// scaled by 1 / F, and the factor of safety is the fixed point F = G(F), found by the secant method on G(F) - F
// from two plain iterations (G changes slowly with F: the passive forces are a part of the resistance).
Outcome solve_passive(const MethodRow& row, SliceTable& t, MethodWorkspace& ws, double guess) {
  constexpr int maximum_passes = 60;
  int solver_iterations = 0;
  Outcome out;
  auto solution_at = [&](double F) {
    t.passive_scale = 1.0 / F;
    t.compute_loads();
    out = solve_envelopes(row, t, ws, F);
    solver_iterations += out.iterations;
    return out.ok() ? out.factor_of_safety - F : std::numeric_limits<double>::quiet_NaN();
  };
  double x0 = std::isfinite(guess) && guess > 0.0 ? guess : 1.0;
  double r0 = solution_at(x0);
  if (!out.ok()) return out;
  double x1 = out.factor_of_safety;
  for (int pass = 1; pass < maximum_passes; ++pass) {
    const double r1 = solution_at(x1);
    if (!out.ok()) return out;
    if (std::fabs(r1) <= 1e-11 * x1) {
      out.iterations = solver_iterations;
      return out;
    }
    double next = r1 != r0 ? x1 - r1 * (x1 - x0) / (r1 - r0) : out.factor_of_safety;
    if (!(next > 0.0) || !std::isfinite(next)) next = out.factor_of_safety;
    x0 = x1;
    r0 = r1;
    x1 = next;
  }
  out.failure = Failure::not_converged;
  out.iterations = solver_iterations;
  return out;
}

}  // namespace

Outcome solve_row(const MethodRow& row, SliceTable& t, MethodWorkspace& ws, double guess) {
  if (t.has_passive_supports) return solve_passive(row, t, ws, guess);
  return solve_envelopes(row, t, ws, guess);
}

}  // namespace slope::detail
