#pragma once
// A run of a scene and its run folder: the analyses (coupling/analyses/pipeline.hpp) into typed results, then, from
// those alone, report.json, report.html, the figures, monitors.csv and the profiles. The command line, the batch's
// runs and the tests call these.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "coupling/analyses/pipeline.hpp"

namespace coupling {

// Runs what options.mode asks for on a validated scene; with options.output_dir, writes the run folder. The
// result carries the report's content (null for invalid input and check mode) and where it was written.
WorkflowResult run_scene(const Scene& scene, const WorkflowOptions& options);

// Loads and validates the scene file (invalid input: status 2, the messages, nothing written), then run_scene.
WorkflowResult run_scene_file(const std::filesystem::path& scene_file, const WorkflowOptions& options);

// report.json's content from a run's typed results (figures: the names of the figures written, relative to the
// run folder; none when nothing was drawn).
nlohmann::json run_report(const Scene& scene, const RunResults& results, const std::vector<std::string>* figures);

}  // namespace coupling
