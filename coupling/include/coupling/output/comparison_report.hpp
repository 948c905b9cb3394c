#pragma once
// The "comparison" block of report.json, written from the comparison's typed result (docs/report-format.md).
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/compare/acceptance.hpp"
#include "coupling/compare/comparison.hpp"

namespace coupling {

// The SPH surface, its displacement check, the deformed ground, the figures per LE method, the verdict and, when
// criteria were given, the acceptance block.
nlohmann::json comparison_report(const ComparisonResult& comparison);

// The block of a comparison that could not be made.
nlohmann::json comparison_error_report(const std::string& message);

// The "acceptance" block of the comparison.
nlohmann::json acceptance_json(const AcceptanceResult& result);

}  // namespace coupling
