// analyses.lem.probabilistic, run after the limit-equilibrium search: the surface the samples are analysed on, the
// samples, and their statistics (slope/probabilistic.hpp).
#include <ostream>

#include "coupling/analyses/stage.hpp"

namespace coupling {

namespace {

const slope::CriticalSurface* critical_of(const slope::SearchResult& search, slope::Method method) {
  for (const slope::CriticalSurface& c : search.methods)
    if (c.method == method && c.mass && c.result.factor_of_safety) return &c;
  return nullptr;
}

// The surface and the deterministic factor of safety; error set when the method has none.
void choose_surface(const ProbabilisticAnalysis& a, const LemStageResult& lem, ProbabilisticOutcome& out) {
  const std::string method(slope::method_key(a.method));
  if (a.mode == ProbabilisticMode::given_surface) {
    const GivenSurfaceResult& given = lem.surfaces[*a.surface];
    out.surface.kind = slope::ProbabilisticSurface::Kind::fixed_polyline;
    out.surface.polyline = lem.analysis.surfaces[*a.surface].polyline;
    for (const slope::CriticalSurface& c : given.methods)
      if (c.method == a.method) out.deterministic = c.result.factor_of_safety;
    if (!out.deterministic)
      out.error = method + " found no factor of safety on the given surface \"" + given.name + "\"";
    return;
  }
  const slope::CriticalSurface* critical = critical_of(lem.search, a.method);
  if (critical == nullptr) {
    out.error = "the search found no critical circle for " + method;
    return;
  }
  out.deterministic = critical->result.factor_of_safety;
  out.surface.circle = critical->mass->circle;
  out.surface.kind = a.mode == ProbabilisticMode::overall ? slope::ProbabilisticSurface::Kind::overall
                                                          : slope::ProbabilisticSurface::Kind::fixed_circle;
}

}  // namespace

ProbabilisticOutcome run_probabilistic(const slope::Section& section, const LemStageResult& lem,
                                       const ProbabilisticAnalysis& a, std::ostream* log) {
  ProbabilisticOutcome out;
  const StageClock::time_point start = StageClock::now();
  choose_surface(a, lem, out);
  if (!out.error.empty()) return out;
  out.values = slope::draw_samples(a.plan, 0, a.plan.samples);
  StageClock::time_point last = start;
  const auto progress = [&](long done) {
    if (log == nullptr || seconds_since(last) < 2.0) return;
    last = StageClock::now();
    *log << "lem probabilistic: " << done << " / " << a.plan.samples << " samples (" << static_cast<long>(seconds_since(start))
         << " s)" << std::endl;
  };
  out.samples = slope::evaluate_samples(section, a.plan, out.surface, a.method, lem.analysis.search, out.values, progress);
  out.statistics = slope::probabilistic_statistics(out.samples);
  out.seconds = seconds_since(start);
  return out;
}

}  // namespace coupling
