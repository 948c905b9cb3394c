#pragma once
// The "srm" block of report.json, written from the strength reduction's typed result (docs/report-format.md).
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/analyses/strength_reduction.hpp"

namespace coupling {

nlohmann::json srm_report(const SrmResult& result);

// The block of a strength reduction that failed before it produced a result.
nlohmann::json srm_error_report(const std::string& message);

}  // namespace coupling
