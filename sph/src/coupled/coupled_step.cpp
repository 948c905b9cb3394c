#include "sph/coupled/coupled_step.hpp"

#include "sphslope/wall_clock.hpp"

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sph::coupled {

namespace {

const soil::Model& checked(const soil::Model& soil, const fluid::Model& water) {
  if (soil.loads.surface_force_x)
    throw std::invalid_argument("coupled run: the soil's own surface forces (strip and line loads) are not yet carried "
                                "beside the water's");
  if (soil.settings.gravity_x != water.settings.gravity_x || soil.settings.gravity_y != water.settings.gravity_y) {
    std::ostringstream os;
    os << "coupled run: the soil's gravity (" << soil.settings.gravity_x << ", " << soil.settings.gravity_y
       << ") m/s^2 must equal the water's (" << water.settings.gravity_x << ", " << water.settings.gravity_y << ")";
    throw std::invalid_argument(os.str());
  }
  return soil;
}

}  // namespace

CoupledStep::CoupledStep(soil::Model& soil, fluid::Model& water)
    : soil_(soil),
      water_(water),
      soil_step_(soil),
      boundary_(water, checked(soil, water)),
      water_step_(water) {
  force_x_ = soil.particles.add_field({"coupled_water_force_x", false, false});
  force_y_ = soil.particles.add_field({"coupled_water_force_y", false, false});
  soil.loads.surface_force_x = force_x_;
  soil.loads.surface_force_y = force_y_;
  // the table's hydrostatic pressure, which the soil carries itself (its pore pressure), is the water's reference
  water_step_.set_reference_pressure([this](double x, double y) {
    return soil_.loads.water ? soil_.loads.water->pressure(x, y) : 0.0;
  });
}

void CoupledStep::share_water_table() { soil_.loads.water = water_table(water_); }

void CoupledStep::share_water_forces() {
  const fluid::StepDiagnostics& d = water_step_.diagnostics();
  boundary_.take_forces(water_, d.coupled_force_x, d.coupled_force_y, soil_, force_x_, force_y_);
}

void CoupledStep::initialise() {
  share_water_table();
  soil_step_.initialise();
  boundary_.update(water_, soil_);
  water_step_.initialise();
}

double CoupledStep::stable_time_step() const { return water_step_.stable_time_step(); }

void CoupledStep::advance(double dt) {
  const sphslope::WallClock::time_point start = sphslope::WallClock::now();
  boundary_.update(water_, soil_);
  water_step_.advance(dt);
  share_water_forces();  // beyond the table the step started from (the water's reference in the step)
  share_water_table();
  const sphslope::WallClock::time_point soil_start = sphslope::WallClock::now();
  water_seconds_ += std::chrono::duration<double>(soil_start - start).count();
  const double bound = soil_step_.stable_time_step();
  substeps_ = bound > 0 && std::isfinite(bound) ? static_cast<int>(std::ceil(dt / bound)) : 1;
  if (substeps_ < 1) substeps_ = 1;
  soil_dt_ = dt / substeps_;
  for (int k = 0; k < substeps_; ++k) soil_step_.advance(soil_dt_);
  soil_seconds_ += sphslope::seconds_since(soil_start);
}

Energies CoupledStep::energies() const {
  const Energies s = soil_step_.energies(), w = water_step_.energies();
  Energies e;
  e.kinetic = s.kinetic + w.kinetic;
  // The soil counts -f.x of its surface forces as potential energy (a fixed load's); the water's force is the
  // exchange between the two phases, no potential: taken back out.
  double exchange = 0;
  const ParticleSet& p = soil_.particles;
  const std::vector<double>& fx = p.field(force_x_);
  const std::vector<double>& fy = p.field(force_y_);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::material)) exchange += fx[i] * p.x[i] + fy[i] * p.y[i];
  e.potential = s.potential + exchange + w.potential;
  e.plastic_dissipation = s.plastic_dissipation + w.plastic_dissipation;
  e.max_speed = std::max(s.max_speed, w.max_speed);
  return e;
}

Health CoupledStep::check_health() const {
  Health h = soil_step_.check_health();
  if (!h.ok) {
    h.diagnostic = "soil: " + h.diagnostic;
    return h;
  }
  h = water_step_.check_health();
  if (!h.ok) h.diagnostic = "water: " + h.diagnostic;
  return h;
}

}  // namespace sph::coupled
