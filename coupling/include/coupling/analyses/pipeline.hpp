#pragma once
// The workflow behind the sphslope program: scene -> analyses -> report.json. main.cpp only parses the command
// line and prints; tests call these functions directly.
//
// Exit statuses (SCENE.md): 0 when every requested analysis ran; 2 for invalid input (nothing written; the
// messages name the JSON path of the fault); 1 for a run that failed (report written with the reason).
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/compare/failure_surface.hpp"
#include "coupling/scene/scene.hpp"
#include "slope/search.hpp"

namespace coupling {

// 3: every analysis ran, but the comparison did not meet analyses.compare.acceptance (a run failure, 1, wins).
enum class ExitStatus : int { ok = 0, failed = 1, invalid_input = 2, not_accepted = 3 };

enum class Mode {
  check,  // validate only
  lem,    // limit equilibrium only (analyses.lem of the scene, or its defaults when absent)
  run,    // every analysis the scene asks for
};

struct WorkflowOptions {
  Mode mode = Mode::run;
  std::optional<std::filesystem::path> output_dir;  // report.json goes here; none: nothing is written
  std::ostream* log = nullptr;                      // progress and notes (stderr in the program); may be null
  bool resume = false;                              // SPH: continue from output_dir/checkpoint.bin
};

// A slip surface given in the scene (analyses.lem.surfaces), analysed with every method asked for.
struct GivenSurfaceResult {
  std::string name;
  std::vector<slope::CriticalSurface> methods;  // in the order asked for, each with the mass and its forces
};

// Slices each surface of analysis.surfaces and solves it with every method of the analysis.
std::vector<GivenSurfaceResult> analyse_given_surfaces(const slope::Section& section, const LemAnalysis& analysis);

struct WorkflowResult {
  ExitStatus status = ExitStatus::ok;
  std::optional<Scene> scene;                     // set once the scene is valid
  std::vector<std::string> errors;                // invalid input: "<json path>: ..."; failed run: the reasons
  std::vector<std::string> rejections;            // not accepted: one line per failed acceptance criterion
  nlohmann::json report;                          // null when the input was invalid or in check mode
  std::optional<slope::SearchResult> lem;         // the limit-equilibrium result, for the table
  std::optional<slope::NonCircularResult> lem_noncircular;  // analyses.lem.noncircular_search, when asked for
  std::vector<GivenSurfaceResult> lem_surfaces;   // the given slip surfaces (analyses.lem.surfaces), for the table
  std::optional<std::filesystem::path> report_file;  // where report.json was written
  std::optional<ParticleSnapshot> sph_final_state;   // soil particles at the end of the SPH analysis
};

// Loads and validates the scene file, then runs what `options.mode` asks for.
WorkflowResult run_scene_file(const std::filesystem::path& scene_file, const WorkflowOptions& options);

// Runs an already validated scene.
WorkflowResult run_scene(const Scene& scene, const WorkflowOptions& options);

// Default output folder of "sphslope run": runs/<scene file stem> (relative to the working directory).
std::filesystem::path default_output_dir(const std::filesystem::path& scene_file);

}  // namespace coupling
