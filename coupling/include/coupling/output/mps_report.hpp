#pragma once
// The "mps" block of report.json, from the typed result of the mps stage (coupling/analyses/mps_stage.hpp;
// docs/scene-format.md, report "mps").
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/analyses/mps_stage.hpp"

namespace coupling {

nlohmann::json mps_report(const MpsStageResult& result);
nlohmann::json mps_error_report(const std::string& error);

}  // namespace coupling
