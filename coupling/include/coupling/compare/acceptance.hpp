#pragma once
// Acceptance criteria of a surface comparison (analyses.compare.acceptance): limits on how far the SPH failure
// surface may lie from a limit-equilibrium critical surface, so that a pipeline gets "accepted or not, and why".
// Keys, units and defaults: docs/scene-format.md ("analyses.compare.acceptance"); exit status: docs/pipelines.md.
#include <optional>
#include <string>
#include <vector>

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

struct ComparisonResult;

// Evaluates the criteria on the comparison's figures per method.
AcceptanceResult evaluate_acceptance(const AcceptanceCriteria& criteria, const ComparisonResult& comparison,
                                     double particle_spacing);

// One line per failed criterion, for stderr.
std::vector<std::string> failed_criteria_lines(const AcceptanceResult& result);

}  // namespace coupling
