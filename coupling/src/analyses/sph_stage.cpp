#include "coupling/analyses/sph_stage.hpp"
#include "coupling/analyses/tank_monitors.hpp"

#include <exception>

#include "coupling/analyses/stage.hpp"

#include <algorithm>
#include <atomic>
#include <functional>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <ostream>

#include "coupling/scene/json_reader.hpp"
#include "coupling/analyses/sph_model.hpp"
#include "sph/soil/checkpoint.hpp"
#include "sph/soil/run.hpp"

namespace coupling {

namespace {

volatile std::sig_atomic_t interrupt_requested = 0;

extern "C" void on_interrupt(int) { interrupt_requested = 1; }

std::string duration_text(double seconds) {
  char buffer[64];
  if (!std::isfinite(seconds)) return "?";
  if (seconds < 120.0) {
    std::snprintf(buffer, sizeof buffer, "%.0f s", seconds);
  } else if (seconds < 7200.0) {
    std::snprintf(buffer, sizeof buffer, "%.1f min", seconds / 60.0);
  } else {
    std::snprintf(buffer, sizeof buffer, "%.1f h", seconds / 3600.0);
  }
  return buffer;
}

// Extent of the soil before and after, for particle scenes (column collapse): the front is the farthest particle
// still in contact with the deposit (a gap wider than 1.5 spacings separates stray particles).
SphDeposit deposit_of(const ParticleSnapshot& p) {
  auto front = [&](const std::vector<double>& xs) { return farthest_in_contact(xs, 1.5 * p.spacing); };
  const double x_min0 = *std::min_element(p.x0.begin(), p.x0.end());
  const double y_min0 = *std::min_element(p.y0.begin(), p.y0.end());
  SphDeposit d;
  d.initial_length_m = front(p.x0) - x_min0 + p.spacing;
  d.initial_height_m = *std::max_element(p.y0.begin(), p.y0.end()) - y_min0 + p.spacing;
  d.final_length_m = front(p.x) - x_min0 + p.spacing;
  d.final_height_m = *std::max_element(p.y.begin(), p.y.end()) - y_min0 + p.spacing;
  return d;
}

}  // namespace

void install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

bool interrupt_pending() { return interrupt_requested != 0; }

sph::RunCallbacks run_callbacks(std::ostream* log, const char* prefix) {
  sph::RunCallbacks callbacks;
  if (log) {
    callbacks.progress = [log, prefix](const sph::Progress& p) {
      char line[200];
      std::snprintf(line, sizeof line, "%s: t = %.4g / %.4g s, step %llu, %.0f steps/s, dt %.3g s, max speed %.3g m/s, %s left\n",
                    prefix, p.time, p.end_time, static_cast<unsigned long long>(p.step), p.steps_per_second, p.time_step,
                    p.max_speed, duration_text(p.eta_seconds).c_str());
      *log << line << std::flush;
    };
  }
  interrupt_requested = 0;
  callbacks.interrupt = [] { return interrupt_requested != 0; };
  return callbacks;
}

namespace {

// Plan before allocating anything: the explicit step is bounded by the P-wave speed; a case that needs more
// steps, particles or memory than its limits is refused here, with the planned figures in the message.
void refuse_before_start(const Scene& scene, const SphAnalysis& analysis) {
  if (const auto plan = plan_sph(scene, analysis)) {
    const std::vector<std::string> refusals = sph_refusals(analysis, *plan);
    if (!refusals.empty()) throw SceneError(refusals);
  }
}

// The model's size, kernel, wave speed, time step and gravity, and the plan on the log.
// The loads of the model besides its weight, one sentence each, so that a reader of the report can check them.
std::vector<std::string> loads_carried(const sph::soil::Model& model) {
  std::vector<std::string> out;
  const sph::soil::SoilLoads& loads = model.loads;
  if (loads.water)
    out.push_back("pore water below the piezometric line (gamma_w = " +
                  format_number(loads.water->unit_weight / 1000.0) +
                  " kN/m3): effective stress, ponded water included");
  if (loads.seismic_coefficient != 0.0)
    out.push_back("pseudo-static k_h = " + format_number(std::fabs(loads.seismic_coefficient)) + " toward " +
                  (loads.seismic_coefficient > 0 ? "+x" : "-x"));
  if (loads.vertical_seismic_coefficient != 0.0)
    out.push_back("pseudo-static k_v = " + format_number(std::fabs(loads.vertical_seismic_coefficient)) + " " +
                  (loads.vertical_seismic_coefficient > 0 ? "upward" : "downward"));
  if (loads.surface_force_y) {
    const auto& fx = model.particles.field(*loads.surface_force_x);
    const auto& fy = model.particles.field(*loads.surface_force_y);
    double down = 0.0, across = 0.0;
    std::size_t loaded = 0;
    for (std::size_t i = 0; i < fy.size(); ++i) {
      down -= fy[i];
      across += fx[i];
      if (fy[i] != 0.0 || fx[i] != 0.0) ++loaded;
    }
    std::string text = "surcharges: " + format_number(down / 1000.0) + " kN/m downward";
    if (across != 0.0) text += " and " + format_number(across / 1000.0) + " kN/m toward +x";
    out.push_back(text + " on " + std::to_string(loaded) + " particles under the strips and line loads");
  }
  return out;
}

SphModelFacts model_facts(const sph::soil::Model& model, const SphSize& size, const SphAnalysis& analysis,
                          std::ostream* log) {
  SphModelFacts f;
  for (const auto& m : model.materials)
    f.p_wave_speed_m_s = std::max(f.p_wave_speed_m_s, sph::soil::MaterialConstants::from(m).sound_speed);
  f.smoothing_length_m = model.settings.smoothing_length();
  f.time_step_estimate_s = sph::soil::time_step_estimate(model);
  const double planned_steps = model.settings.end_time / f.time_step_estimate_s;
  f.planned_steps = std::llround(planned_steps);
  f.particles = model.particles.size();
  f.soil_particles = size.soil_particles;
  f.wall_particles = size.wall_particles;
  f.particle_spacing_m = model.settings.particle_spacing;
  f.kernel = model.settings.kernel;
  f.kernel_gradient = model.settings.kernel_gradient;
  f.stress_substeps = model.settings.stress_substeps;
  f.gravity = model.settings.gravity_mode;
  f.gravity_ramp_s = model.settings.gravity_ramp_time;
  f.wall_layers = analysis.wall_layers;
  f.memory_estimate_MiB = static_cast<double>(size.memory_bytes) / (1024.0 * 1024.0);
  f.loads = loads_carried(model);
  if (log) {
    for (const auto& load : f.loads) *log << "sph: load: " << load << "\n";
    *log << "sph: " << size.soil_particles << " soil + " << size.wall_particles << " wall particles, dx = "
         << model.settings.particle_spacing << " m, h = " << f.smoothing_length_m << " m, P-wave speed "
         << f.p_wave_speed_m_s << " m/s, time step about " << f.time_step_estimate_s << " s: about "
         << f.planned_steps << " steps for " << model.settings.end_time << " s\n";
  }
  return f;
}

// --resume: the model continues from the run folder's checkpoint.
void resume_from_checkpoint(const SphStageOptions& options, sph::soil::Model& model) {
  if (!options.output_dir) throw SceneError({"--resume needs the run folder (-o DIR) that holds checkpoint.bin"});
  const auto checkpoint = *options.output_dir / "checkpoint.bin";
  if (!std::filesystem::exists(checkpoint))
    throw SceneError({"--resume: no checkpoint at " + checkpoint.string() + " (start the run without --resume)"});
  sph::soil::read_checkpoint(checkpoint.string(), model);
  if (options.log)
    *options.log << "sph: resuming at t = " << model.state.time << " s (step " << model.state.step << ")\n";
}

sph::RunOptions run_options_of(const SphAnalysis& analysis, const SphStageOptions& options) {
  sph::RunOptions run_options;
  if (options.output_dir) run_options.output_dir = options.output_dir->string();
  run_options.quasi_static_speed = analysis.quasi_static_speed;
  run_options.quasi_static_min_time = analysis.quasi_static_min_time;
  run_options.progress_interval_wall_s = 2.0;
  return run_options;
}


// Final energies and the energy balance, and the warnings of the run (loads left out, energy created).
void check_energies(const Scene& scene, const sph::soil::Model& model, SphStageResult& result) {
  const sph::RunSummary& summary = result.summary;
  result.energies_finite = std::isfinite(summary.kinetic_energy) && std::isfinite(summary.potential_energy) &&
                           std::isfinite(summary.plastic_dissipation);
  // Energy balance: kinetic energy + plastic work cannot exceed the potential energy released (elastic energy and
  // viscous losses are >= 0; with ramped gravity the work of gravity is smaller still). More means the scheme
  // created energy. Not applicable with a K0 initial stress, whose stored elastic energy is released as well.
  const double released = model.state.initial_potential_energy - summary.potential_energy;
  for (const SectionLoad& load : loads_sph_leaves_out(scene))
    result.warnings.push_back(load.path + " is not carried by the SPH model (" + load.why + "): this SPH result is "
                              "for the slope without " + load.name + ", unlike the limit-equilibrium result");
  if (result.energies_finite && released > 0.0) {
    const double work = summary.kinetic_energy + summary.plastic_dissipation;
    const double ratio = work / released;
    result.energy_balance = SphEnergyBalance{released, work, ratio};
    if (ratio > 1.05 && model.settings.gravity_mode != sph::GravityMode::geostatic_k0)
      result.warnings.push_back("kinetic energy + plastic work = " + format_number(ratio) +
                                " x the potential energy released: the scheme created energy (time step too large "
                                "for the material, artificial viscosity too low?); treat the result as unreliable");
  }
}

// Whether the run reached its end; if not, why (in result.error and the report).
void judge_run(SphStageResult& result) {
  const sph::RunSummary& summary = result.summary;
  result.ok = summary.stopped_because == "end_time" || summary.stopped_because == "quasi_static";
  if (!result.ok) {
    result.error = summary.stopped_because == "interrupted"
                       ? "the SPH run was interrupted at t = " + format_number(summary.simulated_time) +
                             " s; continue it with --resume"
                       : "the SPH run stopped (" + summary.stopped_because + "): " + summary.diagnostic;
  }
}

// The soil particles at the end, for surface extraction.
ParticleSnapshot soil_snapshot(const sph::soil::Model& model) {
  const auto& p = model.particles;
  const sph::soil::ConstSoilArrays soil = model.soil();
  ParticleSnapshot snapshot;
  snapshot.spacing = model.settings.particle_spacing;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != static_cast<std::uint8_t>(sph::ParticleKind::material)) continue;
    snapshot.x.push_back(p.x[i]);
    snapshot.y.push_back(p.y[i]);
    snapshot.x0.push_back(p.x0[i]);
    snapshot.y0.push_back(p.y0[i]);
    snapshot.plastic_strain.push_back(soil.plastic_strain[i]);
    snapshot.stress_xx.push_back(soil.sxx[i]);
    snapshot.stress_yy.push_back(soil.syy[i]);
  }
  return snapshot;
}

// Largest displacement and accumulated plastic strain of any soil particle at the end (none if not finite), and
// the deposit of a particle scene.
void final_state_extremes(const Scene& scene, SphStageResult& result) {
  const ParticleSnapshot& snapshot = result.final_state;
  double max_displacement = 0.0, max_plastic_strain = 0.0;
  bool finite = true;
  for (std::size_t i = 0; i < snapshot.x.size(); ++i) {
    const double u = std::hypot(snapshot.x[i] - snapshot.x0[i], snapshot.y[i] - snapshot.y0[i]);
    finite = finite && std::isfinite(u) && std::isfinite(snapshot.plastic_strain[i]);
    max_displacement = std::max(max_displacement, u);
    max_plastic_strain = std::max(max_plastic_strain, snapshot.plastic_strain[i]);
  }
  if (finite) {
    result.max_displacement_m = max_displacement;
    result.max_plastic_strain = max_plastic_strain;
  }
  if (scene.bodies && !snapshot.x.empty()) result.deposit = deposit_of(snapshot);
}

}  // namespace

SphStageResult run_sph_stage(const Scene& scene, const SphStageOptions& options) {
  const SphAnalysis& analysis = *scene.analyses.sph;
  refuse_before_start(scene, analysis);
  SphSize size;
  sph::soil::Model model = build_sph_model(scene, &size);

  SphStageResult result;
  result.model = model_facts(model, size, analysis, options.log);
  const sph::RunOptions run_options = run_options_of(analysis, options);
  if (options.resume) resume_from_checkpoint(options, model);

  result.summary = sph::soil::run(model, run_options, run_callbacks(options.log, "sph"));
  check_energies(scene, model, result);
  if (options.log)
    for (const auto& w : result.warnings) *options.log << "sph: warning: " << w << "\n";
  result.files_written = options.output_dir.has_value();
  judge_run(result);

  result.final_state = soil_snapshot(model);
  final_state_extremes(scene, result);
  return result;
}

// The "sph" stage of the pipeline: runs the SPH analysis and hands its final particle state to the comparison.
StageOutcome run_sph_analysis_stage(const Scene& scene, StageContext& context) {
  const WorkflowOptions& options = context.options;
  RunResults& results = context.results;
  StageRecord<SphStageResult>& record = results.sph.emplace();
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  SphStageOptions sph_options;
  sph_options.output_dir = options.output_dir;
  sph_options.resume = options.resume;
  sph_options.log = options.log;
  SphStageResult result;
  try {
    result = run_sph_stage(scene, sph_options);
  } catch (const SceneError& error) {
    // Refused before it started (memory, particle or step limits; nothing to resume): a fault of the input.
    outcome.status = ExitStatus::invalid_input;
    outcome.errors = error.messages();
    return outcome;
  } catch (const std::exception& error) {
    outcome.fail(std::string("sph: ") + error.what(), record.error);
    results.seconds["sph"] = seconds_since(start);
    return outcome;
  }
  results.seconds["sph"] = seconds_since(start);
  if (!result.ok) {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back("sph: " + result.error);
  }
  // After a blow-up the particle state is the diverged one (non-finite or meaningless values): no comparison or
  // figure is drawn from it (the last good frame is in frames/).
  if (result.summary.reason != sph::StopReason::blow_up) results.sph_final_state = std::move(result.final_state);
  record.result = std::move(result);
  return outcome;
}

}  // namespace coupling
