// Ordinary (Fellenius), Bishop simplified and Janbu simplified. Formulation and sign conventions: docs/lem-methods.md.
//
// Per slice (frame mirrored so that the mass slides toward +x'): base angle a (positive when it drives), base
// length l, width b = l cos a, vertical load V = W + surcharge + ponded water, horizontal load H = kh W + water
// thrust (in the sliding direction), pore force U = u l, cohesion force c' l. With zero interslice shear, vertical
// equilibrium of a slice gives the effective normal force
//     N' = (V - U cos a - c' l sin a / F) / m_a,    m_a = cos a + sin a tan(phi') / F,
// and the available shear c' l + N' tan(phi') = A / m_a with A = c' l cos a + (V - U cos a) tan(phi')
// (= c' b + (V - u b) tan(phi')).
//   Bishop:  F = sum(d A / m_a) / M_drive            (moment about the circle centre, shear arm d)
//   Janbu:   F = sum(A / (m_a cos a)) / sum(V tan a + H)   (horizontal force equilibrium)
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "method_kernels.hpp"

namespace slope::detail {

namespace {

struct RatioEquation {
  const SliceTable* table;
  const double* numerator;  // w_i
  const double* friction;   // p_i = sin a tan phi'
  double denominator;
};

// phi(F) = F - sum(w_i / m_i(F)) / denominator and its derivative.
inline double ratio_residual(const RatioEquation& eq, double F, double* derivative) {
  const int n = eq.table->count;
  const double* cs = eq.table->cos_a.data();
  const double* w = eq.numerator;
  const double* p = eq.friction;
  const double inv_f = 1.0 / F;
  double sum = 0.0, sum_d = 0.0;
  for (int i = 0; i < n; ++i) {
    const double inv_m = 1.0 / (cs[i] + p[i] * inv_f);
    const double term = w[i] * inv_m;
    sum += term;
    sum_d += term * p[i] * inv_m;
  }
  const double inv_den = 1.0 / eq.denominator;
  if (derivative != nullptr) *derivative = 1.0 - sum_d * inv_f * inv_f * inv_den;
  return F - sum * inv_den;
}

double ratio_residual_gsl(double F, void* params) {
  return ratio_residual(*static_cast<const RatioEquation*>(params), F, nullptr);
}

// The least admissible F of the ratio equation: every slice with a negative base angle keeps m_a >= 0.2 (Whitman &
// Bailey 1967). False (out.failure set) when a slice cannot, or when the balancing F lies below that bound.
bool admissible_lower_bound(const RatioEquation& eq, Outcome& out, double& f_min) {
  const SliceTable& t = *eq.table;
  const int n = t.count;
  f_min = 0.0;
  int binding = -1;
  for (int i = 0; i < n; ++i) {
    if (t.sin_a[i] >= 0.0) continue;
    if (t.cos_a[i] <= minimum_m_alpha) {  // m_a <= cos a < 0.2 for any F
      out.failure = Failure::m_alpha;
      out.slice = i;
      out.value = t.cos_a[i];
      return false;
    }
    if (eq.friction[i] < 0.0) {
      const double f = -eq.friction[i] / (t.cos_a[i] - minimum_m_alpha);
      if (f > f_min) {
        f_min = f;
        binding = i;
      }
    }
  }
  if (f_min > 0.0) {
    const double v = ratio_residual(eq, f_min, nullptr);
    if (v > 0.0) {  // the balancing F lies below f_min, where m_a < 0.2 on slice `binding`
      out.failure = Failure::m_alpha;
      out.slice = binding;
      out.value = std::numeric_limits<double>::quiet_NaN();
      return false;
    }
  }
  return true;
}

// Safeguarded Newton on [lo, hi] from `guess` (at most 40 steps); narrows the bracket as it goes. True when it
// converged (out.factor_of_safety set).
bool ratio_newton(const RatioEquation& eq, double guess, double& lo, double& hi, Outcome& out) {
  double F = (std::isfinite(guess) && guess > lo) ? guess : (lo > 0.0 ? 1.5 * lo : 1.0);
  for (int it = 1; it <= 40; ++it) {
    double d = 0.0;
    const double v = ratio_residual(eq, F, &d);
    if (!std::isfinite(v)) break;
    if (std::fabs(v) <= 1e-11 * std::max(1.0, F)) {
      out.factor_of_safety = F;
      out.iterations = it;
      return true;
    }
    if (v < 0.0) lo = F;
    else hi = F;
    double next = d > 0.0 ? F - v / d : std::numeric_limits<double>::quiet_NaN();
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : std::max(2.0 * F, lo + 1.0);
    F = next;
  }
  return false;
}

// The fallback: bracket the root from [lo, hi) and refine it with GSL's Brent solver.
void ratio_brent(const RatioEquation& eq, double lo, double hi, Outcome& out) {
  if (!std::isfinite(hi)) {
    for (double trial = std::max(2.0 * lo, 1.0); trial < 1e6; trial *= 2.0) {
      if (ratio_residual(eq, trial, nullptr) > 0.0) {
        hi = trial;
        break;
      }
      lo = trial;
    }
  }
  if (!std::isfinite(hi) || !(ratio_residual(eq, std::max(lo, 1e-12), nullptr) < 0.0)) {
    out.failure = Failure::not_converged;
    return;
  }
  gsl_function function{&ratio_residual_gsl, const_cast<RatioEquation*>(&eq)};
  gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(solver, &function, std::max(lo, 1e-12), hi);
  int status = GSL_CONTINUE;
  int it = 0;
  while (status == GSL_CONTINUE && it < 200) {
    ++it;
    if (gsl_root_fsolver_iterate(solver) != GSL_SUCCESS) break;
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver), gsl_root_fsolver_x_upper(solver), 0.0, 1e-12);
  }
  const double root = gsl_root_fsolver_root(solver);
  gsl_root_fsolver_free(solver);
  if (status != GSL_SUCCESS) {
    out.failure = Failure::not_converged;
    out.iterations = it;
    return;
  }
  out.factor_of_safety = root;
  out.iterations = 40 + it;
}

// Solves F = sum(w_i / m_i(F)) / denominator, m_i = cos a_i + p_i / F, on the admissible range: every slice with a
// negative base angle keeps m_a >= 0.2 (Whitman & Bailey 1967). Safeguarded Newton from `guess` (converges in 3-5
// steps from the Ordinary value); GSL Brent on the bracket if Newton has not converged.
Outcome solve_ratio_equation(const RatioEquation& eq, double guess) {
  Outcome out;
  double f_min = 0.0;
  if (!admissible_lower_bound(eq, out, f_min)) return out;
  double lo = f_min;
  double hi = std::numeric_limits<double>::infinity();
  if (ratio_newton(eq, guess, lo, hi, out)) return out;
  ratio_brent(eq, lo, hi, out);
  return out;
}

// Acceptability, as for Spencer / Morgenstern-Price: no slice base may need a negative shear strength
// c' l + N' tan(phi') < 0 (an effective normal tension beyond the Mohr-Coulomb apex). Without this check the search
// drives the Ordinary method under deep water (N' = V cos a - u l < 0) and Bishop on vertical faces (tension in the
// steep upper slices) to surfaces whose "resistance" is mostly negative, down to F = 1e-14. `normal(i)` is the
// effective normal force of slice i at the solution. Returns false (and fills `out`) when a slice fails.
template <class Normal>
bool strengths_non_negative(const SliceTable& t, Normal&& normal, Outcome& out) {
  for (int i = 0; i < t.count; ++i) {
    const double effective_normal = normal(i);
    const double available = t.cohesion_force[i] + effective_normal * t.tan_phi[i];
    const double scale = t.cohesion_force[i] + std::fabs(effective_normal) * t.tan_phi[i];
    if (scale > 0.0 && available < -1e-9 * scale) {
      out.failure = Failure::negative_strength;
      out.slice = i;
      out.value = std::numeric_limits<double>::quiet_NaN();
      return false;
    }
  }
  return true;
}

// Effective normal force of slice i with zero interslice shear (Bishop, Janbu) at F.
inline double simplified_normal(const SliceTable& t, int i, double F) {
  const double m = t.cos_a[i] + t.sin_a[i] * t.tan_phi[i] / F;
  return (t.vertical[i] - t.pore_force[i] * t.cos_a[i] - t.cohesion_force[i] * t.sin_a[i] / F) / m;
}

// Bishop and Janbu: solve F = sum(w / (cos a + sin a tan phi / F)) / driving from `start` (the Ordinary value or a
// caller's guess; 1 when it is not above 0.05), then require a positive F and no slice base with a negative shear
// strength.
Outcome solve_simplified(const SliceTable& t, const RatioEquation& eq, double start) {
  Outcome out = solve_ratio_equation(eq, start > 0.05 ? start : 1.0);
  if (out.ok() && !(out.factor_of_safety > 0.0 && std::isfinite(out.factor_of_safety)))
    out.failure = Failure::not_positive;
  if (out.ok()) {
    const double F = out.factor_of_safety;
    strengths_non_negative(t, [&](int i) { return simplified_normal(t, i, F); }, out);
  }
  return out;
}

// Bishop on a polyline: moments about the moment point, where the base normal forces have arms g_i:
//     h(F) = F (M + sum g (N' + U)) - sum d (c' l + N' tan phi') = 0,   N' as in Bishop's vertical equilibrium.
// The admissible range keeps m_a >= 0.2 as for circles; the first sign change of h on a geometric scan of it is
// refined by GSL Brent.
double bishop_polyline_residual(double F, void* params) {
  const SliceTable& t = *static_cast<const SliceTable*>(params);
  double drive = t.total_drive_moment, resist = 0.0;
  for (int i = 0; i < t.count; ++i) {
    const double effective_normal = simplified_normal(t, i, F);
    drive += t.normal_arm[i] * (effective_normal + t.pore_force[i]);
    resist += t.shear_arm[i] * (t.cohesion_force[i] + effective_normal * t.tan_phi[i]);
  }
  return F * drive - resist;
}

// sum d (c' l + N' tan phi') of bishop_polyline_residual
double bishop_polyline_resistance(const SliceTable& t, double F) {
  double resist = 0.0;
  for (int i = 0; i < t.count; ++i)
    resist += t.shear_arm[i] * (t.cohesion_force[i] + simplified_normal(t, i, F) * t.tan_phi[i]);
  return resist;
}

Outcome bishop_polyline(const SliceTable& t) {
  Outcome out;
  double f_min = 0.0;
  for (int i = 0; i < t.count; ++i) {
    if (t.sin_a[i] >= 0.0) continue;
    if (t.cos_a[i] <= minimum_m_alpha) {
      out.failure = Failure::m_alpha;
      out.slice = i;
      out.value = t.cos_a[i];
      return out;
    }
    if (t.sin_a[i] * t.tan_phi[i] < 0.0) f_min = std::max(f_min, -t.sin_a[i] * t.tan_phi[i] / (t.cos_a[i] - minimum_m_alpha));
  }
  void* params = const_cast<SliceTable*>(&t);
  double lo = std::max(f_min * (1.0 + 1e-9), 1e-3);
  double h_lo = bishop_polyline_residual(lo, params);
  double hi = lo;
  bool bracketed = false;
  for (int k = 0; k < 240 && !bracketed; ++k) {  // up to 1e3 times lo... and beyond, in steps of 5 %
    hi = lo * 1.05;
    const double h_hi = bishop_polyline_residual(hi, params);
    if ((h_lo <= 0.0) != (h_hi <= 0.0)) bracketed = true;
    else {
      lo = hi;
      h_lo = h_hi;
    }
  }
  if (!bracketed) {
    out.failure = f_min > 0.0 ? Failure::m_alpha : Failure::not_converged;
    out.value = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  gsl_function function{&bishop_polyline_residual, params};
  gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(solver, &function, lo, hi);
  int status = GSL_CONTINUE, it = 0;
  while (status == GSL_CONTINUE && it < 200) {
    ++it;
    if (gsl_root_fsolver_iterate(solver) != GSL_SUCCESS) break;
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver), gsl_root_fsolver_x_upper(solver), 0.0, 1e-13);
  }
  out.factor_of_safety = gsl_root_fsolver_root(solver);
  out.iterations = it;
  gsl_root_fsolver_free(solver);
  if (status != GSL_SUCCESS) {
    out.failure = Failure::not_converged;
    return out;
  }
  const double F = out.factor_of_safety;
  // F D(F) = R(F) with D <= 0 is a root with a non-positive driving moment (R < 0): not a factor of safety
  if (!(bishop_polyline_residual(F, params) + bishop_polyline_resistance(t, F) > 1e-9 * F * t.drive_moment_scale)) {
    out.failure = Failure::no_driving_moment;
    return out;
  }
  strengths_non_negative(t, [&](int i) { return simplified_normal(t, i, F); }, out);
  return out;
}

// Ordinary on a polyline: N' = V cos a - H sin a - U as for circles, moments about the moment point with the base
// normal forces' arms g: F = sum d (c' l + N' tan phi') / (M + sum g (N' + U)).
Outcome ordinary_polyline(const SliceTable& t) {
  Outcome out;
  auto normal = [&](int i) { return t.vertical[i] * t.cos_a[i] - t.horizontal[i] * t.sin_a[i] - t.pore_force[i]; };
  double resisting = 0.0, drive = t.total_drive_moment;
  for (int i = 0; i < t.count; ++i) {
    const double effective_normal = normal(i);
    resisting += t.shear_arm[i] * (t.cohesion_force[i] + effective_normal * t.tan_phi[i]);
    drive += t.normal_arm[i] * (effective_normal + t.pore_force[i]);
  }
  if (!(drive > 1e-9 * t.drive_moment_scale)) {
    out.failure = Failure::no_driving_moment;
    return out;
  }
  out.factor_of_safety = resisting / drive;
  out.iterations = 1;
  if (!(out.factor_of_safety > 0.0) || !std::isfinite(out.factor_of_safety)) {
    out.failure = Failure::not_positive;
    return out;
  }
  strengths_non_negative(t, normal, out);
  return out;
}

}  // namespace

Outcome ordinary_method(const SliceTable& t) {
  Outcome out;
  const double moment = t.total_drive_moment;
  if (!t.circular) return ordinary_polyline(t);  // (its driving moment includes the base normal forces')
  if (!t.driven()) {
    out.failure = Failure::no_driving_moment;
    return out;
  }
  double resisting = 0.0;
  for (int i = 0; i < t.count; ++i) {
    // Fellenius: interslice forces ignored; N' = V cos a - H sin a - u l
    const double effective_normal = t.vertical[i] * t.cos_a[i] - t.horizontal[i] * t.sin_a[i] - t.pore_force[i];
    resisting += t.shear_arm[i] * (t.cohesion_force[i] + effective_normal * t.tan_phi[i]);
  }
  out.factor_of_safety = resisting / moment;
  out.iterations = 1;
  if (!(out.factor_of_safety > 0.0) || !std::isfinite(out.factor_of_safety)) {
    out.failure = Failure::not_positive;
    return out;
  }
  strengths_non_negative(
      t, [&](int i) { return t.vertical[i] * t.cos_a[i] - t.horizontal[i] * t.sin_a[i] - t.pore_force[i]; }, out);
  return out;
}

Outcome bishop_method(const SliceTable& t, MethodWorkspace& ws, double guess) {
  Outcome out;
  const double moment = t.total_drive_moment;
  if (!t.circular) return bishop_polyline(t);  // (its driving moment includes the base normal forces')
  if (!t.driven()) {
    out.failure = Failure::no_driving_moment;
    return out;
  }
  const int n = t.count;
  ws.reserve_ratio_terms(n);
  double* w = ws.numerator.data();
  double* p = ws.friction_term.data();
  double ordinary = 0.0;
  for (int i = 0; i < n; ++i) {
    const double c = t.cos_a[i];
    const double s = t.sin_a[i];
    const double tp = t.tan_phi[i];
    const double d = t.shear_arm[i];
    w[i] = d * (t.cohesion_force[i] * c + (t.vertical[i] - t.pore_force[i] * c) * tp);
    p[i] = s * tp;
    ordinary += d * (t.cohesion_force[i] + (t.vertical[i] * c - t.horizontal[i] * s - t.pore_force[i]) * tp);
  }
  return solve_simplified(t, RatioEquation{&t, w, p, moment}, guess > 0.0 ? guess : ordinary / moment);
}

Outcome janbu_method(const SliceTable& t, MethodWorkspace& ws, double guess) {
  Outcome out;
  const int n = t.count;
  ws.reserve_ratio_terms(n);
  double* w = ws.numerator.data();
  double* p = ws.friction_term.data();
  double driving = 0.0, driving_scale = 0.0, ordinary = 0.0;
  for (int i = 0; i < n; ++i) {
    const double c = t.cos_a[i];
    const double s = t.sin_a[i];
    const double tp = t.tan_phi[i];
    driving += t.vertical[i] * s / c + t.horizontal[i];
    driving_scale += std::fabs(t.vertical[i] * s / c) + std::fabs(t.horizontal[i]);
    w[i] = (t.cohesion_force[i] * c + (t.vertical[i] - t.pore_force[i] * c) * tp) / c;
    p[i] = s * tp;
    ordinary += (t.cohesion_force[i] + (t.vertical[i] * c - t.horizontal[i] * s - t.pore_force[i]) * tp) / c;
  }
  if (!(driving > 1e-9 * driving_scale)) {
    out.failure = Failure::no_driving_force;
    return out;
  }
  return solve_simplified(t, RatioEquation{&t, w, p, driving}, guess > 0.0 ? guess : ordinary / driving);
}

double janbu_correction_factor(const SliceTable& t) {
  // Janbu (1973) f0 = 1 + b1 (d/L - 1.4 (d/L)^2); L = chord entry-exit, d = largest depth of the slip surface
  // below that chord (perpendicular to it); for a circle d = R - (distance from the centre to the chord).
  const double lx = t.exit.x - t.entry.x;
  const double ly = t.exit.y - t.entry.y;
  const double chord = std::sqrt(lx * lx + ly * ly);
  if (!(chord > 0.0)) return 1.0;
  const double centre_to_chord =
      std::fabs((t.circle.xc - t.entry.x) * ly - (t.circle.yc - t.entry.y) * lx) / chord;
  const double depth = t.circular ? std::max(0.0, t.circle.radius - centre_to_chord) : t.chord_depth;
  bool has_cohesion = false, has_friction = false;
  for (int i = 0; i < t.count; ++i) {
    has_cohesion = has_cohesion || t.cohesion[i] > 0.0;
    has_friction = has_friction || t.tan_phi[i] > 0.0;
  }
  double b1 = 0.0;
  if (has_cohesion && has_friction) b1 = 0.50;
  else if (has_cohesion) b1 = 0.69;
  else if (has_friction) b1 = 0.31;
  const double ratio = depth / chord;
  return 1.0 + b1 * (ratio - 1.4 * ratio * ratio);
}

}  // namespace slope::detail
