#pragma once
// Internal: the pieces of the critical-circle search (slope/src/search*.cpp). The search itself, in order:
//   search_coarse.cpp  trial circles (entry-exit pairs or a centre grid), evaluated by every method
//   search_refine.cpp  Nelder-Mead refinement per method, cross-refinement, the critical surface per method
//   search.cpp         search_critical(): the steps above as a list of calls
// SearchEngine admits circles (slicing, limits, minimum depth) and evaluates methods on the current slices,
// counting evaluations, rejections and failures for the report.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "method_table.hpp"
#include "slice_table.hpp"
#include "slope/search.hpp"

namespace slope::detail {

inline constexpr double penalty_value = 1e6;  // objective of an inadmissible circle in the refinement
inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
inline constexpr std::size_t rejection_kinds = 8;
inline constexpr std::size_t failure_kinds = 9;

inline std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v;
  if (n <= 1) {
    v.push_back(0.5 * (a + b));
    return v;
  }
  for (int i = 0; i < n; ++i) v.push_back(a + (b - a) * i / (n - 1));
  return v;
}

inline Range ordered(Range r) {
  if (r.min > r.max) std::swap(r.min, r.max);
  return r;
}

struct Trial {
  Circle circle;
  Point entry, exit;
};

class SearchEngine {
 public:
  enum class Admit { ok, rejected, outside_limits, too_shallow };

  SearchEngine(const Section& section, const std::vector<Method>& methods, const SearchOptions& options)
      : methods_(methods), options_(options), slicer_(section) {
    const PreparedSection& ps = slicer_.prepared();
    relief_ = ps.ground_y_max - ps.ground_y_min;
    width_ = ps.x_max - ps.x_min;
    minimum_depth_ = options.minimum_depth >= 0.0 ? options.minimum_depth : 0.02 * relief_;
    failures_.assign(methods.size(), {});
    failure_text_.assign(methods.size(), {});
  }

  const PreparedSection& prepared() const { return slicer_.prepared(); }
  const SliceTable& table() const { return table_; }
  double relief() const { return relief_; }
  double width() const { return width_; }
  long evaluations() const { return evaluations_; }
  Method method(std::size_t method_index) const { return methods_[method_index]; }

  // Slices the circle and checks the user limits. With project_to_base, a circle below the rigid base is moved
  // up onto it (R = yc - bottom_y) first.
  Admit admit(Circle& circle, bool project_to_base, bool check_centre_box) {
    const SearchLimits& lim = options_.limits;
    if (check_centre_box && lim.centre_grid) {
      const Range rx = ordered(lim.centre_grid->x), ry = ordered(lim.centre_grid->y);
      if (circle.xc < rx.min || circle.xc > rx.max || circle.yc < ry.min || circle.yc > ry.max) {
        ++outside_limits_;
        return Admit::outside_limits;
      }
    }
    Rejection r = slicer_.slice(circle, options_.slicing.slices, table_);
    if (r == Rejection::below_base && project_to_base) {
      // shrink the circle onto the base: tangent to it, or through a point where the ground meets it (a toe on
      // a firm stratum)
      const double bottom = prepared().bottom_y;
      Circle tangent = circle;
      tangent.radius = circle.yc - bottom;
      r = slicer_.slice(tangent, options_.slicing.slices, table_);
      if (r == Rejection::none) circle = tangent;
      for (std::size_t k = 0; r != Rejection::none && k < prepared().base_contacts.size(); ++k) {
        Circle through = circle;
        through.radius = std::hypot(circle.xc - prepared().base_contacts[k], circle.yc - bottom);
        if (!(through.radius < circle.radius)) continue;
        r = slicer_.slice(through, options_.slicing.slices, table_);
        if (r == Rejection::none) circle = through;
      }
      if (r != Rejection::none) r = Rejection::below_base;
    }
    if (r != Rejection::none) {
      ++rejections_[static_cast<std::size_t>(r)];
      return Admit::rejected;
    }
    const double tol = 1e-9 * (1.0 + width_);
    if (lim.radius) {
      const Range rr = ordered(*lim.radius);
      if (circle.radius < rr.min - tol || circle.radius > rr.max + tol) {
        ++outside_limits_;
        return Admit::outside_limits;
      }
    }
    return admit_table();
  }

  // Slices a polyline surface (its own admissibility: ends on the ground, below it, above the base, concave) and
  // checks the entry/exit limits and the minimum depth, as for a circle.
  Admit admit(const SlipPolyline& surface) {
    if (!slicer_.slice_polyline(surface, options_.slicing.slices, table_).empty()) return Admit::rejected;
    return admit_table();
  }

 private:
  // The limits that apply to every kind of surface, on the current table: entry and exit ranges, minimum depth.
  Admit admit_table() {
    const SearchLimits& lim = options_.limits;
    const double tol = 1e-9 * (1.0 + width_);
    if (lim.entry_x) {
      const Range re = ordered(*lim.entry_x);
      if (table_.entry.x < re.min - tol || table_.entry.x > re.max + tol) {
        ++outside_limits_;
        return Admit::outside_limits;
      }
    }
    if (lim.exit_x) {
      const Range rx = ordered(*lim.exit_x);
      if (table_.exit.x < rx.min - tol || table_.exit.x > rx.max + tol) {
        ++outside_limits_;
        return Admit::outside_limits;
      }
    }
    if (table_.max_depth < minimum_depth_) {
      ++too_shallow_;
      return Admit::too_shallow;
    }
    return Admit::ok;
  }

 public:
  // One method on the current table; NaN on failure.
  double evaluate(std::size_t method_index, double guess = 0.0) {
    const Method method = methods_[method_index];
    ++evaluations_;
    const Outcome o = evaluate_method(table_, method, ws_, guess);
    if (o.ok()) return o.factor_of_safety;
    record_failure(method_index, o);
    return nan;
  }

  // Every method on the current table; fs[k] is NaN on failure. Each set of equations is solved once (the method
  // table's solution_of), and a method starts from another's factor of safety on the same circle (warm_start).
  void evaluate_all(double* fs) {
    solved_.fill(false);
    for (std::size_t k = 0; k < methods_.size(); ++k) {
      const MethodRow& row = method_row(methods_[k]);
      ++evaluations_;
      const Outcome& solution = solution_of(row.solution_of);
      const Outcome o = row.from_solution ? row.from_solution(table_, solution) : solution;
      if (o.ok()) {
        fs[k] = o.factor_of_safety;
      } else {
        record_failure(k, o);
        fs[k] = nan;
      }
    }
  }

  std::string rejection_summary() const {
    std::ostringstream out;
    std::vector<std::pair<long, std::string>> counts;
    for (std::size_t k = 0; k < rejection_kinds; ++k)
      if (rejections_[k] > 0) counts.emplace_back(rejections_[k], rejection_text(static_cast<Rejection>(k)));
    if (outside_limits_ > 0) counts.emplace_back(outside_limits_, "outside the user's search limits");
    if (too_shallow_ > 0) counts.emplace_back(too_shallow_, "shallower than the minimum depth");
    std::sort(counts.begin(), counts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t i = 0; i < counts.size() && i < 3; ++i)
      out << (i == 0 ? "" : "; ") << counts[i].first << " x " << counts[i].second;
    return out.str();
  }

  std::string failure_summary(std::size_t method_index) const {
    const auto& counts = failures_[method_index];
    std::size_t most = 0;
    for (std::size_t k = 1; k < failure_kinds; ++k)
      if (counts[k] > counts[most]) most = k;
    if (counts[most] == 0) return "no admissible trial circle";
    std::ostringstream out;
    out << counts[most] << " trial circles failed, e.g. " << failure_text_[method_index][most];
    return out.str();
  }

 private:
  // The solution of a method's own equations on the current table, solved on first use per trial.
  const Outcome& solution_of(Method method) {
    const std::size_t i = method_index(method);
    if (!solved_[i]) {
      const MethodRow& row = method_table()[i];
      solutions_[i] = solve_row(row, table_, ws_, warm_start(row));
      solved_[i] = true;
    }
    return solutions_[i];
  }

  // The first of the row's warm-start methods already solved on this table with a finite factor of safety;
  // 0 (the method's own start) when none is.
  double warm_start(const MethodRow& row) const {
    for (const std::optional<Method>& m : row.warm_start) {
      if (!m) continue;
      const std::size_t i = method_index(*m);
      if (solved_[i] && solutions_[i].ok() && std::isfinite(solutions_[i].factor_of_safety))
        return solutions_[i].factor_of_safety;
    }
    return 0.0;
  }

  void record_failure(std::size_t method_index, const Outcome& o) {
    const auto kind = static_cast<std::size_t>(o.failure);
    if (failures_[method_index][kind]++ == 0) failure_text_[method_index][kind] = describe_failure(o, table_);
  }

  const std::vector<Method>& methods_;
  const SearchOptions& options_;
  Slicer slicer_;
  SliceTable table_;
  MethodWorkspace ws_;
  double relief_ = 0.0, width_ = 0.0, minimum_depth_ = 0.0;
  long evaluations_ = 0;
  std::array<long, rejection_kinds> rejections_{};
  long outside_limits_ = 0, too_shallow_ = 0;
  std::vector<std::array<long, failure_kinds>> failures_;
  std::vector<std::array<std::string, failure_kinds>> failure_text_;
  std::array<Outcome, method_count> solutions_{};  // per method-table row, this trial's solutions
  std::array<bool, method_count> solved_{};
};

// ---- coarse trial circles (search_coarse.cpp) ------------------------------------------------------------------

// Entry-exit trials: circles through pairs of ground points (an even grid plus the vertices that shape the
// ground), `samples` points over the whole ground or the user's entry/exit ranges.
std::vector<Circle> entry_exit_circles(const PreparedSection& ps, const SearchLimits& limits, int samples);
// Grid-and-radius trials: every centre of the grid with radii from the range, or automatic radii.
std::vector<Circle> grid_circles(const PreparedSection& ps, const CentreGrid& grid,
                                 const std::optional<Range>& radius_range);

// ---- refinement (search_refine.cpp) ----------------------------------------------------------------------------

// Candidate critical circles of one method, best first (FS, circle).
using Candidates = std::vector<std::pair<double, Circle>>;

// The best coarse trial of method k and the results of refining up to three distinct good trials. Empty when the
// method failed on every trial. fs holds trials x n_methods factors of safety (NaN: failed).
Candidates refine_method(SearchEngine& engine, std::size_t k, const std::vector<Trial>& trials,
                         const std::vector<double>& fs, std::size_t n_methods, bool refine, bool check_box);
// For every method, the other methods' best circles: one that gives this method a lower FS than its own best
// starts one more refinement.
void cross_refine(SearchEngine& engine, std::vector<Candidates>& found, bool check_box);
// The critical surface with its slices and forces, through the public path.
CriticalSurface critical_surface(const Section& section, Method method, const Candidates& candidates,
                                 const SearchOptions& options, const std::string& failure_summary);

}  // namespace slope::detail
