#pragma once
// The "coupled" block of report.json, from the typed result of the coupled stage (coupling/analyses/coupled_stage.hpp).
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/analyses/coupled_stage.hpp"

namespace coupling {

nlohmann::json coupled_report(const CoupledStageResult& result);
nlohmann::json coupled_error_report(const std::string& error);

}  // namespace coupling
