// The "isph" stage: the explicit three-step ISPH fluid (analyses.isph, docs/isph.md) in a tank, with its monitors
// (surface gauges, the surge front), snapshots and the measures taken at its end; --resume continues it from the run
// folder's checkpoint. coupling/output/isph_report writes its monitors.csv, figures and report block.
#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>

#include "coupling/analyses/isph_front.hpp"
#include "coupling/analyses/isph_measures.hpp"
#include "coupling/analyses/isph_waves.hpp"
#include "coupling/analyses/sph_stage.hpp"
#include "coupling/analyses/stage.hpp"
#include "coupling/analyses/tank_monitors.hpp"
#include "coupling/analyses/tank_run.hpp"
#include "coupling/analyses/isph_stage.hpp"
#include "sph/engine/atomic_file.hpp"
#include "sph/fluid/cases.hpp"
#include "sph/fluid/run.hpp"

namespace coupling {

sph::fluid::Model build_isph_model(const IsphAnalysis& a, const std::vector<std::vector<sph::Point>>& displacing) {
  sph::fluid::Model model(a.settings);
  for (const IsphSolid& solid : a.solids) sph::fluid::add_solid_wall(model, solid.polygon);
  for (const IsphBody& body : a.bodies) sph::fluid::add_rigid_body(model, body.polygon, body.body);
  for (const auto& polygon : displacing) model.solids.push_back(polygon);
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

namespace {

double fluid_mass(const sph::ParticleSet& p) { return p.total_mass(sph::ParticleKind::material); }  // kind 0: fluid

double gravity_of(const IsphAnalysis& a) { return std::hypot(a.settings.gravity_x, a.settings.gravity_y); }

void echo_settings(const IsphAnalysis& a, const sph::fluid::Model& model, IsphStageResult& result) {
  result.pressure_mode = sph::fluid::pressure_mode_key(a.settings.pressure_mode);
  result.kernel = sphslope::name_of(sph::kernel_names, a.settings.kernel);
  result.particle_spacing = a.settings.particle_spacing;
  result.smoothing_length = a.settings.smoothing_length();
  result.fluid_particles = model.particles.count(sph::ParticleKind::material);
  result.wall_particles = model.particles.size() - result.fluid_particles;
  result.fluid_mass_start = fluid_mass(model.particles);
}

// Draws each snapshot into the run folder (coupling/output's figure; nothing without a run folder).
SnapshotObserver::Writer snapshot_writer(const WorkflowOptions& options) {
  if (!options.output_dir || !options.draw_snapshot) return {};
  return options.draw_snapshot;
}

// --resume: the model, the monitors' rows, the snapshots already drawn and the figures taken over the run so far.
void resume_isph(const WorkflowOptions& options, sph::fluid::Model& model, TankMonitorObserver& monitors,
                 WallCrossingObserver& crossing, SnapshotObserver& snapshots, BodyTracker& bodies,
                 IsphStageResult& result) {
  const std::optional<ReportRecord> record = resume_tank_run(
      options, "isph", [&model](const std::string& path) { sph::fluid::read_checkpoint(path, model); }, model.state,
      monitors);
  const IsphCarryOver earlier = record && record->isph ? *record->isph : IsphCarryOver{};
  result.max_density_error = earlier.max_density_error;
  result.mean_density_error = earlier.mean_density_error;
  result.largest_time_step = earlier.largest_time_step;
  result.wall_contacts = earlier.wall_contacts;
  bodies.restore(earlier.bodies, earlier.fluid_energy_start.value_or(bodies.fluid_energy_start()), model);
  crossing.restore(earlier.past_walls_most, earlier.past_walls_first_time);
  std::vector<std::string> drawn;
  for (const double t : snapshots.times())
    if (t <= model.state.time + 1e-12 && std::filesystem::exists(*options.output_dir / "figures" / snapshot_file_name(t)))
      drawn.push_back("figures/" + snapshot_file_name(t));
  snapshots.restore(model.state.time, std::move(drawn));
}

// What the run says beyond its figures: a time-step bound that never applied, particles the walls did not hold.
std::vector<std::string> isph_warnings(const IsphAnalysis& a, const IsphStageResult& r) {
  std::vector<std::string> out;
  const double bound = a.settings.max_time_step;
  if (bound > 0 && r.largest_time_step > 0 && r.largest_time_step < bound * (1.0 - 1e-9))
    out.push_back("analyses.isph.max_time_step_s: " + format_number(bound) +
                  " s is above every time step the stability limits allowed (the largest taken: " +
                  format_number(r.largest_time_step) +
                  " s; cfl dx/|V|max, cfl sqrt(dx/g) and the viscous limit, docs/isph.md section 2): it never "
                  "applied, the time step cannot exceed those limits");
  const SurfaceRows rows = surface_row_kernel_sums(a.settings.kernel, a.settings.h_over_dx);
  const double beta = a.settings.surface_beta, margin = 0.02;  // the kernel sum moves by a few per cent in a flow
  const std::string rows_text = " (the kernel sum of a flat surface's top row at rest is " + format_number(rows.top) +
                                " rho0, of the row under it " + format_number(rows.second) + " rho0, docs/isph.md D4)";
  if (beta < rows.top + margin)
    out.push_back("analyses.isph.surface_beta: " + format_number(beta) + " is less than " + format_number(margin) +
                  " above the top row's kernel sum" + rows_text +
                  ": a surface particle pressed slightly is no longer marked free and P = 0 is not held there");
  if (beta > rows.second - margin)
    out.push_back("analyses.isph.surface_beta: " + format_number(beta) + " is less than " + format_number(margin) +
                  " below the kernel sum of the row under the surface" + rows_text +
                  ": particles inside the water, spread slightly, are marked free and get P = 0");
  if (r.past_walls_most > 0)
    out.push_back("analyses.isph.tank: fluid particles went past the tank's walls (centres beyond the first row of "
                  "wall particles), first at t = " + format_number(r.past_walls_first_time.value_or(0.0)) +
                  " s, at most " + std::to_string(r.past_walls_most) + " at one step, " +
                  std::to_string(r.past_walls_end) + " at the end: the walls did not hold the fluid and results "
                  "near them are not reliable (docs/stability.md)");
  return out;
}

// Ritter's dam break as the scene gives it (front_reference's dam and depth), with the gauge at the dam if any.
RitterSetting ritter_setting(const IsphAnalysis& a) {
  const FrontReference& ref = *a.outputs.front_reference;
  RitterSetting c;
  c.dam_x = *ref.ritter_dam_x;
  c.depth = *ref.ritter_depth;
  c.g = gravity_of(a);
  c.reservoir_length = c.dam_x - a.tank.x_min;
  c.far_wall_x = a.tank.x_max;
  c.gauge_offset = a.monitors.still_water - a.tank.y_min;
  for (const Gauge& gauge : a.monitors.gauges)
    if (std::abs(gauge.x - c.dam_x) <= a.settings.particle_spacing) c.dam_gauge = gauge.name + "_m";
  return c;
}

// The figures and checks taken at the end of the run.
void finish_result(const IsphAnalysis& a, const sph::fluid::Model& model, const WallCrossingObserver& crossing,
                   IsphStageResult& result) {
  const double dx = a.settings.particle_spacing;
  result.fluid_mass_end = fluid_mass(model.particles);
  result.front_x = sph::fluid::front_position(model);
  result.past_walls_end = fluid_past_walls(model.particles, a.tank, dx);
  result.past_walls_most = std::max(crossing.most(), result.past_walls_end);
  result.past_walls_first_time = crossing.first_time();
  result.still_tank = still_tank_check(model, a);
  result.fluid_removed = model.fluid_particles_built - model.particles.count(sph::ParticleKind::material);
  result.fluid_mass_removed = model.fluid_mass_built - result.fluid_mass_end;
  result.fluid_energy_end = fluid_energy(model);
  const std::optional<FrontReference>& ref = a.outputs.front_reference;
  if (ref && !ref->data.empty())
    result.front_errors = martin_moyce_front_errors(result.monitors, {ref->column_width, gravity_of(a), a.tank.x_min});
  if (ref && ref->ritter_dam_x && ref->ritter_depth) result.ritter = ritter_comparison(result.monitors, ritter_setting(a));
  if (!a.bodies.empty() && !a.monitors.gauges.empty())
    result.waves = gauge_waves(result.monitors, a.monitors, a.tank, gravity_of(a));
  result.warnings = isph_warnings(a, result);
}

IsphStageResult run_isph(const Scene& scene, const WorkflowOptions& options) {
  const IsphAnalysis& a = *scene.analyses.isph;
  sph::fluid::Model model = build_isph_model(a);
  IsphStageResult result;
  echo_settings(a, model, result);
  TankMonitorObserver monitors(a.monitors, a.tank, a.settings.particle_spacing);
  monitors.sample(model.particles, 0.0);
  WallCrossingObserver crossing(a.tank, a.settings.particle_spacing);
  SnapshotObserver snapshots(a.outputs.snapshot_times, model.fields.pressure, a.settings.particle_spacing,
                             snapshot_writer(options));
  BodyTracker bodies(a, model);
  if (options.resume) resume_isph(options, model, monitors, crossing, snapshots, bodies, result);
  sph::RunOptions run_options;
  if (options.output_dir) run_options.output_dir = options.output_dir->string();
  run_options.progress_interval_wall_s = 2.0;
  sph::RunCallbacks callbacks = run_callbacks(options.log, "isph");
  for (sph::Observer* o : {static_cast<sph::Observer*>(&monitors), static_cast<sph::Observer*>(&crossing),
                           static_cast<sph::Observer*>(&snapshots)})
    callbacks.observers.push_back(o);
  result.summary = sph::fluid::run(model, run_options, callbacks, [&](const sph::fluid::Step& s,
                                                                       const sph::RunState&) {
    bodies.after_step(s, model);
    const sph::fluid::StepDiagnostics& d = s.diagnostics();
    result.max_density_error = std::max(result.max_density_error, d.max_density_error);
    result.mean_density_error = std::max(result.mean_density_error, d.mean_density_error);
    result.largest_time_step = std::max(result.largest_time_step, d.time_step);
    result.wall_contacts += d.wall_contacts;
  });
  if (monitors.table().times.back() < model.state.time) monitors.sample(model.particles, model.state.time);  // the end
  result.monitors = std::move(monitors.table());
  result.figures = snapshots.files();
  result.bodies = bodies.bodies();
  result.fluid_energy_start = bodies.fluid_energy_start();
  finish_result(a, model, crossing, result);
  return result;
}

}  // namespace

StageOutcome run_isph_stage(const Scene& scene, StageContext& context) {
  const WorkflowOptions& options = context.options;
  RunResults& results = context.results;
  StageRecord<IsphStageResult>& record = results.isph.emplace();
  StageOutcome outcome;
  const StageClock::time_point start = StageClock::now();
  try {
    IsphStageResult result = run_isph(scene, options);
    tank_run_outcome(result.summary, "isph", outcome);
    if (options.log) {
      *options.log << "isph: " << result.fluid_particles << " fluid particles, " << result.summary.total_steps
                   << " steps to t = " << result.summary.simulated_time << " s, front x = " << result.front_x << " m\n";
      for (const std::string& w : result.warnings) *options.log << "isph: warning: " << w << "\n";
    }
    record.result = std::move(result);
  } catch (const std::exception& error) {
    outcome.fail(std::string("isph: ") + error.what(), record.error);
  }
  results.seconds["isph"] = seconds_since(start);
  return outcome;
}

}  // namespace coupling
