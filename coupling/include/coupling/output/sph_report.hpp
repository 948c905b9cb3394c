#pragma once
// The "sph" block of report.json, written from the SPH stage's typed result (docs/report-format.md).
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/analyses/sph_stage.hpp"

namespace coupling {

nlohmann::json sph_report(const SphStageResult& result);

// The block of a stage that failed before it produced a result.
nlohmann::json sph_error_report(const std::string& message);

}  // namespace coupling
