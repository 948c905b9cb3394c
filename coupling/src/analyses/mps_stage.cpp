// The "mps" stage: the weakly compressible MPS (analyses.mps, docs/mps.md) in a tank, with its monitors (surface
// gauges, the front, the height at the left wall) and profiles; coupling/output/mps_report writes its monitors.csv,
// profiles and report block.
#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <ostream>
#include <string>
#include <vector>

#include "coupling/analyses/sph_stage.hpp"
#include "coupling/analyses/mps_profiles.hpp"
#include "coupling/analyses/stage.hpp"
#include "coupling/analyses/tank_monitors.hpp"
#include "coupling/analyses/tank_run.hpp"
#include "coupling/analyses/mps_stage.hpp"
#include "sph/engine/atomic_file.hpp"
#include "sph/mps/run.hpp"

namespace coupling {

namespace {

sph::mps::Model build_mps_model(const MpsAnalysis& a) {
  std::vector<sph::mps::Material> materials;
  for (const MpsMaterial& m : a.materials) materials.push_back(m.material);
  sph::mps::Model model(a.settings, std::move(materials));
  for (std::size_t k = 0; k < a.blocks.size(); ++k) {
    const TankRectangle& b = a.blocks[k];
    sph::mps::add_block(model, b.x_min, b.y_min, b.x_max, b.y_max, a.block_material[k]);
  }
  // the walls' material index only labels them (their viscosity is never used)
  sph::mps::add_box(model, a.tank.x_min, a.tank.x_max, a.tank.y_min, a.tank.height, 0);
  if (a.gate_x) sph::mps::add_gate(model, *a.gate_x, a.tank.y_min, a.tank.height, 0);
  return model;
}

double moving_mass(const sph::ParticleSet& p) { return p.total_mass(sph::ParticleKind::material); }  // kind 0

// The mass of the moving particles of material m inside the tank (its walls' inner faces, up to any height).
double phase_mass_in_tank(const sph::ParticleSet& p, std::uint16_t m, const Tank& tank) {
  double mass = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == 0 && p.material[i] == m && p.x[i] > tank.x_min && p.x[i] < tank.x_max && p.y[i] > tank.y_min)
      mass += p.mass[i];
  return mass;
}

std::vector<std::uint8_t> granular_flags(const MpsAnalysis& a) {
  std::vector<std::uint8_t> out;
  for (const MpsMaterial& m : a.materials)
    out.push_back(m.material.type == sph::mps::Material::Type::granular ? 1 : 0);
  return out;
}

double max_speed(const sph::ParticleSet& p) {
  double v = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == 0) v = std::max(v, std::hypot(p.vx[i], p.vy[i]));
  return v;
}

// A block fewer than r_e/dx particles across (its width or its height): every particle's r_e reaches past both of
// its faces, so no particle has a full neighbourhood and the operators are truncated throughout.
std::vector<std::string> thin_block_warnings(const MpsAnalysis& a) {
  std::vector<std::string> out;
  const double dx = a.settings.particle_spacing, across_needed = a.settings.re_over_dx;
  for (std::size_t k = 0; k < a.blocks.size(); ++k) {
    const TankRectangle& b = a.blocks[k];
    const double across = std::min(b.x_max - b.x_min, b.y_max - b.y_min) / dx;
    if (across >= across_needed) continue;
    out.push_back("analyses.mps.blocks[" + std::to_string(k) + "]: " + format_number(std::floor(across + 1e-9)) +
                  " particles across, fewer than re_over_dx = " + format_number(across_needed) +
                  ": every particle's r_e reaches past both faces of the block, no particle has a full "
                  "neighbourhood and the results are crude; use a smaller particle_spacing_m");
  }
  return out;
}

// --resume: the model continues from the run folder's checkpoint (the monitors keep their earlier rows); returns
// the largest speed of the run before it, from the earlier report.json.
double resume_mps(const WorkflowOptions& options, sph::mps::Model& model, TankMonitorObserver& monitors) {
  const std::optional<ReportRecord> earlier = resume_tank_run(
      options, "mps", [&model](const std::string& path) { sph::mps::read_checkpoint(path, model); }, model.state,
      monitors);
  return earlier && earlier->mps ? earlier->mps->max_speed : 0.0;
}

// The settings the report echoes.
void echo_settings(const MpsAnalysis& a, MpsStageResult& result) {
  result.regularisation = sph::mps::regularisation_key(a.settings.regularisation);
  result.interaction_viscosity = sph::mps::interaction_viscosity_key(a.settings.interaction_viscosity);
  result.effective_pressure = sph::mps::effective_pressure_key(a.settings.effective_pressure);
  result.stress_divergence = sph::mps::stress_divergence_key(a.settings.stress_divergence);
  result.particle_spacing = a.settings.particle_spacing;
  result.effective_radius = a.settings.effective_radius();
  result.sound_speed = a.settings.sound_speed;
  result.viscosity_cap = a.settings.viscosity_cap;
  result.gate = a.gate_x.has_value();
  result.gate_x = a.gate_x.value_or(0.0);
  result.gate_lift_speed = a.settings.gate_lift_speed;
  result.gate_lift_distance = a.settings.gate_lift_distance;
  result.pore_pressure = sph::mps::pore_pressure_key(a.settings.pore_pressure);
}

MpsStageResult run_mps(const MpsAnalysis& a, const WorkflowOptions& options) {
  sph::mps::Model model = build_mps_model(a);
  const double dx = a.settings.particle_spacing;
  MpsStageResult result;
  echo_settings(a, result);
  result.moving_particles = model.particles.count(sph::ParticleKind::material);
  result.wall_particles = model.particles.size() - result.moving_particles;
  result.mass_start = moving_mass(model.particles);
  for (std::uint16_t m = 0; m < a.materials.size(); ++m)
    result.phases.push_back({a.materials[m].name, model.density_of(m), phase_mass_in_tank(model.particles, m, a.tank),
                             0.0});
  const std::vector<std::uint8_t> granular = granular_flags(a);
  ProfileObserver profiles(a.profile_times, a.tank, dx, granular);
  const Profile start_profile = measure_profile(model.particles, a.tank, dx, granular, 0.0);
  const double wall_x = a.tank.x_min + 0.5 * dx;  // the centres of the lattice column against the left wall
  result.front_start = contact_front(model.particles, dx);
  result.wall_height_start = surface_at(model.particles, wall_x, dx, a.tank.y_min) - a.tank.y_min;
  TankMonitorObserver monitors(a.monitors, a.tank, dx);
  monitors.sample(model.particles, 0.0);
  double fastest = options.resume ? resume_mps(options, model, monitors) : 0.0;
  if (options.resume) {
    std::ifstream csv(*options.output_dir / "profiles.csv");
    profiles.restore(std::string(std::istreambuf_iterator<char>(csv), {}), model.state.time);
  }
  sph::RunOptions run_options;
  if (options.output_dir) run_options.output_dir = options.output_dir->string();
  run_options.progress_interval_wall_s = 2.0;
  sph::RunCallbacks callbacks = run_callbacks(options.log, "mps");
  callbacks.observers.push_back(&monitors);
  callbacks.observers.push_back(&profiles);
  result.summary = sph::mps::run(model, run_options, callbacks, [&](const sph::mps::Step&, const sph::RunState&) {
    fastest = std::max(fastest, max_speed(model.particles));
  });
  result.max_speed_run = fastest;
  result.warnings = thin_block_warnings(a);
  const std::string sound = sph::mps::sound_speed_problem(a.settings.sound_speed, fastest);
  if (!sound.empty()) result.warnings.push_back("analyses.mps.sound_speed_m_s: " + sound);
  if (monitors.table().times.back() < model.state.time) monitors.sample(model.particles, model.state.time);
  result.mass_end = moving_mass(model.particles);
  result.front_end = contact_front(model.particles, dx);
  result.wall_height_end = surface_at(model.particles, wall_x, dx, a.tank.y_min) - a.tank.y_min;
  result.max_speed_end = max_speed(model.particles);
  result.monitors = std::move(monitors.table());
  for (std::uint16_t m = 0; m < a.materials.size(); ++m)
    result.phases[m].mass_end = phase_mass_in_tank(model.particles, m, a.tank);
  result.profiles = profiles.profiles();
  result.dam_x = a.dam_x;
  if (a.dam_x)
    for (const Profile& p : result.profiles)
      result.dam_break.push_back(dam_break_figures(start_profile, p, *a.dam_x, dx, std::abs(a.settings.gravity_y)));
  return result;
}

}  // namespace

StageOutcome run_mps_stage(const Scene& scene, StageContext& context) {
  const WorkflowOptions& options = context.options;
  RunResults& results = context.results;
  StageRecord<MpsStageResult>& record = results.mps.emplace();
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  try {
    MpsStageResult result = run_mps(*scene.analyses.mps, options);
    tank_run_outcome(result.summary, "mps", outcome);
    if (options.log) {
      *options.log << "mps: " << result.moving_particles << " particles, " << result.summary.steps
                   << " steps to t = " << result.summary.simulated_time << " s; front x = " << result.front_end
                   << " m, height at the left wall " << result.wall_height_end << " m\n";
      for (const std::string& w : result.warnings) *options.log << "mps: warning: " << w << "\n";
    }
    record.result = std::move(result);
  } catch (const std::exception& error) {
    outcome.fail(std::string("mps: ") + error.what(), record.error);
  }
  results.seconds["mps"] = seconds_since(start);
  return outcome;
}

}  // namespace coupling
