#pragma once
// Acceptance criteria of a surface comparison (analyses.compare.acceptance): limits on how far the SPH failure
// surface may lie from a limit-equilibrium critical surface, so that a pipeline gets "accepted or not, and why".
// Keys, units and defaults: docs/scene-format.md ("analyses.compare.acceptance"); exit status: docs/pipelines.md.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/analysis_options.hpp"

namespace coupling {

// One evaluated criterion.
struct CriterionResult {
  std::string method;     // LE method key
  std::string criterion;  // e.g. "entry_offset_m"
  double limit = 0.0;     // in the criterion's unit (m, or - for overlap and FS)
  std::optional<double> measured;
  bool passed = false;
  std::string note;       // why it could not be measured, or the limit's origin ("4 particle spacings")
};

struct AcceptanceResult {
  std::vector<CriterionResult> criteria;
  bool accepted = false;  // every criterion passed (a criterion that cannot be measured fails)
};

// Evaluates the criteria on the "comparison" block of the report (its "methods.<key>" figures).
AcceptanceResult evaluate_acceptance(const AcceptanceCriteria& criteria, const nlohmann::json& comparison,
                                     double particle_spacing);

// The "acceptance" block of the comparison report, and one line per failed criterion for stderr.
nlohmann::json acceptance_json(const AcceptanceResult& result);
std::vector<std::string> failed_criteria_lines(const AcceptanceResult& result);

}  // namespace coupling
