#pragma once
// Internal: the methods of slices as one table. Adding a method is one row here (slope/src/method_table.cpp), one
// enumerator in slope/methods.hpp and its solver; the dispatch (factor_of_safety, slice forces), the keys, the
// search's work sharing between methods and the report's lambda all iterate this table.
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "method_kernels.hpp"

namespace slope::detail {

struct MethodRow {
  Method method;
  std::string_view key;  // scene files and reports
  // Solves the method's equations on a slice table. guess: a starting factor of safety (<= 0: the method's own).
  Outcome (*solve)(const SliceTable& table, MethodWorkspace& ws, double guess);
  // Base normal and shear forces (and interslice forces where the method has them) at a solution.
  void (*forces)(const SliceTable& table, MethodWorkspace& ws, const Outcome& outcome,
                 std::vector<SliceForces>& forces);
  bool has_lambda;  // Spencer's tan(theta) / Morgenstern-Price's lambda is part of the solution
  // Whose equations give this method's solution: itself, or a method with the same equations (Morgenstern-Price
  // with f = 1 is Spencer) or one it corrects (Janbu corrected is Janbu times f0). The search solves each set of
  // equations once per trial circle.
  Method solution_of;
  // Turns the solution of `solution_of` into this method's (nullptr: the same).
  Outcome (*from_solution)(const SliceTable& table, Outcome solution);
  // Methods whose factor of safety on the same circle, when already known and finite, starts this one's
  // iteration (the first such, in this order).
  std::array<std::optional<Method>, 2> warm_start;
};

inline constexpr std::size_t method_count = 7;

// Rows in the order of slope::all_methods().
const std::array<MethodRow, method_count>& method_table();
const MethodRow& method_row(Method method);
// Position of the method in method_table().
std::size_t method_index(Method method);

// Solves the row's equations on the table (row.solve). When slice bases have non-linear strength envelopes
// (SliceTable::envelope), each solve sees the envelopes' tangents at the bases' effective normal stresses as their
// cohesion and friction (written into the table), starting from the Ordinary method's normal forces; the
// solution's normal forces give the next stresses, until none changes by more than 1e-6 of the largest
// (envelope_iteration.cpp).
Outcome solve_row(const MethodRow& row, SliceTable& table, MethodWorkspace& ws, double guess);

}  // namespace slope::detail
