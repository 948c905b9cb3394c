// The "compare" stage: the SPH failure surface read out of the final particle state and compared with the
// critical limit-equilibrium surfaces, with the acceptance criteria of analyses.compare.
#include "coupling/analyses/stage.hpp"

#include "coupling/compare/acceptance.hpp"
#include "coupling/compare/comparison.hpp"

namespace coupling {

StageOutcome run_compare_stage(const Scene& scene, StageContext& context) {
  RunResults& results = context.results;
  StageRecord<ComparisonResult>& record = results.comparison.emplace();
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  const LemStageResult* lem = results.lem_result();
  if (!results.sph_final_state || !lem || !scene.section) {
    outcome.fail("compare: needs both a finished SPH run and a limit-equilibrium result", record.error);
    return outcome;
  }
  const ComparisonOptions& options = *scene.analyses.compare;
  const slope::Section& section = scene.section->section;
  results.sph_failure = extract_sph_failure(*results.sph_final_state, section.profile_lines.front().points, options);
  ComparisonResult comparison = compare_with_lem(section, *results.sph_failure, lem->search, options,
                                                 lem->noncircular ? &*lem->noncircular : nullptr);
  // Loads SPH left out on request (analyses.sph.ignore_loads): the two surfaces answer different problems.
  for (const SectionLoad& load : loads_sph_leaves_out(scene))
    comparison.verdict += " Caution: the SPH run leaves out " + load.name + " (" + load.path +
                          "), the limit-equilibrium analysis includes it.";
  if (options.acceptance) {
    comparison.acceptance = evaluate_acceptance(*options.acceptance, comparison, results.sph_final_state->spacing);
    if (!comparison.acceptance->accepted) {
      outcome.status = ExitStatus::not_accepted;
      outcome.errors = failed_criteria_lines(*comparison.acceptance);
    }
  }
  record.result = std::move(comparison);
  results.seconds["compare"] = seconds_since(start);
  return outcome;
}

}  // namespace coupling
