// The "coupled" stage: the soil of analyses.sph (the top-level bodies) and the water of analyses.isph in one run
// (sph/coupled, docs/coupled.md), with the water's monitors, progress, Ctrl-C and --resume from the run folder's
// checkpoint. coupling/output/coupled_report writes its report block; run_files.cpp its monitors.csv and figure.
#include "coupling/analyses/coupled_stage.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <iterator>
#include <limits>
#include <ostream>
#include <unordered_map>

#include "coupling/analyses/coupled_impact.hpp"
#include "coupling/analyses/isph_stage.hpp"
#include "coupling/analyses/sph_model.hpp"
#include "coupling/analyses/sph_stage.hpp"
#include "coupling/analyses/stage.hpp"
#include "coupling/analyses/tank_monitors.hpp"
#include "coupling/analyses/tank_run.hpp"
#include "sph/coupled/model.hpp"
#include "sph/engine/fill.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

constexpr auto kMaterial = static_cast<std::uint8_t>(sph::ParticleKind::material);

// The water's solids as the soil's walls too (rows parallel to their faces, normals out of them), with the soil
// cleared from them as the water is: no soil particle inside a solid or closer than dx/2 to its faces.
void add_solids_to_soil(const IsphAnalysis& water, const SphAnalysis& analysis, sph::soil::Model& soil) {
  if (water.solids.empty()) return;
  const double dx = soil.settings.particle_spacing, clearance = 0.5 * dx * (1.0 - 1e-9);
  sph::ParticleSet& p = soil.particles;
  std::vector<std::uint8_t> drop(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (const IsphSolid& solid : water.solids)
      if (p.kind[i] == kMaterial && (sph::point_in_polygon(solid.polygon, p.x[i], p.y[i]) ||
                                     sph::distance_to_polygon_edges(solid.polygon, p.x[i], p.y[i]) < clearance))
        drop[i] = 1;
  p.remove(drop);
  for (const IsphSolid& solid : water.solids)
    sph::add_polygon_walls(p, solid.polygon, dx, soil.settings.smoothing_length(), analysis.wall_layers, 0,
                           soil.materials.front().density);
}

sph::coupled::Model build_coupled_model(const Scene& scene) {
  std::vector<std::vector<sph::Point>> soil;
  for (const ParticleBody& body : *scene.bodies) {
    soil.emplace_back();
    for (const auto& p : body.polygon) soil.back().push_back({p.x, p.y});
  }
  sph::soil::Model soil_model = build_sph_model(scene);
  add_solids_to_soil(*scene.analyses.isph, *scene.analyses.sph, soil_model);
  return sph::coupled::Model(std::move(soil_model), build_isph_model(*scene.analyses.isph, soil));
}

// Water particles whose centre lies closer than dx/2 to a soil particle's: inside the soil.
std::size_t water_inside_soil(const sph::ParticleSet& soil, const sph::ParticleSet& water, double dx) {
  auto key = [dx](double x, double y) {
    return (static_cast<long long>(std::floor(x / dx)) << 32) ^ (static_cast<long long>(std::floor(y / dx)) & 0xffffffffLL);
  };
  std::unordered_multimap<long long, std::size_t> cells;
  for (std::size_t i = 0; i < soil.size(); ++i)
    if (soil.kind[i] == kMaterial) cells.emplace(key(soil.x[i], soil.y[i]), i);
  std::size_t inside = 0;
  for (std::size_t k = 0; k < water.size(); ++k) {
    if (water.kind[k] != kMaterial) continue;
    bool hit = false;
    for (int cx = -1; cx <= 1 && !hit; ++cx)
      for (int cy = -1; cy <= 1 && !hit; ++cy) {
        const auto range = cells.equal_range(key(water.x[k] + cx * dx, water.y[k] + cy * dx));
        for (auto it = range.first; it != range.second && !hit; ++it)
          hit = std::hypot(water.x[k] - soil.x[it->second], water.y[k] - soil.y[it->second]) < 0.5 * dx;
      }
    inside += hit;
  }
  return inside;
}

void soil_measures(const sph::soil::Model& soil, CoupledStageResult& r) {
  const auto sa = soil.soil();
  const sph::ParticleSet& p = soil.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != kMaterial) continue;
    r.soil_max_displacement = std::max(r.soil_max_displacement, std::hypot(p.x[i] - p.x0[i], p.y[i] - p.y0[i]));
    r.soil_max_plastic_strain = std::max(r.soil_max_plastic_strain, sa.plastic_strain[i]);
  }
  r.soil_mass_end = p.total_mass(sph::ParticleKind::material);
}

// The soil's centroid (mass-weighted) and the speed of its mean velocity, sampled on the monitors' interval grid at
// t = 0, at the first step at or after each multiple and at the end: slide.csv.
class SlideObserver : public sph::Observer {
 public:
  // With a ramp angle (analyses.coupled.impact), also the slide's largest thickness normal to the ramp.
  SlideObserver(const sph::soil::Model& soil, double interval, std::optional<double> ramp_angle_deg)
      : soil_(soil), interval_(interval), ramp_angle_(ramp_angle_deg) {
    table_.columns = {"centroid_x_m", "centroid_y_m", "centroid_speed_m_s"};
    if (ramp_angle_) table_.columns.push_back(slide_thickness_column);
  }
  std::string after_step(const sph::ParticleSet&, const sph::RunState& state, const sph::Energies&) override {
    if (state.time + 1e-12 >= next_) sample(state.time);
    return {};
  }
  void sample(double time) {
    const sph::ParticleSet& p = soil_.particles;
    double mass = 0, x = 0, y = 0, vx = 0, vy = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.kind[i] != kMaterial) continue;
      mass += p.mass[i];
      x += p.mass[i] * p.x[i];
      y += p.mass[i] * p.y[i];
      vx += p.mass[i] * p.vx[i];
      vy += p.mass[i] * p.vy[i];
    }
    table_.times.push_back(time);
    table_.rows.push_back({x / mass, y / mass, std::hypot(vx, vy) / mass});
    if (ramp_angle_) table_.rows.back().push_back(thickness_normal_to_ramp());
    next_ = (std::floor(time / interval_ + 1e-9) + 1.0) * interval_;
  }
  void restore(const std::string& csv, double time) {
    if (restore_rows(table_, csv, time)) next_ = (std::floor(table_.times.back() / interval_ + 1e-9) + 1.0) * interval_;
  }
  MonitorTable& table() { return table_; }

 private:
  // The soil in strips 2 dx wide along the ramp (direction (cos a, -sin a)): the largest extent of a strip normal to
  // the ramp, plus dx (a particle's own width) [m].
  double thickness_normal_to_ramp() const {
    const sph::ParticleSet& p = soil_.particles;
    const double a = *ramp_angle_ * sphslope::degree, dx = soil_.settings.particle_spacing;
    std::unordered_map<long, std::pair<double, double>> strips;  // strip -> lowest, highest normal coordinate
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.kind[i] != kMaterial) continue;
      const double along = p.x[i] * std::cos(a) - p.y[i] * std::sin(a), normal = p.x[i] * std::sin(a) + p.y[i] * std::cos(a);
      const auto key = static_cast<long>(std::floor(along / (2 * dx)));
      auto [it, fresh] = strips.try_emplace(key, normal, normal);
      if (!fresh) it->second = {std::min(it->second.first, normal), std::max(it->second.second, normal)};
    }
    double thickest = 0;
    for (const auto& [key, range] : strips) thickest = std::max(thickest, range.second - range.first + dx);
    return thickest;
  }

  const sph::soil::Model& soil_;
  double interval_;
  std::optional<double> ramp_angle_;
  MonitorTable table_;
  double next_ = 0;
};

// What the run says beyond its numbers.
std::vector<std::string> coupled_warnings(const CoupledStageResult& r) {
  std::vector<std::string> out;
  if (r.water_inside_soil > 0)
    out.push_back("analyses.coupled: " + std::to_string(r.water_inside_soil) +
                  " water particles ended closer than dx/2 to a soil particle (inside the soil): the interface did "
                  "not hold the water out there (docs/coupled.md)");
  if (r.water_removed > 0)
    out.push_back("analyses.isph.tank: " + std::to_string(r.water_removed) +
                  " water particles left the tank through its walls and were removed");
  return out;
}

// Counts of the sub-steps and of the pressure solver's iterations per water step.
struct StepTally {
  double steps = 0, substeps = 0, iterations = 0;
  int most_substeps = 0, most_iterations = 0;
  double water_seconds = 0, soil_seconds = 0;  // each physics' steps' wall time
  void add(const sph::coupled::CoupledStep& step) {
    steps += 1;
    water_seconds = step.water_seconds();
    soil_seconds = step.soil_seconds();
    substeps += step.last_substeps();
    iterations += step.water_diagnostics().solve_iterations;
    most_substeps = std::max(most_substeps, step.last_substeps());
    most_iterations = std::max(most_iterations, step.water_diagnostics().solve_iterations);
  }
};

void finish_result(const sph::coupled::Model& m, const StepTally& tally, CoupledStageResult& r) {
  const double rho0 = m.water.settings.rest_density;
  r.water_volume_end = m.water.particles.total_mass(sph::ParticleKind::material) / rho0;
  r.water_removed = m.water.fluid_particles_built - m.water.particles.count(sph::ParticleKind::material);
  r.most_substeps = tally.most_substeps;
  r.mean_substeps = tally.steps > 0 ? tally.substeps / tally.steps : 0;
  r.most_solver_iterations = tally.most_iterations;
  r.mean_solver_iterations = tally.steps > 0 ? tally.iterations / tally.steps : 0;
  r.soil_steps = tally.substeps;
  r.soil_seconds = tally.soil_seconds;
  r.water_seconds = tally.water_seconds;
  r.soil_particle_steps_per_second =
      tally.soil_seconds > 0 ? static_cast<double>(r.soil_particles) * tally.substeps / tally.soil_seconds : 0;
  r.water_particle_steps_per_second =
      tally.water_seconds > 0 ? static_cast<double>(r.water_particles) * tally.steps / tally.water_seconds : 0;
  r.water_inside_soil = water_inside_soil(m.soil.particles, m.water.particles, r.particle_spacing);
  r.water_max_speed = sph::moving_energies(m.water.particles, m.water.settings).max_speed;
  soil_measures(m.soil, r);
  r.warnings = coupled_warnings(r);
}

CoupledStageResult run_coupled(const Scene& scene, const WorkflowOptions& options) {
  const IsphAnalysis& a = *scene.analyses.isph;
  sph::coupled::Model model = build_coupled_model(scene);
  CoupledStageResult result;
  result.particle_spacing = a.settings.particle_spacing;
  result.soil_particles = model.soil.particles.count(sph::ParticleKind::material);
  result.soil_wall_particles = model.soil.particles.size() - result.soil_particles;
  result.water_particles = model.water.particles.count(sph::ParticleKind::material);
  result.soil_mass_start = model.soil.particles.total_mass(sph::ParticleKind::material);
  result.water_volume_start = model.water.fluid_mass_built / model.water.settings.rest_density;
  TankMonitorObserver monitors(a.monitors, a.tank, a.settings.particle_spacing);
  monitors.sample(model.water.particles, 0.0);
  const auto& impact = scene.analyses.coupled->impact;
  SlideObserver slide(model.soil, a.monitors.interval,
                      impact ? std::optional<double>(impact->ramp_angle_deg) : std::nullopt);
  slide.sample(0.0);
  if (options.resume) {
    resume_tank_run(
        options, "coupled", [&model](const std::string& path) { sph::coupled::read_checkpoint(path, model); },
        model.water.state, monitors);
    std::ifstream csv(*options.output_dir / "slide.csv");
    slide.restore(std::string(std::istreambuf_iterator<char>(csv), {}), model.water.state.time);
  }
  sph::RunOptions run_options;
  if (options.output_dir) run_options.output_dir = options.output_dir->string();
  run_options.progress_interval_wall_s = 2.0;
  sph::RunCallbacks callbacks = run_callbacks(options.log, "coupled");
  callbacks.observers.push_back(&monitors);
  callbacks.observers.push_back(&slide);
  StepTally tally;
  result.summary = sph::coupled::run(model, run_options, callbacks,
                                     [&tally](const sph::coupled::CoupledStep& step, const sph::RunState&) {
                                       tally.add(step);
                                     });
  if (monitors.table().times.back() < model.water.state.time)
    monitors.sample(model.water.particles, model.water.state.time);  // the end
  result.monitors = std::move(monitors.table());
  if (slide.table().times.back() < model.water.state.time) slide.sample(model.water.state.time);
  result.slide = std::move(slide.table());
  finish_result(model, tally, result);
  if (impact)
    result.impact = coupled_impact(result.slide, result.monitors, *impact, a.monitors, a.tank, result.soil_mass_start,
                                   std::hypot(a.settings.gravity_x, a.settings.gravity_y), a.settings.rest_density);
  return result;
}

}  // namespace

StageOutcome run_coupled_stage(const Scene& scene, StageContext& context) {
  const WorkflowOptions& options = context.options;
  RunResults& results = context.results;
  StageRecord<CoupledStageResult>& record = results.coupled.emplace();
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  try {
    CoupledStageResult result = run_coupled(scene, options);
    tank_run_outcome(result.summary, "coupled", outcome);
    if (options.log) {
      *options.log << "coupled: " << result.soil_particles << " soil and " << result.water_particles
                   << " water particles, " << result.summary.total_steps << " water steps (up to "
                   << result.most_substeps << " soil sub-steps each) to t = " << result.summary.simulated_time
                   << " s\n";
      for (const std::string& w : result.warnings) *options.log << "coupled: warning: " << w << "\n";
    }
    record.result = std::move(result);
  } catch (const SceneError& error) {
    outcome.status = ExitStatus::invalid_input;  // refused before it started (particle, memory or step limits)
    outcome.errors = error.messages();
  } catch (const std::exception& error) {
    outcome.fail(std::string("coupled: ") + error.what(), record.error);
  }
  results.seconds["coupled"] = seconds_since(start);
  return outcome;
}

}  // namespace coupling
