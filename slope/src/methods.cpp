// Method keys and the public factor_of_safety(), through the method table (method_table.hpp).
#include "slope/methods.hpp"

#include <array>
#include <cmath>
#include <sstream>

#include "method_table.hpp"
#include "sphslope/units.hpp"

namespace slope {

std::string_view method_key(Method method) { return detail::method_row(method).key; }

std::optional<Method> method_from_key(std::string_view key) {
  for (const detail::MethodRow& row : detail::method_table())
    if (row.key == key) return row.method;
  return std::nullopt;
}

const std::vector<Method>& all_methods() {
  static const std::vector<Method> methods = [] {
    std::vector<Method> all;
    for (const detail::MethodRow& row : detail::method_table()) all.push_back(row.method);
    return all;
  }();
  return methods;
}

bool has_interslice_lambda(Method method) { return detail::method_row(method).has_lambda; }

namespace detail {

std::string describe_failure(const Outcome& outcome, const SliceTable& table) {
  std::ostringstream out;
  out.precision(3);
  auto slice_text = [&](int i) {
    if (i < 0 || i >= table.count) return;
    out << " at slice " << i + 1 << " of " << table.count << " (x = " << table.base_x[i]
        << " m, base angle " << sphslope::degrees(std::atan2(table.sin_a[i], table.cos_a[i])) << " deg)";
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
