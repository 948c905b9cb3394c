#include "sph/engine/settings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sph/engine/require.hpp"

namespace sph {

namespace {
std::string number(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}
}  // namespace

void EngineSettings::validate_engine() const {
  require(finite_positive(particle_spacing), "settings.particle_spacing must be > 0 m (the lattice spacing dx)");
  require(finite_positive(h_over_dx) && h_over_dx >= h_over_dx_min && h_over_dx <= h_over_dx_max,
          "settings.h_over_dx must lie in [" + number(h_over_dx_min) + ", " + number(h_over_dx_max) +
              "] (typical 1.2-1.5), got " + std::to_string(h_over_dx));
  require(std::isfinite(gravity_x) && std::isfinite(gravity_y), "settings.gravity must be finite");
  if (gravity_mode == GravityMode::ramped)
    require(finite_positive(gravity_ramp_time), "settings.gravity_ramp_time must be > 0 s when gravity is ramped");
  require(finite_positive(cfl) && cfl <= 2.0, "settings.cfl must lie in (0, 2] (each physics states its own limit)");
  require(finite_positive(acceleration_safety) && acceleration_safety <= 0.5,
          "settings.acceleration_safety must lie in (0, 0.5]");
  require(std::isfinite(end_time) && end_time >= 0, "settings.end_time must be >= 0 s");
  require(std::isfinite(output_interval), "settings.output_interval must be finite");
  require(std::isfinite(checkpoint_interval_wall_s), "settings.checkpoint_interval_wall_s must be finite");
  require(finite_positive(blow_up_speed_factor), "settings.blow_up_speed_factor must be > 0");
  require(finite_positive(blow_up_energy_factor), "settings.blow_up_energy_factor must be > 0");
}

double EngineSettings::gravity_factor(double t) const {
  if (gravity_mode != GravityMode::ramped) return 1.0;
  return t >= gravity_ramp_time ? 1.0 : std::max(t, 0.0) / gravity_ramp_time;
}

}  // namespace sph
