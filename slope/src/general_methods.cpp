// Spencer and Morgenstern-Price: force and moment equilibrium with interslice shear X = lambda f(x) E.
// Formulation and sign conventions: docs/lem-methods.md.
//
// Slices are swept from the entry (upper end) to the exit in the mirrored frame (sliding toward +x'). At each
// interface E is the (compressive) normal force and X the shear force, X acting upward on the upslope slice and
// downward on the downslope slice; X = lambda f E, so lambda > 0 in the usual case where the downslope part holds
// the upslope part up. Slice i receives E_L (+x') and X_L (downward) on its upslope face and -E_R, X_R (upward)
// on its downslope face. Vertical equilibrium
//     (N' + U) cos a + S sin a = V + X_L - X_R,       S = (c' l + N' tan phi') / F,
// gives N' = (A0 - X_R) / m_a with A0 = V + X_L - U cos a - c' l sin a / F; horizontal equilibrium
//     E_R = E_L + H + (N' + U) sin a - S cos a
// with X_R = lambda f_R E_R is linear in E_R and solved slice by slice (the standard recursion, cf. Zhu, Lee, Qian
// & Chen 2005). Two residuals in (F, lambda):
//     r1 = E at the exit / sum(V)                          (horizontal force equilibrium of the whole mass)
//     r2 = sum(d S) / M_drive - 1                          (moment equilibrium about the circle centre)
// (about the moment point of a polyline surface, where the base normal forces N have arms g and
// M_drive = sum(moments of V and H) + sum(g N): Fredlund & Krahn 1977)
// are solved with GSL's hybrid (Powell dogleg) multiroot solver in (ln F, lambda), which keeps F positive.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>

#include <cmath>
#include <mutex>

#include "method_kernels.hpp"
#include "sphslope/units.hpp"

namespace slope::detail {

namespace {

struct Sweep {
  double end_force = 0.0;         // E after the last slice
  double resisting_moment = 0.0;  // sum d (c' l + N' tan phi')
  double normal_moment = 0.0;     // polylines: sum of the base normal forces' moments about the moment point
  bool finite = true;
  int weakest_slice = -1;         // slice with the least available shear strength (relative to its scale)
  double weakest_strength = 0.0;  // (c' l + N' tan phi') / (c' l + |N'| tan phi') there: < 0 is impossible
};

// One pass over the slices. f[k]: interslice function at the downslope boundary of the k-th slice from the entry.
// When `forces` is given, the slice forces are written there (index = slice index, left to right).
Sweep sweep(const SliceTable& t, const double* f, double F, double lambda, SliceForces* forces) {
  Sweep out;
  const int n = t.count;
  const double inv_f = 1.0 / F;
  double e_left = 0.0, x_left = 0.0, moment = 0.0;
  for (int k = 0; k < n; ++k) {
    const int i = t.direction > 0 ? k : n - 1 - k;
    const double c = t.cos_a[i];
    const double s = t.sin_a[i];
    const double tp = t.tan_phi[i];
    const double cl = t.cohesion_force[i];
    const double U = t.pore_force[i];
    const double inv_m = 1.0 / (c + s * tp * inv_f);
    const double a0 = t.vertical[i] + x_left - U * c - cl * s * inv_f;
    const double kk = (s - tp * c * inv_f) * inv_m;
    const double lf = lambda * f[k];
    const double numerator = e_left + t.horizontal[i] + U * s - cl * c * inv_f + a0 * kk;
    const double e_right = numerator / (1.0 + lf * kk);
    const double x_right = lf * e_right;
    const double effective_normal = (a0 - x_right) * inv_m;
    const double available = cl + effective_normal * tp;
    moment += t.shear_arm[i] * available;
    if (!t.circular) out.normal_moment += t.normal_arm[i] * (effective_normal + U);
    if (forces != nullptr) {
      const double scale = cl + std::fabs(effective_normal) * tp;
      const double relative = scale > 0.0 ? available / scale : 0.0;
      if (out.weakest_slice < 0 || relative < out.weakest_strength) {
        out.weakest_slice = i;
        out.weakest_strength = relative;
      }
    }
    if (forces != nullptr) {
      SliceForces& sf = forces[i];
      sf.normal = effective_normal + U;
      sf.shear = available * inv_f;
      sf.pore_force = U;
      // reported on the right-hand side of the slice (increasing x), as pushed by the left-hand slice
      if (t.direction > 0) {
        sf.interslice_normal_right = e_right;
        sf.interslice_shear_right = x_right;
      } else {
        // for a mass sliding toward -x the sweep runs right to left: the right side of slice i carries the
        // upslope force E_L, X_L of this sweep step
        sf.interslice_normal_right = e_left;
        sf.interslice_shear_right = x_left;
      }
    }
    e_left = e_right;
    x_left = x_right;
  }
  out.end_force = e_left;
  out.resisting_moment = moment;
  out.finite = std::isfinite(e_left) && std::isfinite(moment);
  return out;
}

struct Problem {
  const SliceTable* table;
  const double* f;
  double force_scale;
};

// The two residuals at x = (ln F, lambda); false where the sweep is not finite.
bool residual_at(const Problem& p, const double x[2], double r[2]) {
  const double F = std::exp(x[0]);
  const double lambda = x[1];
  if (!std::isfinite(F) || !std::isfinite(lambda)) return false;
  const Sweep s = sweep(*p.table, p.f, F, lambda, nullptr);
  if (!s.finite) return false;
  r[0] = s.end_force / p.force_scale;
  if (p.table->circular) {
    r[1] = s.resisting_moment / (F * p.table->total_drive_moment) - 1.0;
  } else {
    // A polyline's base normal forces have a moment too, which depends on the solution: the moment imbalance
    // (resisting - driving) relative to the loads' moments, with no division by a driving moment that may vanish.
    const double drive = p.table->total_drive_moment + s.normal_moment;
    r[1] = (s.resisting_moment / F - drive) / p.table->drive_moment_scale;
  }
  return true;
}

int residual(const gsl_vector* x, void* params, gsl_vector* r) {
  const double at[2] = {gsl_vector_get(x, 0), gsl_vector_get(x, 1)};
  double value[2];
  if (!residual_at(*static_cast<const Problem*>(params), at, value)) return GSL_EBADFUNC;
  gsl_vector_set(r, 0, value[0]);
  gsl_vector_set(r, 1, value[1]);
  return GSL_SUCCESS;
}

constexpr double residual_tolerance = 1e-10;  // on |r1| + |r2| (gsl_multiroot_test_residual)

// Newton's method from the last envelope pass's root (MethodWorkspace::RootContinuation), which the new tangents
// have moved only a little: one sweep when it is still a root, usually one or two steps otherwise, with the Jacobian
// (forward differences, as GSL's hybrid solver takes them) found at the first such pass and kept for the later ones.
// x: in, the last root; out, the new one. False when it does not converge in a few steps.
bool continue_root(const Problem& p, MethodWorkspace::RootContinuation& c, double x[2], int& iterations) {
  double r[2];
  if (!residual_at(p, x, r)) return false;
  for (int step = 0; step < 6; ++step) {
    if (std::fabs(r[0]) + std::fabs(r[1]) < residual_tolerance) return true;
    if (!c.has_jacobian) {
      for (int j = 0; j < 2; ++j) {
        double shifted[2] = {x[0], x[1]}, rj[2];
        const double h = GSL_SQRT_DBL_EPSILON * (x[j] != 0.0 ? std::fabs(x[j]) : 1.0);
        shifted[j] += h;
        if (!residual_at(p, shifted, rj)) return false;
        c.jacobian[j] = (rj[0] - r[0]) / h;      // d r1 / d x_j
        c.jacobian[2 + j] = (rj[1] - r[1]) / h;  // d r2 / d x_j
      }
      c.has_jacobian = true;
    }
    const double* J = c.jacobian;
    const double det = J[0] * J[3] - J[1] * J[2];
    if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) return false;
    x[0] -= (J[3] * r[0] - J[1] * r[1]) / det;
    x[1] -= (J[0] * r[1] - J[2] * r[0]) / det;
    ++iterations;
    if (!residual_at(p, x, r)) return false;
  }
  return std::fabs(r[0]) + std::fabs(r[1]) < residual_tolerance;
}

void fill_interface_function(const SliceTable& t, bool half_sine, std::vector<double>& f) {
  const int n = t.count;
  if (f.size() < static_cast<std::size_t>(n)) f.resize(static_cast<std::size_t>(n) * 2);
  const double x_entry = t.entry.x;
  const double span = t.exit.x - t.entry.x;
  for (int k = 0; k < n; ++k) {
    if (!half_sine) {
      f[k] = 1.0;
      continue;
    }
    const int i = t.direction > 0 ? k : n - 1 - k;
    const double x_boundary = t.direction > 0 ? t.x_right[i] : t.x_left[i];  // downslope boundary
    const double fraction = (x_boundary - x_entry) / span;
    f[k] = std::sin(sphslope::pi * fraction);
  }
  if (half_sine) f[n - 1] = 0.0;  // the exit
}

}  // namespace

MethodWorkspace::MethodWorkspace() {
  static std::once_flag once;
  // GSL's default error handler aborts the program; the library reports failures through return codes instead.
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

MethodWorkspace::~MethodWorkspace() {
  if (solver != nullptr) gsl_multiroot_fsolver_free(solver);
  if (start != nullptr) gsl_vector_free(start);
}

namespace {

// The checks of a (F, lambda) root; false (and `out` filled) when it is not acceptable.
bool acceptable_solution(const SliceTable& t, MethodWorkspace& ws, double F, double lambda, Outcome& out) {
  // Whitman & Bailey (1967) check at the solution, and a sane recursion (1 + lambda f k / m_a must stay positive:
  // otherwise the interslice forces change sign through a pole).
  const int n = t.count;
  for (int k = 0; k < n; ++k) {
    const int i = t.direction > 0 ? k : n - 1 - k;
    const double c = t.cos_a[i];
    const double s = t.sin_a[i];
    const double m = c + s * t.tan_phi[i] / F;
    if (s < 0.0 && m < minimum_m_alpha) {
      out.failure = Failure::m_alpha;
      out.slice = i;
      out.value = m;
      return false;
    }
    const double kk = (s - t.tan_phi[i] * c / F) / m;
    if (1.0 + lambda * ws.interface_function[k] * kk <= 0.0) {
      out.failure = Failure::singular_recursion;
      out.slice = i;
      return false;
    }
  }
  // Acceptability: no slice base may need a negative shear strength (an effective normal tension beyond the
  // Mohr-Coulomb apex, N' < -c' l / tan phi'). Roots on steep slopes with cohesion can balance the equations
  // that way, with interslice tensions many times the slice weights; they are not physical.
  ws.forces.resize(static_cast<std::size_t>(n));
  const Sweep check = sweep(t, ws.interface_function.data(), F, lambda, ws.forces.data());
  if (check.weakest_slice >= 0 && check.weakest_strength < -1e-9) {
    out.failure = Failure::negative_strength;
    out.slice = check.weakest_slice;
    out.value = lambda;
    return false;
  }
  return true;
}

}  // namespace

Outcome general_limit_equilibrium(const SliceTable& t, MethodWorkspace& ws, bool half_sine, double guess) {
  Outcome out;
  // (On a polyline the loads' moment alone says nothing: the normal forces' moments depend on the moment point,
  // while the solution does not.)
  if (t.circular && !t.driven()) {
    out.failure = Failure::no_driving_moment;
    return out;
  }
  if (!(guess > 0.0) || !std::isfinite(guess)) {
    const Outcome bishop = bishop_method(t, ws);
    guess = bishop.ok() ? bishop.factor_of_safety : 1.0;
  }
  fill_interface_function(t, half_sine, ws.interface_function);
  double force_scale = 0.0;
  for (int i = 0; i < t.count; ++i) force_scale += std::fabs(t.vertical[i]) + std::fabs(t.horizontal[i]);
  Problem problem{&t, ws.interface_function.data(), force_scale > 0.0 ? force_scale : 1.0};
  double root[2] = {std::log(guess), 0.0};
  int it = 0;
  MethodWorkspace::RootContinuation& continuation = ws.continuation;
  bool solved = false;
  if (continuation.active) {
    root[0] = std::log(continuation.factor_of_safety);
    root[1] = continuation.lambda;
    solved = continue_root(problem, continuation, root, it);
    if (!solved) {  // GSL's solver from the last root
      root[0] = std::log(continuation.factor_of_safety);
      root[1] = continuation.lambda;
    }
  }
  if (!solved) {
    if (ws.solver == nullptr) {
      ws.solver = gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, 2);
      ws.start = gsl_vector_alloc(2);
    }
    gsl_multiroot_function function{&residual, 2, &problem};
    gsl_vector_set(ws.start, 0, root[0]);
    gsl_vector_set(ws.start, 1, root[1]);
    if (gsl_multiroot_fsolver_set(ws.solver, &function, ws.start) != GSL_SUCCESS) {
      out.failure = Failure::singular_recursion;
      return out;
    }
    int status = GSL_CONTINUE;
    while (status == GSL_CONTINUE && it < 100) {
      ++it;
      const int step = gsl_multiroot_fsolver_iterate(ws.solver);
      if (step == GSL_EBADFUNC) {
        out.failure = Failure::singular_recursion;
        out.iterations = it;
        return out;
      }
      status = gsl_multiroot_test_residual(ws.solver->f, residual_tolerance);
      if (status == GSL_CONTINUE && step != GSL_SUCCESS) break;  // no progress
    }
    if (status != GSL_SUCCESS) {
      out.failure = Failure::not_converged;
      out.iterations = it;
      return out;
    }
    root[0] = gsl_vector_get(ws.solver->x, 0);
    root[1] = gsl_vector_get(ws.solver->x, 1);
  }
  out.iterations = it;
  const double F = std::exp(root[0]);
  const double lambda = root[1];
  if (!(F > 0.0) || !std::isfinite(F)) {
    out.failure = Failure::not_positive;
    return out;
  }
  if (!(std::fabs(lambda) <= maximum_lambda)) {  // a root beyond the poles of the recursion: not physical
    out.failure = Failure::lambda_out_of_range;
    out.value = lambda;
    return out;
  }
  if (!acceptable_solution(t, ws, F, lambda, out)) return out;
  out.factor_of_safety = F;
  out.lambda = lambda;
  return out;
}

void general_forces(const SliceTable& t, MethodWorkspace& ws, bool half_sine, double F, double lambda,
                    std::vector<SliceForces>& forces) {
  fill_interface_function(t, half_sine, ws.interface_function);
  forces.assign(static_cast<std::size_t>(t.count), SliceForces{});
  sweep(t, ws.interface_function.data(), F, lambda, forces.data());
}

}  // namespace slope::detail
