#include "sph/fluid/model.hpp"

#include <cmath>

namespace sph::fluid {

Model::Model(const Settings& s) : settings(s), fields(Fields::register_in(particles)) { settings.validate(); }

std::size_t add_fluid_block(Model& model, double x_min, double y_min, double x_max, double y_max) {
  const Settings& st = model.settings;
  const double dx = st.particle_spacing;
  const auto points = lattice_points_in_region(x_min, y_min, x_max, y_max, dx, [](double, double) { return true; });
  model.particles.reserve(model.particles.size() + points.size());
  for (const Point& p : points)
    model.particles.add(p.x, p.y, st.particle_mass(), st.rest_density, 0, ParticleKind::soil);
  return points.size();
}

std::size_t add_tank_walls(Model& model, double x_min, double x_max, double y_min, double height) {
  const Settings& st = model.settings;
  BoxWalls box;
  box.x_min = x_min;
  box.x_max = x_max;
  box.y_min = y_min;
  box.height = height;
  box.layers = st.wall_layers;
  return add_box_walls(model.particles, box, st.particle_spacing, st.smoothing_length(), 0, st.rest_density);
}

void set_hydrostatic_pressure(Model& model, double surface_y) {
  const Settings& st = model.settings;
  const double g = st.gravity_factor(model.state.time) * std::hypot(st.gravity_x, st.gravity_y);
  double* p = model.particles.field(model.fields.pressure).data();
  for (std::size_t i = 0; i < model.particles.size(); ++i)
    p[i] = model.settings.rest_density * g * std::max(surface_y - model.particles.y[i], 0.0);
}

}  // namespace sph::fluid
