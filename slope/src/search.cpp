// Critical circular slip-surface search.
//
// 1. Coarse search (no user settings needed):
//    - entry-exit (default, or with entry/exit ranges and/or a radius range): points on the ground surface (an even
//      grid over the whole section plus the vertices that shape the ground, at most as many as the grid); for every pair where one point is higher than the
//      other, circles through both with the centre above the chord: half-angles from a near-chord circle to a
//      near-semicircle, plus the circle through both points tangent to the rigid base (the deepest admissible one);
//      with a radius range, radii from that range instead;
//    - grid-and-radius (when a centre grid is given): every grid centre with radii from the range, or automatic
//      radii from the one that just reaches the ground to the one tangent to the rigid base.
//    Every admissible circle is evaluated with every method asked for (slices are shared).
// 2. Refinement per method: GSL Nelder-Mead (nmsimplex2) in (xc, yc, R) from the best few distinct coarse circles,
//    restarted once; inadmissible circles get a penalty, and a circle that dips below the rigid base is moved onto
//    it (R = yc - bottom_y), so base-tangent optima are reached from either side.
#include "slope/search.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "method_table.hpp"
#include "slice_table.hpp"

namespace slope {

namespace {

using detail::Failure;
using detail::Rejection;

constexpr double penalty_value = 1e6;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t rejection_kinds = 8;
constexpr std::size_t failure_kinds = 9;

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v;
  if (n <= 1) {
    v.push_back(0.5 * (a + b));
    return v;
  }
  for (int i = 0; i < n; ++i) v.push_back(a + (b - a) * i / (n - 1));
  return v;
}

Range ordered(Range r) {
  if (r.min > r.max) std::swap(r.min, r.max);
  return r;
}

// Circle through p and q with the given radius and its centre above the chord (the arc between them below it).
std::optional<Circle> circle_through(const Point& p, const Point& q, double radius) {
  const double ux = q.x - p.x;
  const double uy = q.y - p.y;
  const double length = std::sqrt(ux * ux + uy * uy);
  if (!(length > 0.0) || radius < 0.5 * length) return std::nullopt;
  double nx = -uy / length, ny = ux / length;
  if (ny < 0.0) {
    nx = -nx;
    ny = -ny;
  }
  const double h = std::sqrt(std::max(0.0, radius * radius - 0.25 * length * length));
  return Circle{0.5 * (p.x + q.x) + nx * h, 0.5 * (p.y + q.y) + ny * h, radius};
}

// Circles through p and q tangent to the horizontal line y = base (both points above it).
void circles_tangent_to_base(const Point& p, const Point& q, double base, std::vector<Circle>& out) {
  const double ap = p.y - base;
  const double aq = q.y - base;
  if (!(ap > 0.0) || !(aq > 0.0)) return;
  // yc = ((xp - xc)^2 + yp^2 - base^2) / (2 ap), the same with q; equate -> a xc^2 + b xc + c = 0
  const double kp = p.x * p.x + p.y * p.y - base * base;
  const double kq = q.x * q.x + q.y * q.y - base * base;
  const double a = aq - ap;
  const double b = -2.0 * (p.x * aq - q.x * ap);
  const double c = kp * aq - kq * ap;
  double roots[2];
  int count = 0;
  if (std::fabs(a) < 1e-12 * (std::fabs(b) + 1e-300)) {
    if (b != 0.0) roots[count++] = -c / b;
  } else {
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return;
    const double sq = std::sqrt(disc);
    roots[count++] = (-b + sq) / (2.0 * a);
    roots[count++] = (-b - sq) / (2.0 * a);
  }
  for (int i = 0; i < count; ++i) {
    const double xc = roots[i];
    const double yc = ((p.x - xc) * (p.x - xc) + p.y * p.y - base * base) / (2.0 * ap);
    const double radius = yc - base;
    if (radius > 0.0 && std::isfinite(radius)) out.push_back(Circle{xc, yc, radius});
  }
}

double distance_to_polyline(const std::vector<Point>& line, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const double dx = line[i + 1].x - line[i].x;
    const double dy = line[i + 1].y - line[i].y;
    const double t = std::clamp(((x - line[i].x) * dx + (y - line[i].y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    const double ex = line[i].x + t * dx - x;
    const double ey = line[i].y + t * dy - y;
    best = std::min(best, std::sqrt(ex * ex + ey * ey));
  }
  return best;
}

struct Trial {
  Circle circle;
  Point entry, exit;
};

class Engine {
 public:
  enum class Admit { ok, rejected, outside_limits, too_shallow };

  Engine(const Section& section, const std::vector<Method>& methods, const SearchOptions& options)
      : methods_(methods), options_(options), slicer_(section) {
    const detail::PreparedSection& ps = slicer_.prepared();
    relief_ = ps.ground_y_max - ps.ground_y_min;
    width_ = ps.x_max - ps.x_min;
    minimum_depth_ = options.minimum_depth >= 0.0 ? options.minimum_depth : 0.02 * relief_;
    failures_.assign(methods.size(), {});
    failure_text_.assign(methods.size(), {});
  }

  const detail::PreparedSection& prepared() const { return slicer_.prepared(); }
  const detail::SliceTable& table() const { return table_; }
  double relief() const { return relief_; }
  double width() const { return width_; }
  long evaluations() const { return evaluations_; }

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

  // One method on the current table; NaN on failure.
  double evaluate(std::size_t method_index, double guess = 0.0) {
    const Method method = methods_[method_index];
    ++evaluations_;
    const detail::Outcome o = detail::evaluate_method(table_, method, ws_, guess);
    if (o.ok()) return o.factor_of_safety;
    record_failure(method_index, o);
    return nan;
  }

  // Every method on the current table; fs[k] is NaN on failure. Each set of equations is solved once (the method
  // table's solution_of), and a method starts from another's factor of safety on the same circle (warm_start).
  void evaluate_all(double* fs) {
    solved_.fill(false);
    for (std::size_t k = 0; k < methods_.size(); ++k) {
      const detail::MethodRow& row = detail::method_row(methods_[k]);
      ++evaluations_;
      const detail::Outcome& solution = solution_of(row.solution_of);
      const detail::Outcome o = row.from_solution ? row.from_solution(table_, solution) : solution;
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
      if (rejections_[k] > 0) counts.emplace_back(rejections_[k], detail::rejection_text(static_cast<Rejection>(k)));
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
  const detail::Outcome& solution_of(Method method) {
    const std::size_t i = detail::method_index(method);
    if (!solved_[i]) {
      const detail::MethodRow& row = detail::method_table()[i];
      solutions_[i] = row.solve(table_, ws_, warm_start(row));
      solved_[i] = true;
    }
    return solutions_[i];
  }

  // The first of the row's warm-start methods already solved on this table with a finite factor of safety;
  // 0 (the method's own start) when none is.
  double warm_start(const detail::MethodRow& row) const {
    for (const std::optional<Method>& m : row.warm_start) {
      if (!m) continue;
      const std::size_t i = detail::method_index(*m);
      if (solved_[i] && solutions_[i].ok() && std::isfinite(solutions_[i].factor_of_safety))
        return solutions_[i].factor_of_safety;
    }
    return 0.0;
  }

  void record_failure(std::size_t method_index, const detail::Outcome& o) {
    const auto kind = static_cast<std::size_t>(o.failure);
    if (failures_[method_index][kind]++ == 0) failure_text_[method_index][kind] = detail::describe_failure(o, table_);
  }

  const std::vector<Method>& methods_;
  const SearchOptions& options_;
  detail::Slicer slicer_;
  detail::SliceTable table_;
  detail::MethodWorkspace ws_;
  double relief_ = 0.0, width_ = 0.0, minimum_depth_ = 0.0;
  long evaluations_ = 0;
  std::array<long, rejection_kinds> rejections_{};
  long outside_limits_ = 0, too_shallow_ = 0;
  std::vector<std::array<long, failure_kinds>> failures_;
  std::vector<std::array<std::string, failure_kinds>> failure_text_;
  std::array<detail::Outcome, detail::method_count> solutions_{};  // per method-table row, this trial's solutions
  std::array<bool, detail::method_count> solved_{};
};

// ---- coarse trial circles -------------------------------------------------------------------------------------

// Indices of the ground vertices that shape the profile: the Douglas-Peucker simplification of the ground to
// within `tolerance` (m), ends excluded. Collinear vertices are never kept, so splitting a segment changes nothing.
std::vector<std::size_t> shape_vertices(const std::vector<Point>& ground, double tolerance) {
  std::vector<std::size_t> kept;
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, ground.size() - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    if (b <= a + 1) continue;
    const double ux = ground[b].x - ground[a].x;
    const double uy = ground[b].y - ground[a].y;
    const double length = std::hypot(ux, uy);
    double farthest = -1.0;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = std::fabs((ground[i].x - ground[a].x) * uy - (ground[i].y - ground[a].y) * ux) / length;
      if (d > farthest) {
        farthest = d;
        at = i;
      }
    }
    if (!(farthest > tolerance)) continue;
    kept.push_back(at);
    stack.push_back({a, at});
    stack.push_back({at, b});
  }
  return kept;
}

// The ground vertices offered as entry and exit points besides the even grid: those that shape the profile (its
// crest, toe and breaks of slope), at most `count` of them. The tolerance starts at 0.1 % of the relief and is
// doubled until few enough remain, so a hand-drawn section keeps all its corners and a surveyed profile of tens
// of thousands of vertices offers its main breaks only (the refinement then moves freely between vertices).
std::vector<double> shape_vertex_xs(const detail::PreparedSection& ps, std::size_t count) {
  const double relief = ps.ground_y_max - ps.ground_y_min;
  std::vector<std::size_t> kept;
  for (double tolerance = 1e-3 * relief;; tolerance *= 2.0) {
    kept = shape_vertices(ps.ground, tolerance);
    if (kept.size() <= count || !(tolerance < relief)) break;
  }
  std::vector<double> xs{ps.ground.front().x, ps.ground.back().x};
  for (std::size_t i : kept) xs.push_back(ps.ground[i].x);
  return xs;
}

std::vector<double> ground_samples(const detail::PreparedSection& ps, std::optional<Range> range, int count) {
  Range r{ps.x_min, ps.x_max};
  if (range) {
    r = ordered(*range);
    r.min = std::max(r.min, ps.x_min);
    r.max = std::min(r.max, ps.x_max);
    if (r.min > r.max) return {};
  }
  std::vector<double> xs = linspace(r.min, r.max, count);
  for (double x : shape_vertex_xs(ps, static_cast<std::size_t>(std::max(count, 1))))
    if (x >= r.min && x <= r.max) xs.push_back(x);
  std::sort(xs.begin(), xs.end());
  const double tol = 1e-6 * (ps.x_max - ps.x_min);
  xs.erase(std::unique(xs.begin(), xs.end(), [tol](double a, double b) { return b - a < tol; }), xs.end());
  return xs;
}

std::vector<Circle> entry_exit_circles(const detail::PreparedSection& ps, const SearchLimits& limits, int samples) {
  std::vector<Circle> circles;
  // A user range is narrower than the whole ground line: it gets 17 of the default 41 points, in proportion.
  const int limited = std::max(3, (samples * 17 + 20) / 41);
  const std::vector<double> entries = ground_samples(ps, limits.entry_x, limits.entry_x ? limited : samples);
  const std::vector<double> exits = ground_samples(ps, limits.exit_x, limits.exit_x ? limited : samples);
  const double relief = ps.ground_y_max - ps.ground_y_min;
  const double tol_y = 1e-3 * relief + 1e-12;
  const double min_chord = 1e-3 * (ps.x_max - ps.x_min);
  static constexpr double half_angles_deg[] = {4, 10, 17, 24, 32, 40, 49, 58, 68, 80};
  for (double xe : entries) {
    const Point p{xe, ps.ground_at(xe)};
    for (double xx : exits) {
      const Point q{xx, ps.ground_at(xx)};
      if (!(p.y > q.y + tol_y) || std::fabs(p.x - q.x) < min_chord) continue;
      const double length = std::hypot(q.x - p.x, q.y - p.y);
      if (limits.radius) {
        const Range rr = ordered(*limits.radius);
        for (double radius : linspace(rr.min, rr.max, 8))
          if (auto c = circle_through(p, q, radius)) circles.push_back(*c);
      } else {
        for (double deg : half_angles_deg) {
          const double radius = 0.5 * length / std::sin(deg * M_PI / 180.0);
          if (auto c = circle_through(p, q, radius)) circles.push_back(*c);
        }
        circles_tangent_to_base(p, q, ps.bottom_y, circles);
      }
    }
  }
  return circles;
}

std::vector<Circle> grid_circles(const detail::PreparedSection& ps, const CentreGrid& grid,
                                 const std::optional<Range>& radius_range) {
  std::vector<Circle> circles;
  for (double xc : linspace(grid.x.min, grid.x.max, std::max(1, grid.nx))) {
    for (double yc : linspace(grid.y.min, grid.y.max, std::max(1, grid.ny))) {
      if (radius_range) {
        const Range rr = ordered(*radius_range);
        for (double radius : linspace(rr.min, rr.max, 10)) circles.push_back(Circle{xc, yc, radius});
        continue;
      }
      const double r_lo = distance_to_polyline(ps.ground, xc, yc);
      const double r_hi = yc - ps.bottom_y;
      if (!(r_hi > r_lo)) continue;
      for (int k = 1; k <= 12; ++k) circles.push_back(Circle{xc, yc, r_lo + (r_hi - r_lo) * k / 12.0});
    }
  }
  return circles;
}

// ---- Nelder-Mead refinement -----------------------------------------------------------------------------------

struct Refinement {
  Engine* engine;
  std::size_t method_index;
  bool check_centre_box;
  double best_fs = std::numeric_limits<double>::infinity();
  Circle best_circle;
};

double refinement_objective(const gsl_vector* v, void* params) {
  Refinement& r = *static_cast<Refinement*>(params);
  Circle circle{gsl_vector_get(v, 0), gsl_vector_get(v, 1), gsl_vector_get(v, 2)};
  if (r.engine->admit(circle, true, r.check_centre_box) != Engine::Admit::ok) return penalty_value;
  const double fs = r.engine->evaluate(r.method_index);
  if (!std::isfinite(fs)) return penalty_value;
  if (fs < r.best_fs) {
    r.best_fs = fs;
    r.best_circle = circle;
  }
  return fs;
}

void nelder_mead(Refinement& r, const Circle& start, double step, double tolerance) {
  gsl_multimin_function function{&refinement_objective, 3, &r};
  gsl_vector* x = gsl_vector_alloc(3);
  gsl_vector* steps = gsl_vector_alloc(3);
  gsl_vector_set(x, 0, start.xc);
  gsl_vector_set(x, 1, start.yc);
  gsl_vector_set(x, 2, start.radius);
  gsl_vector_set_all(steps, step);
  gsl_multimin_fminimizer* s = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, 3);
  if (gsl_multimin_fminimizer_set(s, &function, x, steps) == GSL_SUCCESS) {
    for (int it = 0; it < 400; ++it) {
      if (gsl_multimin_fminimizer_iterate(s) != GSL_SUCCESS) break;
      if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(s), tolerance) == GSL_SUCCESS) break;
    }
  }
  gsl_multimin_fminimizer_free(s);
  gsl_vector_free(steps);
  gsl_vector_free(x);
}

// Candidate critical circles of one method, best first (FS, circle).
using Candidates = std::vector<std::pair<double, Circle>>;

void sort_candidates(Candidates& c) {
  std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
}

// Runs the two Nelder-Mead passes from `start` (FS `start_fs`) for method k; returns the best circle found.
std::pair<double, Circle> refine_from(Engine& engine, std::size_t k, bool check_box, const Circle& start,
                                      double start_fs, double chord) {
  Refinement r{&engine, k, check_box, start_fs, start};
  nelder_mead(r, start, 0.05 * chord, 1e-5 * chord);
  nelder_mead(r, r.best_circle, 0.01 * chord, 1e-6 * chord);
  return {r.best_fs, r.best_circle};
}

// The best coarse trial of method k and the results of refining up to three distinct good trials (entry or exit
// more than 5 % of the section width apart). Empty when the method failed on every trial.
Candidates refine_method(Engine& engine, std::size_t k, const std::vector<Trial>& trials,
                         const std::vector<double>& fs, std::size_t n_methods, bool refine, bool check_box) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < trials.size(); ++i)
    if (std::isfinite(fs[i * n_methods + k])) order.push_back(i);
  if (order.empty()) return {};
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return fs[a * n_methods + k] < fs[b * n_methods + k]; });
  Candidates candidates{{fs[order.front() * n_methods + k], trials[order.front()].circle}};
  if (!refine) return candidates;
  std::vector<std::size_t> starts;
  const double separation = 0.05 * engine.width();
  for (std::size_t i : order) {
    bool distinct = true;
    for (std::size_t s : starts) {
      if (std::fabs(trials[i].entry.x - trials[s].entry.x) < separation &&
          std::fabs(trials[i].exit.x - trials[s].exit.x) < separation)
        distinct = false;
    }
    if (distinct) starts.push_back(i);
    if (starts.size() == 3) break;
  }
  for (std::size_t s : starts) {
    const Trial& trial = trials[s];
    const double chord = std::hypot(trial.exit.x - trial.entry.x, trial.exit.y - trial.entry.y);
    candidates.push_back(refine_from(engine, k, check_box, trial.circle, fs[s * n_methods + k], chord));
  }
  sort_candidates(candidates);
  return candidates;
}

// For every method, the other methods' best circles: one that gives this method a lower FS than its own best
// starts one more refinement.
void cross_refine(Engine& engine, std::vector<Candidates>& found, bool check_box) {
  std::vector<Circle> bests;
  for (const Candidates& c : found)
    if (!c.empty()) bests.push_back(c.front().second);
  for (std::size_t k = 0; k < found.size(); ++k) {
    if (found[k].empty()) continue;
    double best_other = found[k].front().first;
    std::optional<Circle> start;
    for (Circle circle : bests) {
      if (engine.admit(circle, true, check_box) != Engine::Admit::ok) continue;
      const double value = engine.evaluate(k);
      if (std::isfinite(value) && value < best_other * (1.0 - 1e-9)) {
        best_other = value;
        start = circle;
      }
    }
    if (!start) continue;
    const detail::SliceTable& t = engine.table();
    engine.admit(*start, true, check_box);
    const double chord = std::hypot(t.exit.x - t.entry.x, t.exit.y - t.entry.y);
    found[k].push_back(refine_from(engine, k, check_box, *start, best_other, chord));
    sort_candidates(found[k]);
  }
}

// The critical surface with its slices and forces, through the public path (same code as the trials; a
// candidate that does not reproduce there, which only happens on ill-conditioned slivers, gives way to the next).
CriticalSurface critical_surface(const Section& section, Method method, const Candidates& candidates,
                                 const SearchOptions& options, const std::string& failure_summary) {
  CriticalSurface critical;
  critical.method = method;
  if (candidates.empty()) {
    critical.result.error = std::string(method_key(method)) + ": the method failed on every admissible trial circle (" +
                            failure_summary + ")";
    return critical;
  }
  for (const auto& [value, circle] : candidates) {
    std::string reason;
    std::optional<SlipMass> mass = slice_circle(section, circle, options.slicing, &reason);
    if (!mass) {
      if (critical.result.error.empty()) critical.result.error = std::string(method_key(method)) + ": " + reason;
      continue;
    }
    FsResult fs_result = factor_of_safety(*mass, method, true);
    if (!fs_result.factor_of_safety) {
      if (critical.result.error.empty()) critical.result.error = fs_result.error;
      continue;
    }
    critical.result = std::move(fs_result);
    critical.mass = std::move(mass);
    break;
  }
  return critical;
}

}  // namespace

SearchResult search_critical(const Section& section, const std::vector<Method>& methods,
                             const SearchOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  SearchResult result;
  auto finish = [&]() {
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
  };
  auto fail_all = [&](const std::string& error) {
    result.error = error;
    for (Method m : methods) {
      CriticalSurface c;
      c.method = m;
      c.result.error = std::string(method_key(m)) + ": " + error;
      result.methods.push_back(std::move(c));
    }
  };
  if (const std::string error = section_error(section); !error.empty()) {
    fail_all("invalid section: " + error);
    return finish();
  }
  if (methods.empty()) return finish();

  Engine engine(section, methods, options);
  const detail::PreparedSection& ps = engine.prepared();
  const SearchLimits& limits = options.limits;
  if (!(engine.relief() > 0.0)) {
    fail_all("the ground surface is flat: there is no slope to analyse");
    return finish();
  }

  // 1. Coarse search.
  const std::vector<Circle> candidates =
      limits.centre_grid ? grid_circles(ps, *limits.centre_grid, limits.radius)
                         : entry_exit_circles(ps, limits, std::max(3, options.entry_exit_samples));
  const std::size_t n_methods = methods.size();
  std::vector<Trial> trials;
  std::vector<double> fs;  // trials x methods
  std::vector<double> row(n_methods);
  for (Circle circle : candidates) {
    if (engine.admit(circle, false, false) != Engine::Admit::ok) continue;
    engine.evaluate_all(row.data());
    const detail::SliceTable& t = engine.table();
    trials.push_back(Trial{circle, t.entry, t.exit});
    fs.insert(fs.end(), row.begin(), row.end());
    if (std::isfinite(row[0])) result.fs_map.push_back(FsMapEntry{circle, t.entry, t.exit, row[0]});
  }
  if (trials.empty()) {
    std::ostringstream out;
    out << "no admissible slip circle within the search limits (";
    if (candidates.empty())
      out << "no trial circle can be drawn: every entry point must lie above an exit point on the ground surface";
    else
      out << candidates.size() << " trial circles: " << engine.rejection_summary();
    out << ")";
    fail_all(out.str());
    result.trial_surfaces = engine.evaluations();
    return finish();
  }

  // 2. Refinement, per method; then each method tries the other methods' critical circles, and refines from one
  //    that beats its own (on rough surveyed ground a refinement can stop in a local minimum another one avoided).
  const bool check_box = limits.centre_grid.has_value();
  std::vector<Candidates> found(n_methods);
  for (std::size_t k = 0; k < n_methods; ++k)
    found[k] = refine_method(engine, k, trials, fs, n_methods, options.refine, check_box);
  if (options.refine) cross_refine(engine, found, check_box);
  for (std::size_t k = 0; k < n_methods; ++k)
    result.methods.push_back(critical_surface(section, methods[k], found[k], options, engine.failure_summary(k)));
  result.trial_surfaces = engine.evaluations();
  return finish();
}

}  // namespace slope
