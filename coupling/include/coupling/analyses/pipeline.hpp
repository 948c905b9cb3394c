#pragma once
// The analyses of a scene, stage after stage (coupling/analyses/stage.hpp), into typed results
// (coupling/analyses/run_results.hpp). The run folder's report.json, report.html, monitors and figures are written
// by coupling/output/run_files.hpp (run_scene, run_scene_file), which the command line and the tests call.
//
// Exit statuses (docs/pipelines.md): 0 when every requested analysis ran; 2 for invalid input (nothing written; the
// messages name the JSON path of the fault); 1 for a run that failed (report written with the reason).
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/analyses/isph_measures.hpp"
#include "coupling/analyses/run_results.hpp"
#include "coupling/scene/scene.hpp"

namespace coupling {

// 3: every analysis ran, but the comparison did not meet analyses.compare.acceptance (a run failure, 1, wins).
enum class ExitStatus : int { ok = 0, failed = 1, invalid_input = 2, not_accepted = 3 };

enum class Mode {
  check,  // validate only
  lem,    // limit equilibrium only (analyses.lem of the scene, or its defaults when absent)
  run,    // every analysis the scene asks for
};

// Draws an isph snapshot into the run folder while the run goes and returns the figure's file name relative to the
// folder (coupling/output sets it: the analyses draw nothing themselves).
using SnapshotFigure = std::function<std::string(double requested_time, const IsphSnapshot& snapshot)>;

struct WorkflowOptions {
  Mode mode = Mode::run;
  // The run folder: the runs keep their frames, checkpoints and journals there, and coupling/output writes the
  // report and figures there. None: nothing is written.
  std::optional<std::filesystem::path> output_dir;
  std::ostream* log = nullptr;  // progress and notes (stderr in the program); may be null
  bool resume = false;          // continue from output_dir/checkpoint.bin
  SnapshotFigure draw_snapshot;  // isph snapshots (analyses.isph.snapshots_s); none: not drawn
  // analyses.lem.probabilistic split over several runs (docs/pipelines.md): this run draws and analyses only its
  // part of the samples, or, with merge_samples, analyses none and takes every sample's result from the parts'
  // probabilistic_samples.csv (their run folders or the files), which must hold each sample once.
  std::optional<SamplePart> sample_part;
  std::vector<std::filesystem::path> merge_samples;
};

struct WorkflowResult {
  ExitStatus status = ExitStatus::ok;
  std::optional<Scene> scene;              // set once the scene is valid
  std::vector<std::string> errors;         // invalid input: "<json path>: ..."; failed run: the reasons
  std::vector<std::string> rejections;     // not accepted: one line per failed acceptance criterion
  RunResults results;                      // what each stage found
  // Filled by coupling/output's run_scene: report.json's content (null when the input was invalid or in check
  // mode) and where it was written.
  nlohmann::json report;
  std::optional<std::filesystem::path> report_file;
};

// Runs the stages a validated scene asks for (options.mode): typed results, no report. In check mode it only
// states whether the SPH run would be refused.
WorkflowResult run_analyses(const Scene& scene, const WorkflowOptions& options);

// Default output folder of "sphslope run": runs/<scene file stem> (relative to the working directory).
std::filesystem::path default_output_dir(const std::filesystem::path& scene_file);

}  // namespace coupling
