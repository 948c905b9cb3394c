#pragma once
// Internal: the methods of slices on a SliceTable, without allocation per call once the workspace has grown.
#include <gsl/gsl_multiroots.h>

#include <string>
#include <vector>

#include "slice_table.hpp"
#include "slope/methods.hpp"
#include "slope/strength.hpp"

namespace slope::detail {

enum class Failure {
  none,
  no_driving_moment,   // the loads do not drive the mass toward the exit
  no_driving_force,    // force methods: the net driving force is not positive
  m_alpha,             // m_alpha < 0.2 on a slice with a negative base angle (Whitman & Bailey 1967)
  not_converged,       // the iteration did not converge
  not_positive,        // the solution is not a positive finite number
  singular_recursion,  // Spencer / Morgenstern-Price: the interslice force recursion broke down
  lambda_out_of_range, // Spencer / Morgenstern-Price: |lambda| > maximum_lambda (non-physical root)
  negative_strength,   // a slice base would need c' l + N' tan phi' < 0 (effective normal tension)
};

struct Outcome {
  double factor_of_safety = 0.0;
  double lambda = 0.0;
  int iterations = 0;
  Failure failure = Failure::none;
  int slice = -1;      // slice index (left to right) the failure refers to, if any
  double value = 0.0;  // the offending value (m_alpha, ...)
  bool ok() const { return failure == Failure::none; }
};

// Whitman & Bailey (1967): a surface is rejected when m_alpha = cos(a) + sin(a) tan(phi') / F < 0.2 on a slice.
inline constexpr double minimum_m_alpha = 0.2;
// Spencer / Morgenstern-Price roots with |lambda| above this (interslice resultant steeper than about 72 degrees
// where f = 1) lie beyond the poles of the interslice recursion and are rejected as non-physical.
inline constexpr double maximum_lambda = 3.0;

// Scratch buffers and the GSL multiroot solver, reused between trials (one per thread).
class MethodWorkspace {
 public:
  MethodWorkspace();
  ~MethodWorkspace();
  MethodWorkspace(const MethodWorkspace&) = delete;
  MethodWorkspace& operator=(const MethodWorkspace&) = delete;

  std::vector<double> numerator, friction_term, interface_function;
  // Spencer and Morgenstern-Price: the slice forces of the solution they last returned (acceptable_solution)
  std::vector<SliceForces> forces;
  // the iteration on non-linear strength envelopes: the bases' effective normal stresses and the forces they come from
  std::vector<double> envelope_normal;
  std::vector<EnvelopeHint> envelope_hint;
  std::uint64_t envelope_surface = 0;  // SliceTable::surface_id of the solution envelope_normal holds (0: none)
  std::vector<SliceForces> envelope_forces;
  // Spencer and Morgenstern-Price within the envelope iteration (envelope_iteration.cpp): the last pass's root on
  // this surface, where the next pass starts (active: between passes; the iteration clears it when it ends), and
  // the Jacobian of the residuals in (ln F, lambda) the first continued pass found.
  struct RootContinuation {
    bool active = false;
    double factor_of_safety = 0.0, lambda = 0.0;
    bool has_jacobian = false;
    double jacobian[4] = {};  // row-major d(r1, r2) / d(ln F, lambda)
  } continuation;

  // Grows the per-slice buffers of the ratio equations (Bishop, Janbu) to hold n slices (with room to spare).
  void reserve_ratio_terms(int n) {
    if (numerator.size() < static_cast<std::size_t>(n)) {
      numerator.resize(static_cast<std::size_t>(n) * 2);
      friction_term.resize(static_cast<std::size_t>(n) * 2);
    }
  }
  gsl_multiroot_fsolver* solver = nullptr;
  gsl_vector* start = nullptr;
};

Outcome ordinary_method(const SliceTable& table);
// guess (circles): where the iteration on F starts when positive (the envelope iteration's last pass), else at
// the Ordinary method's value.
Outcome bishop_method(const SliceTable& table, MethodWorkspace& ws, double guess = 0.0);
Outcome janbu_method(const SliceTable& table, MethodWorkspace& ws, double guess = 0.0);
// Janbu's empirical correction factor f0 = 1 + b1 (d/L - 1.4 (d/L)^2) for this mass.
double janbu_correction_factor(const SliceTable& table);
// Spencer (half_sine = false: f = 1) or Morgenstern-Price with the half-sine interslice function.
// guess: starting factor of safety (e.g. Bishop's); <= 0 to let the method pick one.
Outcome general_limit_equilibrium(const SliceTable& table, MethodWorkspace& ws, bool half_sine, double guess);

// Dispatch; guess as above (used by Spencer and Morgenstern-Price only). With non-linear strength envelopes the
// table's cohesion and friction are rewritten (method_table.hpp, solve_row).
Outcome evaluate_method(SliceTable& table, Method method, MethodWorkspace& ws, double guess = 0.0);

// Slice forces at a solution.
void slice_forces(const SliceTable& table, Method method, const Outcome& outcome, MethodWorkspace& ws,
                  std::vector<SliceForces>& forces);

std::string describe_failure(const Outcome& outcome, const SliceTable& table);

}  // namespace slope::detail
