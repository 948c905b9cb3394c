#include "sph/fluid/cases.hpp"

#include <algorithm>
#include <limits>

namespace sph::fluid {

Model make_still_tank(const Settings& settings, double width, double depth) {
  Model model(settings);
  add_fluid_block(model, 0.0, 0.0, width, depth);
  add_tank_walls(model, 0.0, width, 0.0, 1.5 * depth);
  set_hydrostatic_pressure(model, depth - 0.5 * settings.particle_spacing);  // P = 0 at the top row (D6)
  return model;
}

Model make_dam_break(const Settings& settings, double a, double n2, double tank_length) {
  Model model(settings);
  add_fluid_block(model, 0.0, 0.0, a, n2 * a);
  add_tank_walls(model, 0.0, tank_length, 0.0, 1.5 * n2 * a);
  set_hydrostatic_pressure(model, n2 * a - 0.5 * settings.particle_spacing);
  return model;
}

double front_position(const Model& model) {
  const ParticleSet& p = model.particles;
  double front = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::material)) front = std::max(front, p.x[i]);
  return front + 0.5 * model.settings.particle_spacing;
}

}  // namespace sph::fluid
