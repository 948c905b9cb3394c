// The "srm" stage: the SPH factor of safety by strength reduction (analyses.srm), next to the LEM factors.
#include "coupling/analyses/stage.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <ostream>

#include "coupling/analyses/strength_reduction.hpp"
#include "coupling/output/report.hpp"
#include "coupling/output/srm_report.hpp"

namespace coupling {

StageOutcome run_srm_stage(const Scene& scene, StageContext& context) {
  const WorkflowOptions& options = context.options;
  WorkflowResult& out = context.out;
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  std::optional<double> bishop;
  std::map<std::string, double> lem_fs;
  if (out.lem)
    for (const auto& critical : out.lem->methods)
      if (critical.mass && critical.result.factor_of_safety && std::isfinite(*critical.result.factor_of_safety)) {
        const std::string key(slope::method_key(critical.method));
        lem_fs[key] = *critical.result.factor_of_safety;
        if (key == "bishop") bishop = *critical.result.factor_of_safety;
      }
  try {
    const SrmOptions& srm = *scene.analyses.srm;
    const SrmResult result =
        run_strength_reduction(scene, srm, bishop, lem_fs, options.log, SrmFiles{options.output_dir, options.resume});
    out.report["srm"] = srm_report(result);
    if (!result.ok) {
      outcome.status = ExitStatus::failed;
      outcome.errors.push_back(result.bisection.error.empty() ? std::string("srm: no factor of safety")
                                                              : "srm: " + result.bisection.error);
    }
    if (options.log) {
      char line[200];
      const std::string lem_text = bishop ? format_number(*bishop) : std::string("-");
      if (result.bisection.bracketed)
        std::snprintf(line, sizeof line, "srm: FS_SPH = %.3f in [%.3f, %.3f]; LEM Bishop = %s\n",
                      result.bisection.factor_of_safety, result.bisection.lo, result.bisection.hi, lem_text.c_str());
      else
        std::snprintf(line, sizeof line, "srm: FS_SPH not bracketed; LEM Bishop = %s\n", lem_text.c_str());
      *options.log << line;
    }
  } catch (const SceneError& error) {
    outcome.status = ExitStatus::invalid_input;
    outcome.errors = error.messages();
    return outcome;
  } catch (const std::exception& error) {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back(std::string("srm: ") + error.what());
    out.report["srm"] = srm_error_report(outcome.errors.back());
  }
  out.report["timing_s"]["srm"] = seconds_since(start);
  return outcome;
}

}  // namespace coupling
