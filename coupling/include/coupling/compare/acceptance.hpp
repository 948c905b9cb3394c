#pragma once
// Acceptance criteria of a surface comparison (analyses.compare.acceptance): limits on how far the SPH failure
// surface may lie from a limit-equilibrium critical surface, so that a pipeline gets "accepted or not, and why".
// Keys, units and defaults: docs/scene-format.md ("analyses.compare.acceptance"); exit status: docs/pipelines.md.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/json_reader.hpp"

namespace coupling {

// A length limit in metres, or in particle spacings of the SPH run.
struct LengthLimit {
  double value = 0.0;
  bool in_spacings = false;
  double metres(double particle_spacing) const { return in_spacings ? value * particle_spacing : value; }
};

struct AcceptanceCriteria {
  std::vector<std::string> methods;            // LE method keys the criteria apply to (default: bishop)
  std::optional<LengthLimit> entry_offset;     // distance between the SPH and LE entry points
  std::optional<LengthLimit> exit_offset;      // distance between the SPH and LE exit points
  std::optional<LengthLimit> mean_normal_distance;
  std::optional<LengthLimit> max_normal_distance;
  std::optional<double> min_overlap;           // intersection over union of the sliding masses, in [0, 1]
  std::optional<double> max_fs_difference;     // |FS of LE on the SPH surface - critical LE FS|
};

// Reads analyses.compare.acceptance (errors at "analyses.compare.acceptance.<key>"); `known_methods` are the method
// keys the scene's LE analysis computes (a criterion on another method is an error).
std::optional<AcceptanceCriteria> read_acceptance(const nlohmann::json& block, const std::vector<std::string>& known_methods,
                                                  Diagnostics& diagnostics);

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
