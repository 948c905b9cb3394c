#pragma once
// The summary files of `sphslope batch` (docs/pipelines.md), written from the rows of summary.json: one row per
// scene with its status, exit status, seconds, factors of safety, comparison figures and acceptance criteria.
#include <string>

#include <nlohmann/json.hpp>

namespace coupling {

// summary.csv: one line per scene; a column fs_<method> for every method any scene computed.
std::string summary_csv(const nlohmann::json& rows);

// JUnit XML: one test case per scene (the run) and one per acceptance criterion.
std::string junit_xml(const nlohmann::json& rows);

}  // namespace coupling
