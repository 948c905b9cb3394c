#pragma once
// The "isph" block of report.json, from the typed result of the isph stage (coupling/analyses/isph_stage.hpp).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/analyses/isph_stage.hpp"

namespace coupling {

nlohmann::json isph_report(const IsphStageResult& result);
nlohmann::json isph_error_report(const std::string& error);

}  // namespace coupling
