// Critical-circle search, step 2: refinement per method. GSL Nelder-Mead (nmsimplex2) in (xc, yc, R) from the best
// few distinct coarse circles, restarted once; inadmissible circles get a penalty, and a circle that dips below the
// rigid base is moved onto it (R = yc - bottom_y), so base-tangent optima are reached from either side. Then each
// method tries the other methods' critical circles; the critical surface is recomputed through the public path.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>

#include "search_internal.hpp"

namespace slope::detail {

namespace {


struct Refinement {
  SearchEngine* engine;
  std::size_t method_index;
  bool check_centre_box;
  double best_fs = std::numeric_limits<double>::infinity();
  Circle best_circle;
};

double refinement_objective(const gsl_vector* v, void* params) {
  Refinement& r = *static_cast<Refinement*>(params);
  Circle circle{gsl_vector_get(v, 0), gsl_vector_get(v, 1), gsl_vector_get(v, 2)};
  if (r.engine->admit(circle, true, r.check_centre_box) != SearchEngine::Admit::ok) return penalty_value;
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

void sort_candidates(Candidates& c) {
  std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
}

// Runs the two Nelder-Mead passes from `start` (FS `start_fs`) for method k; returns the best circle found.
std::pair<double, Circle> refine_from(SearchEngine& engine, std::size_t k, bool check_box, const Circle& start,
                                      double start_fs, double chord) {
  Refinement r{&engine, k, check_box, start_fs, start};
  nelder_mead(r, start, 0.05 * chord, 1e-5 * chord);
  nelder_mead(r, r.best_circle, 0.01 * chord, 1e-6 * chord);
  return {r.best_fs, r.best_circle};
}

}  // namespace

// The best coarse trial of method k and the results of refining up to three distinct good trials (entry or exit
// more than 5 % of the section width apart). Empty when the method failed on every trial.
Candidates refine_method(SearchEngine& engine, std::size_t k, const std::vector<Trial>& trials,
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
void cross_refine(SearchEngine& engine, std::vector<Candidates>& found, bool check_box) {
  std::vector<Circle> bests;
  for (const Candidates& c : found)
    if (!c.empty()) bests.push_back(c.front().second);
  for (std::size_t k = 0; k < found.size(); ++k) {
    if (found[k].empty()) continue;
    double best_other = found[k].front().first;
    std::optional<Circle> start;
    for (Circle circle : bests) {
      if (engine.admit(circle, true, check_box) != SearchEngine::Admit::ok) continue;
      const double value = engine.evaluate(k);
      if (std::isfinite(value) && value < best_other * (1.0 - 1e-9)) {
        best_other = value;
        start = circle;
      }
    }
    if (!start) continue;
    const SliceTable& t = engine.table();
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

}  // namespace slope::detail
