#include "sph/mps/settings.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sph/mps/terms.hpp"

namespace sph::mps {

namespace {

template <class E, std::size_t N>
E value_from(const sphslope::NameTable<E, N>& names, const std::string& key, const char* setting) {
  return sphslope::value_named_or_throw(names, key, std::string("mps ") + setting);
}

}  // namespace

Regularisation regularisation_from(const std::string& key) {
  return value_from(regularisation_names, key, "regularisation");
}
const char* regularisation_key(Regularisation r) { return sphslope::name_of(regularisation_names, r).data(); }

InteractionViscosity interaction_viscosity_from(const std::string& key) {
  return value_from(interaction_viscosity_names, key, "interaction viscosity");
}
const char* interaction_viscosity_key(InteractionViscosity v) {
  return sphslope::name_of(interaction_viscosity_names, v).data();
}

EffectivePressure effective_pressure_from(const std::string& key) {
  return value_from(effective_pressure_names, key, "effective pressure");
}
const char* effective_pressure_key(EffectivePressure p) { return sphslope::name_of(effective_pressure_names, p).data(); }

PorePressure pore_pressure_from(const std::string& key) { return value_from(pore_pressure_names, key, "pore pressure"); }
const char* pore_pressure_key(PorePressure p) { return sphslope::name_of(pore_pressure_names, p).data(); }

StressDivergence stress_divergence_from(const std::string& key) {
  return value_from(stress_divergence_names, key, "stress divergence");
}
const char* stress_divergence_key(StressDivergence s) { return sphslope::name_of(stress_divergence_names, s).data(); }

std::string sound_speed_problem(double c0, double u_max) {
  if (terms::sound_speed_sufficient(c0, u_max)) return {};
  std::ostringstream s;
  s << "sound_speed = " << c0 << " m/s is below " << terms::sound_speed_factor << " x the largest flow speed ("
    << u_max << " m/s): the density error exceeds about 1 %; allowed: at least " << terms::sound_speed_factor * u_max
    << " m/s";
  return s.str();
}

Settings::Settings() {
  particle_spacing = 0.001;  // 1 mm: the dry collapse's likely spacing (seed A14)
  output_interval = 0.0;  // no frames unless asked for
}

namespace {

// Throws "mps settings: <name> = <value> is <what is wrong>; allowed: <allowed>" unless ok.
void need(bool ok, const char* name, double value, const char* wrong, const char* allowed) {
  if (ok) return;
  std::ostringstream s;
  s << "mps settings: " << name << " = " << value << " is " << wrong << "; allowed: " << allowed;
  throw std::invalid_argument(s.str());
}

}  // namespace

void Settings::validate() const {
  validate_engine();
  const double re = re_over_dx;
  need(std::isfinite(re) && re >= min_re_over_dx && re <= max_re_over_dx, "re_over_dx", re,
       "out of range (the weight's radius r_e in spacings)", "2 to 6 (default 4)");
  need(std::isfinite(rest_density) && rest_density > 0, "rest_density", rest_density, "not a positive density",
       "> 0 kg/m^3");
  need(std::isfinite(sound_speed) && sound_speed > 0, "sound_speed", sound_speed, "not a positive speed",
       "> 0 m/s, at least 10 x the largest flow speed");
  need(std::isfinite(tait_gamma) && tait_gamma >= 1 && tait_gamma <= 10, "tait_gamma", tait_gamma, "out of range",
       "1 to 10 (default 7)");
  need(surface_beta >= min_surface_beta && surface_beta <= max_surface_beta, "surface_beta", surface_beta,
       "outside the paper's range", "0.80 to 0.99 (default 0.92)");
  need(std::isfinite(viscosity_cap) && viscosity_cap > 0, "viscosity_cap", viscosity_cap, "not a positive viscosity",
       "> 0 Pa s (default 200)");
  need(cfl <= max_cfl, "cfl", cfl, "above the stability limit of eq. 30's C_r", "(0, 1] (default 0.2; seed 0.1-0.25)");
  need(pressure_split >= 0 && pressure_split <= 1, "pressure_split", pressure_split, "out of range",
       "0 to 1 (default 0.5; 0: the pressure force of the old level only)");
  need(end_time > 0, "end_time", end_time, "not positive", "> 0 s");
  need(wall_collision_distance == 0 || (wall_collision_distance > 0.5 && wall_collision_distance < 1.0),
       "wall_collision_distance", wall_collision_distance, "out of range (in spacings)",
       "0 (off) or above 0.5 and below 1 (default 0.75)");
  need(wall_collision_restitution >= 0 && wall_collision_restitution <= 1, "wall_collision_restitution",
       wall_collision_restitution, "out of range", "0 to 1 (default 0)");
  need(std::isfinite(gate_lift_speed) && gate_lift_speed >= 0, "gate_lift_speed", gate_lift_speed,
       "not a speed", ">= 0 m/s (0: the gate stays)");
  need(std::isfinite(gate_lift_distance) && gate_lift_distance >= 0, "gate_lift_distance", gate_lift_distance,
       "not a distance", ">= 0 m");
}

double Settings::gate_rise(double t) const { return std::min(gate_lift_speed * t, gate_lift_distance); }

}  // namespace sph::mps
