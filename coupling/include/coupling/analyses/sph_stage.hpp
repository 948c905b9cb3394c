#pragma once
// The SPH stage of the workflow: build the particle model of a scene, run it (or resume it from the run
// folder's checkpoint) with progress on the log, and report it.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "coupling/compare/failure_surface.hpp"
#include "coupling/scene/scene.hpp"
#include "sph/engine/run_loop.hpp"
#include "sph/engine/settings.hpp"

namespace coupling {

struct SphStageOptions {
  std::optional<std::filesystem::path> output_dir;  // frames, energy.csv, checkpoint.bin; none: nothing written
  bool resume = false;                              // continue from output_dir/checkpoint.bin
  std::ostream* log = nullptr;                      // plan, progress and notes (stderr in the program)
};

// The model as built: what the report states about the run before it starts.
struct SphModelFacts {
  std::size_t particles = 0, soil_particles = 0, wall_particles = 0;
  double particle_spacing_m = 0, smoothing_length_m = 0;
  sph::KernelType kernel = sph::KernelType::cubic_spline;
  sph::soil::KernelGradient kernel_gradient = sph::soil::KernelGradient::standard;  // analyses.sph.kernel_gradient
  int stress_substeps = 1;          // analyses.sph.stress_substeps
  double p_wave_speed_m_s = 0, time_step_estimate_s = 0;
  long long planned_steps = 0;
  sph::GravityMode gravity = sph::GravityMode::sudden;
  double gravity_ramp_s = 0;  // ramped gravity only
  int wall_layers = 0;
  double memory_estimate_MiB = 0;
  std::vector<std::string> loads;  // the loads besides the weight the model carries, one sentence each (units stated)
};

// Kinetic energy + plastic work against the potential energy released (when some was released).
struct SphEnergyBalance {
  double released_potential_J_m = 0, kinetic_plus_plastic_J_m = 0, ratio = 0;
};

// Extent of a particle scene's soil before and after (column collapse), in metres.
struct SphDeposit {
  double initial_length_m = 0, initial_height_m = 0, final_length_m = 0, final_height_m = 0;
};

// What the SPH stage found; coupling/output/sph_report writes it as the "sph" block of report.json.
struct SphStageResult {
  bool ok = false;               // the run reached its end (end time or quasi-static state)
  std::string error;             // why not (blow-up diagnostic, interruption, ...)
  SphModelFacts model;
  sph::RunSummary summary;
  bool energies_finite = false;  // false after a blow-up: no final energies
  std::optional<SphEnergyBalance> energy_balance;
  std::vector<std::string> warnings;  // loads left out, energy created
  bool files_written = false;         // frames.pvd, energy.csv and checkpoint.bin in the run folder
  std::optional<double> max_displacement_m, max_plastic_strain;  // none when not finite
  std::optional<SphDeposit> deposit;                              // particle scenes only
  ParticleSnapshot final_state;  // soil particles at the end, for surface extraction
};

// Throws SceneError for a case that must be refused before it starts (memory, particle or step limits).
SphStageResult run_sph_stage(const Scene& scene, const SphStageOptions& options);

// Installs a SIGINT/SIGTERM handler that asks running SPH stages to stop at the end of the current step
// (a checkpoint is written, so the run can be resumed).
void install_interrupt_handler();

// Whether SIGINT/SIGTERM arrived since the last SPH stage started (for other stages that run SPH, e.g. srm).
bool interrupt_pending();

// Callbacks of a particle run: a progress line "<prefix>: t = ... / ... s, step ..., ... left" on the log every
// progress interval (none when log is null), and the stop at the end of a step on SIGINT/SIGTERM (clears a pending
// request first).
sph::RunCallbacks run_callbacks(std::ostream* log, const char* prefix);

}  // namespace coupling
