// The "compare" stage: the SPH failure surface read out of the final particle state and compared with the
// critical limit-equilibrium surfaces, with the acceptance criteria of analyses.compare.
#include "coupling/analyses/stage.hpp"

#include "coupling/compare/acceptance.hpp"
#include "coupling/compare/comparison.hpp"
#include "coupling/output/comparison_report.hpp"

namespace coupling {

StageOutcome run_compare_stage(const Scene& scene, StageContext& context) {
  WorkflowResult& out = context.out;
  const std::optional<ParticleSnapshot>& final_state = context.final_state;
  std::optional<SphFailure>& failure = context.failure;
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  if (!final_state || !out.lem || !scene.section) {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back("compare: needs both a finished SPH run and a limit-equilibrium result");
    out.report["comparison"] = comparison_error_report(outcome.errors.back());
    return outcome;
  }
  const ComparisonOptions& options = *scene.analyses.compare;
  const slope::Section& section = scene.section->section;
  failure = extract_sph_failure(*final_state, section.profile_lines.front().points, options);
  ComparisonResult comparison = compare_with_lem(section, *failure, *out.lem, options,
                                                 out.lem_noncircular ? &*out.lem_noncircular : nullptr);
  // Loads SPH left out on request (analyses.sph.ignore_loads): the two surfaces answer different problems.
  for (const SectionLoad& load : loads_sph_leaves_out(scene))
    comparison.verdict += " Caution: the SPH run leaves out " + load.name + " (" + load.path +
                          "), the limit-equilibrium analysis includes it.";
  if (options.acceptance) {
    comparison.acceptance = evaluate_acceptance(*options.acceptance, comparison, final_state->spacing);
    if (!comparison.acceptance->accepted) {
      outcome.status = ExitStatus::not_accepted;
      outcome.errors = failed_criteria_lines(*comparison.acceptance);
    }
  }
  out.report["comparison"] = comparison_report(comparison);
  out.report["timing_s"]["compare"] = seconds_since(start);
  return outcome;
}

}  // namespace coupling
