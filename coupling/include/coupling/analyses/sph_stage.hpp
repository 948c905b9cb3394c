#pragma once
// The SPH stage of the workflow: build the particle model of a scene, run it (or resume it from the run
// folder's checkpoint) with progress on the log, and report it.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/compare/failure_surface.hpp"
#include "coupling/scene/scene.hpp"

namespace coupling {

struct SphStageOptions {
  std::optional<std::filesystem::path> output_dir;  // frames, energy.csv, checkpoint.bin; none: nothing written
  bool resume = false;                              // continue from output_dir/checkpoint.bin
  std::ostream* log = nullptr;                      // plan, progress and notes (stderr in the program)
};

struct SphStageResult {
  bool ok = false;               // the run reached its end (end time or quasi-static state)
  std::string error;             // why not (blow-up diagnostic, interruption, ...)
  nlohmann::json report;         // the "sph" block of report.json
  ParticleSnapshot final_state;  // soil particles at the end, for surface extraction
};

// Throws SceneError for a case that must be refused before it starts (memory, particle or step limits).
SphStageResult run_sph_stage(const Scene& scene, const SphStageOptions& options);

// Installs a SIGINT/SIGTERM handler that asks running SPH stages to stop at the end of the current step
// (a checkpoint is written, so the run can be resumed).
void install_interrupt_handler();

// Whether SIGINT/SIGTERM arrived since the last SPH stage started (for other stages that run SPH, e.g. srm).
bool interrupt_pending();

}  // namespace coupling
