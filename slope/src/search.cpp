// Critical circular slip-surface search: search_critical() runs its steps in order.
// 1. Coarse search (search_coarse.cpp): entry-exit pairs or a centre grid; every admissible circle is evaluated
//    with every method asked for (slices are shared).
// 2. Refinement per method (search_refine.cpp): Nelder-Mead from the best few distinct coarse circles, then from
//    the other methods' critical circles; the critical surface is recomputed through the public path.
#include "slope/search.hpp"

#include <algorithm>
#include <chrono>

#include "search_internal.hpp"

namespace slope {

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

  detail::SearchEngine engine(section, methods, options);
  const detail::PreparedSection& ps = engine.prepared();
  const SearchLimits& limits = options.limits;
  if (!(engine.relief() > 0.0)) {
    fail_all("the ground surface is flat: there is no slope to analyse");
    return finish();
  }

  // 1. Coarse search.
  const std::vector<Circle> candidates =
      limits.centre_grid ? detail::grid_circles(ps, *limits.centre_grid, limits.radius)
                         : detail::entry_exit_circles(ps, limits, std::max(3, options.entry_exit_samples));
  const std::size_t n_methods = methods.size();
  std::vector<detail::Trial> trials;
  std::vector<double> fs;  // trials x methods
  std::vector<double> row(n_methods);
  std::size_t map_column = 0;
  if (options.fs_map_method) {
    const auto it = std::find(methods.begin(), methods.end(), *options.fs_map_method);
    if (it != methods.end()) map_column = static_cast<std::size_t>(it - methods.begin());
  }
  for (Circle circle : candidates) {
    if (engine.admit(circle, false, false) != detail::SearchEngine::Admit::ok) continue;
    engine.evaluate_all(row.data());
    const detail::SliceTable& t = engine.table();
    trials.push_back(detail::Trial{circle, t.entry, t.exit});
    fs.insert(fs.end(), row.begin(), row.end());
    if (std::isfinite(row[map_column]))
      result.fs_map.push_back(FsMapEntry{circle, t.entry, t.exit, row[map_column]});
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
  std::vector<detail::Candidates> found(n_methods);
  for (std::size_t k = 0; k < n_methods; ++k)
    found[k] = detail::refine_method(engine, k, trials, fs, n_methods, options.refine, check_box);
  if (options.refine) detail::cross_refine(engine, found, check_box);
  for (std::size_t k = 0; k < n_methods; ++k)
    result.methods.push_back(detail::critical_surface(section, methods[k], found[k], options, engine.failure_summary(k)));
  result.trial_surfaces = engine.evaluations();
  return finish();
}

}  // namespace slope
