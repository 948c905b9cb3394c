// The "lem" stage: the limit-equilibrium search for the critical slip circle of every method.
#include "coupling/analyses/stage.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

namespace coupling {

std::vector<GivenSurfaceResult> analyse_given_surfaces(const slope::Section& section, const LemAnalysis& analysis) {
  std::vector<GivenSurfaceResult> out;
  for (const GivenSurface& given : analysis.surfaces) {
    GivenSurfaceResult surface{given.name, {}};
    std::string reason;
    const auto mass = slope::slice_polyline(section, given.polyline, analysis.search.slicing, &reason);
    for (slope::Method method : analysis.methods) {
      slope::CriticalSurface result{method, mass, {}};
      if (mass) result.result = slope::factor_of_safety(*mass, method, true);
      else result.result.error = "not an admissible slip surface: " + reason;
      surface.methods.push_back(std::move(result));
    }
    out.push_back(std::move(surface));
  }
  return out;
}

namespace {

NewmarkOutcome newmark_outcome(const AccelerationRecordInput& input, double yield_coefficient) {
  NewmarkOutcome out;
  constexpr double g = sphslope::standard_gravity;
  out.as_given = slope::newmark_displacement(input.record, yield_coefficient, input.scale, g, &out.as_given_history);
  out.reversed = slope::newmark_displacement(input.record, yield_coefficient, -input.scale, g, &out.reversed_history);
  for (double a : input.record.acceleration) out.peak_acceleration = std::max(out.peak_acceleration, std::fabs(a));
  out.peak_acceleration *= input.scale;
  return out;
}

// analyses.lem.rapid_drawdown on every given surface.
std::vector<DrawdownSurfaceResult> analyse_drawdown(const slope::Section& section, const LemAnalysis& analysis) {
  const DrawdownAnalysis& drawdown = *analysis.rapid_drawdown;
  slope::DrawdownInput input{section, section, drawdown.envelopes, drawdown.method, analysis.search.slicing};
  input.after.water = drawdown.water_after;
  std::vector<DrawdownSurfaceResult> out;
  for (const GivenSurface& given : analysis.surfaces)
    out.push_back({given.name, slope::rapid_drawdown(input, std::nullopt, given.polyline)});
  return out;
}

}  // namespace

StageOutcome run_lem_stage(const Scene& scene, StageContext& context) {
  const LemAnalysis& analysis = *context.lem;
  RunResults& results = context.results;
  StageRecord<LemStageResult>& record = results.lem.emplace();
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  const slope::Section& section = scene.section->section;
  slope::SearchResult search;
  try {
    search = slope::search_critical(section, analysis.methods, analysis.search);
  } catch (const std::exception& error) {
    outcome.fail(std::string("lem: the limit-equilibrium search failed: ") + error.what(), record.error);
    results.seconds["lem"] = seconds_since(start);
    return outcome;
  }
  results.seconds["lem"] = seconds_since(start);

  if (!search.error.empty()) {
    if (analysis.has_search_limits) {
      // The user's limits admit no slip circle: that is a fault of the input, reported at its JSON path.
      outcome.status = ExitStatus::invalid_input;
      outcome.errors.push_back("analyses.lem.search: the search limits admit no valid slip circle (" + search.error +
                               "); widen entry_x_m, exit_x_m, radius_m or centre_grid, or leave \"search\" out "
                               "for the automatic search");
      return outcome;
    }
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back("lem: the automatic search found no valid slip circle: " + search.error);
  }
  LemStageResult result;
  result.analysis = analysis;
  result.surfaces = analyse_given_surfaces(section, analysis);
  if (analysis.noncircular && search.error.empty()) {
    const StageClock::time_point noncircular_start = StageClock::now();
    result.noncircular = slope::search_noncircular(section, search, analysis.search, *analysis.noncircular);
    results.seconds["lem_noncircular"] = seconds_since(noncircular_start);
  }
  if (analysis.critical_coefficient_method && search.error.empty()) {
    const StageClock::time_point k_start = StageClock::now();
    result.critical_coefficient =
        slope::critical_seismic_coefficient(section, *analysis.critical_coefficient_method, analysis.search);
    results.seconds["lem_critical_coefficient"] = seconds_since(k_start);
    if (analysis.acceleration_record && result.critical_coefficient->coefficient)
      result.newmark = newmark_outcome(*analysis.acceleration_record, *result.critical_coefficient->coefficient);
  }
  if (outcome.status == ExitStatus::ok) {
    bool any = false;
    for (const slope::CriticalSurface& critical : search.methods) {
      any = any || (critical.mass && critical.result.factor_of_safety && std::isfinite(*critical.result.factor_of_safety));
    }
    if (!any) {
      outcome.status = ExitStatus::failed;
      outcome.errors.push_back("lem: no method converged on any slip surface (see lem.methods.*.error)");
    }
  }
  result.search = std::move(search);
  if (analysis.probabilistic && result.search.error.empty()) {
    try {
      result.probabilistic = run_probabilistic(section, result, *analysis.probabilistic, context.options.log,
                                               context.options.sample_part, context.options.merge_samples);
    } catch (const std::invalid_argument& error) {  // a part that is not this analysis's (--sample-part, --merge-samples)
      outcome.status = ExitStatus::invalid_input;
      outcome.errors.push_back(error.what());
      return outcome;
    }
    results.seconds["lem_probabilistic"] = result.probabilistic->seconds;
  }
  if (analysis.rapid_drawdown) {
    const StageClock::time_point drawdown_start = StageClock::now();
    result.rapid_drawdown = analyse_drawdown(section, analysis);
    results.seconds["lem_rapid_drawdown"] = seconds_since(drawdown_start);
  }
  if (analysis.sensitivity && result.search.error.empty()) {
    result.sensitivity = run_sensitivity(section, result, *analysis.sensitivity);
    results.seconds["lem_sensitivity"] = result.sensitivity->seconds;
  }
  record.result = std::move(result);
  return outcome;
}

}  // namespace coupling
