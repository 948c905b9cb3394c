// The "isph" stage: the explicit three-step ISPH fluid (analyses.isph, docs/isph.md) in a tank, with its monitors
// (surface gauges, the surge front) written to monitors.csv and its block of report.json.
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <ostream>
#include <string>

#include "coupling/analyses/stage.hpp"
#include "coupling/analyses/tank_monitors.hpp"
#include "coupling/output/isph_report.hpp"
#include "sph/engine/atomic_file.hpp"
#include "sph/fluid/cases.hpp"
#include "sph/fluid/run.hpp"

namespace coupling {

namespace {

sph::fluid::Model build_isph_model(const IsphAnalysis& a) {
  sph::fluid::Model model(a.settings);
  for (const IsphSolid& solid : a.solids) sph::fluid::add_solid_wall(model, solid.polygon);
  for (const IsphBody& body : a.bodies) sph::fluid::add_rigid_body(model, body.polygon, body.body);
  double top = -std::numeric_limits<double>::infinity();  // the water fills around the solids and bodies
  for (const TankRectangle& w : a.water) {
    sph::fluid::add_fluid_block(model, w.x_min, w.y_min, w.x_max, w.y_max);
    top = std::max(top, w.y_max);
  }
  sph::fluid::add_tank_walls(model, a.tank.x_min, a.tank.x_max, a.tank.y_min, a.tank.height);
  // hydrostatic start with P = 0 at the top row's centres (docs/isph.md D6)
  sph::fluid::set_hydrostatic_pressure(model, top - 0.5 * a.settings.particle_spacing);
  return model;
}

double fluid_mass(const sph::ParticleSet& p) { return p.total_mass(sph::ParticleKind::soil); }  // kind 0: fluid

IsphStageResult run_isph(const IsphAnalysis& a, const WorkflowOptions& options) {
  sph::fluid::Model model = build_isph_model(a);
  IsphStageResult result;
  result.pressure_mode = sph::fluid::pressure_mode_key(a.settings.pressure_mode);
  result.kernel = a.settings.kernel == sph::KernelType::wendland_c2 ? "wendland_c2" : "cubic_spline";
  result.particle_spacing = a.settings.particle_spacing;
  result.smoothing_length = a.settings.smoothing_length();
  result.fluid_particles = model.particles.count(sph::ParticleKind::soil);
  result.wall_particles = model.particles.size() - result.fluid_particles;
  result.fluid_mass_start = fluid_mass(model.particles);
  TankMonitorObserver monitors(a.monitors, a.tank, a.settings.particle_spacing);
  monitors.sample(model.particles, 0.0);
  sph::RunOptions run_options;
  if (options.output_dir) run_options.output_dir = options.output_dir->string();
  sph::RunCallbacks callbacks;
  callbacks.observers.push_back(&monitors);
  double worst = 0;
  result.summary =
      sph::fluid::run(model, run_options, callbacks, [&worst](const sph::fluid::Step& s, const sph::RunState&) {
        worst = std::max(worst, s.diagnostics().max_density_error);
      });
  result.max_density_error = worst;
  if (monitors.table().times.back() < model.state.time) monitors.sample(model.particles, model.state.time);  // the end
  result.fluid_mass_end = fluid_mass(model.particles);
  result.front_x = sph::fluid::front_position(model);
  result.monitors = std::move(monitors.table());
  return result;
}

}  // namespace

StageOutcome run_isph_stage(const Scene& scene, StageContext& context) {
  const WorkflowOptions& options = context.options;
  WorkflowResult& out = context.out;
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  try {
    const IsphStageResult result = run_isph(*scene.analyses.isph, options);
    out.report["isph"] = isph_report(result);
    if (options.output_dir)
      sph::write_file_atomically(*options.output_dir / "monitors.csv", monitors_csv(result.monitors));
    if (result.summary.stopped_because != "end_time") {
      outcome.status = ExitStatus::failed;
      outcome.errors.push_back("isph: stopped (" + result.summary.stopped_because + ") " + result.summary.diagnostic);
    }
    if (options.log)
      *options.log << "isph: " << result.fluid_particles << " fluid particles, " << result.summary.steps
                   << " steps to t = " << result.summary.simulated_time << " s, front x = " << result.front_x << " m\n";
  } catch (const std::exception& error) {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back(std::string("isph: ") + error.what());
    out.report["isph"] = isph_error_report(outcome.errors.back());
  }
  out.report["timing_s"]["isph"] = seconds_since(start);
  return outcome;
}

}  // namespace coupling
