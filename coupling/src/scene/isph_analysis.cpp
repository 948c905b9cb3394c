// analyses.isph: settings, tank, water blocks and monitors of the ISPH fluid (docs/scene-format.md).
#include "coupling/scene/isph_analysis.hpp"

#include <cmath>
#include <exception>

namespace coupling {

namespace {

void read_numerics(JsonReader& r, sph::fluid::Settings& s) {
  if (auto v = r.number("particle_spacing_m", Need::required)) s.particle_spacing = *v;
  if (auto v = r.number("end_time_s", Need::required)) s.end_time = *v;
  s.h_over_dx = r.number_or("h_over_dx", s.h_over_dx,
                            Bounds::closed(sph::EngineSettings::h_over_dx_min, sph::EngineSettings::h_over_dx_max));
  s.output_interval = r.number_or("output_interval_s", s.output_interval);
  s.rest_density = r.number_or("rest_density_kg_m3", s.rest_density);
  s.viscosity = r.number_or("viscosity_Pa_s", s.viscosity);
  s.surface_beta = r.number_or("surface_beta", s.surface_beta);
  s.wall_clearance =
      r.number_or("wall_clearance", s.wall_clearance, Bounds::half_open(0.0, sph::fluid::Settings::max_wall_clearance));
  s.cfl = r.number_or("cfl", s.cfl, Bounds{0.0, false, sph::fluid::Settings::max_cfl, true});
  s.max_time_step = r.number_or("max_time_step_s", s.max_time_step);
  s.solver_tolerance = r.number_or("solver_tolerance", s.solver_tolerance);
  read_named(r, "pressure", sph::fluid::pressure_mode_names, s.pressure_mode);
  read_named(r, "preconditioner", sph::fluid::preconditioner_names, s.preconditioner);
  read_named(r, "solver", sph::fluid::linear_solver_names, s.solver);
  s.wall_layers = static_cast<int>(std::ceil(2.0 * s.h_over_dx - 1e-9));
}

// Fluid leaving the tank through its walls' outer faces (or below its floor) is removed (docs/isph.md D11).
void set_domain(IsphAnalysis& a) {
  const double wall = a.settings.wall_layers * a.settings.particle_spacing;
  a.settings.domain_x_min = a.tank.x_min - wall;
  a.settings.domain_x_max = a.tank.x_max + wall;
  a.settings.domain_y_min = a.tank.y_min - wall;
}

void validate_settings(const IsphAnalysis& a, Diagnostics& diagnostics) {
  try {
    a.settings.validate();
  } catch (const std::exception& error) {
    diagnostics.error("analyses.isph", error.what());
  }
}

}  // namespace

void apply_isph_spacing(IsphAnalysis& analysis, double spacing, Diagnostics& diagnostics) {
  analysis.settings.particle_spacing = spacing;
  set_domain(analysis);
  validate_settings(analysis, diagnostics);
}

IsphAnalysis read_isph_analysis(JsonReader& isph) {
  IsphAnalysis a;
  read_numerics(isph, a.settings);
  read_tank(isph, a.tank);
  read_isph_geometry(isph, a);
  read_tank_rectangles(isph, "water", a.tank, a.water);
  set_domain(a);
  read_tank_monitors(isph, a.monitors, false);
  isph.finish();
  validate_settings(a, isph.diagnostics());
  return a;
}

}  // namespace coupling
