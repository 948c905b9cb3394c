// The "srm" stage: the SPH factor of safety by strength reduction (analyses.srm), next to the LEM factors.
#include "coupling/analyses/stage.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <ostream>

#include "coupling/analyses/strength_reduction.hpp"

namespace coupling {

namespace {

// LEM's factor of safety of every method that found one, by method key.
std::map<std::string, double> lem_factors(const LemStageResult* lem) {
  std::map<std::string, double> out;
  if (lem)
    for (const auto& critical : lem->search.methods)
      if (critical.mass && critical.result.factor_of_safety && std::isfinite(*critical.result.factor_of_safety))
        out[std::string(slope::method_key(critical.method))] = *critical.result.factor_of_safety;
  return out;
}

void log_srm(std::ostream& log, const SrmResult& result, std::optional<double> bishop) {
  char line[200];
  const std::string lem_text = bishop ? format_number(*bishop) : std::string("-");
  if (result.bisection.bracketed)
    std::snprintf(line, sizeof line, "srm: FS_SPH = %.3f in [%.3f, %.3f]; LEM Bishop = %s\n",
                  result.bisection.factor_of_safety, result.bisection.lo, result.bisection.hi, lem_text.c_str());
  else
    std::snprintf(line, sizeof line, "srm: FS_SPH not bracketed; LEM Bishop = %s\n", lem_text.c_str());
  log << line;
}

}  // namespace

StageOutcome run_srm_stage(const Scene& scene, StageContext& context) {
  const WorkflowOptions& options = context.options;
  RunResults& results = context.results;
  StageRecord<SrmResult>& record = results.srm.emplace();
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  const std::map<std::string, double> lem_fs = lem_factors(results.lem_result());
  std::optional<double> bishop;
  if (const auto it = lem_fs.find("bishop"); it != lem_fs.end()) bishop = it->second;
  try {
    const SrmOptions& srm = *scene.analyses.srm;
    SrmResult result =
        run_strength_reduction(scene, srm, bishop, lem_fs, options.log, SrmFiles{options.output_dir, options.resume});
    if (!result.ok) {
      outcome.status = ExitStatus::failed;
      outcome.errors.push_back(result.bisection.error.empty() ? std::string("srm: no factor of safety")
                                                              : "srm: " + result.bisection.error);
    }
    if (options.log) log_srm(*options.log, result, bishop);
    record.result = std::move(result);
  } catch (const SceneError& error) {
    outcome.status = ExitStatus::invalid_input;
    outcome.errors = error.messages();
    return outcome;
  } catch (const std::exception& error) {
    outcome.fail(std::string("srm: ") + error.what(), record.error);
  }
  results.seconds["srm"] = seconds_since(start);
  return outcome;
}

}  // namespace coupling
