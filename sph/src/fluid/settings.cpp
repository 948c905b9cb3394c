#include "sph/fluid/settings.hpp"

#include <cmath>
#include <stdexcept>

namespace sph::fluid {

PressureMode pressure_mode_from(const std::string& key) {
  return sphslope::value_named_or_throw(pressure_mode_names, key, "pressure mode");
}
const char* pressure_mode_key(PressureMode mode) { return sphslope::name_of(pressure_mode_names, mode).data(); }

LinearSolver linear_solver_from(const std::string& key) {
  return sphslope::value_named_or_throw(linear_solver_names, key, "linear solver");
}
const char* linear_solver_key(LinearSolver solver) { return sphslope::name_of(linear_solver_names, solver).data(); }

Preconditioner preconditioner_from(const std::string& key) {
  return sphslope::value_named_or_throw(preconditioner_names, key, "preconditioner");
}
const char* preconditioner_key(Preconditioner preconditioner) {
  return sphslope::name_of(preconditioner_names, preconditioner).data();
}

Settings::Settings() {
  kernel = default_kernel;
  particle_spacing = 0.01;
  h_over_dx = default_h_over_dx;
  cfl = default_cfl;
  output_interval = 0.0;  // no frames unless asked for
}

void Settings::validate() const {
  validate_engine();
  auto need = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("fluid settings: ") + what);
  };
  need(cfl <= max_cfl, "cfl must be at most 0.5 (the particle may move at most half a spacing per step; 0.1 typical)");
  need(rest_density > 0, "rest_density must be > 0");
  need(viscosity >= 0, "viscosity must be >= 0");
  need(eta_over_h > 0 && eta_over_h < 1, "eta_over_h must be in (0, 1)");
  need(surface_beta > 0 && surface_beta < 1, "surface_beta must be in (0, 1)");
  need(viscous_alpha > 0 && viscous_alpha <= 1, "viscous_alpha must be in (0, 1]");
  need(max_time_step >= 0, "max_time_step must be >= 0");
  need(solver_tolerance > 0 && solver_tolerance < 1, "solver_tolerance must be in (0, 1)");
  need(solver_max_iterations > 0, "solver_max_iterations must be > 0");
  need(wall_pass_tolerance > 0 && wall_pass_tolerance < 1, "wall_pass_tolerance must be in (0, 1)");
  need(wall_clearance >= 0 && wall_clearance < max_wall_clearance, "wall_clearance must be in [0, 1) spacings");
  need(wall_passes >= 1 && wall_passes <= 20, "wall_passes must be in [1, 20]");
  need(wall_layers >= static_cast<int>(std::ceil(2.0 * h_over_dx - 1e-9)),
       "wall_layers must cover the kernel support (at least ceil(2 h/dx))");
  need(end_time > 0, "end_time must be > 0");
}

}  // namespace sph::fluid
