#include "sph/fluid/model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sph::fluid {

namespace {

// Linear interpolation in a table (x ascending), constant beyond its ends.
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (xs.empty()) return 0.0;
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
  const double w = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
  return ys[k - 1] + w * (ys[k] - ys[k - 1]);
}

// Whether a lattice point is free of the solids: outside every solid polygon and at least dx/2 from its faces
// (the solids' first rows of particles sit dx/2 inside them, so fluid and wall particles are at least dx apart).
bool clear_of_solids(const Model& model, double x, double y) {
  const double clearance = 0.5 * model.settings.particle_spacing * (1.0 - 1e-9);  // a point at dx/2 is kept
  for (const std::vector<Point>& solid : model.solids)
    if (point_in_polygon(solid, x, y) || distance_to_polygon_edges(solid, x, y) < clearance) return false;
  return true;
}

}  // namespace

void RigidBody::prescribed(double t, double& travel, double& speed) const {
  const double tau = std::max(0.0, t - start_time);
  if (motion == Motion::table) {
    travel = interpolate(table_time, table_travel, tau);
    speed = 0.0;
    for (std::size_t k = 1; k < table_time.size(); ++k)
      if (tau >= table_time[k - 1] && tau < table_time[k]) {
        speed = (table_travel[k] - table_travel[k - 1]) / (table_time[k] - table_time[k - 1]);
        break;
      }
    return;
  }
  if (motion == Motion::ln_cosh && initial_acceleration > 0 && terminal_speed > 0) {
    const double a0 = initial_acceleration, ut = terminal_speed, arg = a0 * tau / ut;
    // ln cosh(z) = z + ln((1 + e^{-2z}) / 2), exact and free of overflow for large z
    travel = ut * ut / a0 * (arg + std::log1p(std::exp(-2.0 * arg)) - std::log(2.0));
    speed = ut * std::tanh(arg);
    return;
  }
  travel = 0.0;
  speed = 0.0;
}

Model::Model(const Settings& s) : settings(s), fields(Fields::register_in(particles)) { settings.validate(); }

std::size_t add_fluid_block(Model& model, double x_min, double y_min, double x_max, double y_max) {
  const Settings& st = model.settings;
  const double dx = st.particle_spacing;
  const auto points = lattice_points_in_region(x_min, y_min, x_max, y_max, dx,
                                               [&](double x, double y) { return clear_of_solids(model, x, y); });
  model.particles.reserve(model.particles.size() + points.size());
  for (const Point& p : points)
    model.particles.add(p.x, p.y, st.particle_mass(), st.rest_density, 0, ParticleKind::material);
  model.fluid_particles_built += points.size();
  model.fluid_mass_built += static_cast<double>(points.size()) * st.particle_mass();
  return points.size();
}

std::size_t add_solid_wall(Model& model, const std::vector<Point>& polygon) {
  const Settings& st = model.settings;
  const auto points = boundary_layer_points(polygon, st.particle_spacing, st.wall_layers);
  for (const Point& p : points)
    model.particles.add(p.x, p.y, st.particle_mass(), st.rest_density, 0, ParticleKind::wall);
  model.solids.push_back(polygon);
  return points.size();
}

std::size_t add_rigid_body(Model& model, const std::vector<Point>& polygon, RigidBody body) {
  const Settings& st = model.settings;
  const double norm = std::hypot(body.direction_x, body.direction_y);
  if (!(norm > 0)) throw std::invalid_argument("rigid body: the direction of travel must not be zero");
  body.direction_x /= norm;
  body.direction_y /= norm;
  body.area = polygon_area(polygon);
  double cx = 0, cy = 0, twice = 0;  // the centroid of the polygon (shoelace weights)
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const double c = polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y;
    twice += c;
    cx += (polygon[j].x + polygon[i].x) * c;
    cy += (polygon[j].y + polygon[i].y) * c;
  }
  body.centroid_x = cx / (3.0 * twice);
  body.centroid_y = cy / (3.0 * twice);
  if (model.bodies.size() + 1 >= 0xffff) throw std::invalid_argument("rigid body: too many bodies");
  const auto material = static_cast<std::uint16_t>(model.bodies.size() + 1);
  const int fill_rows = 1 << 20;  // rows until the polygon is full
  const auto points = boundary_layer_points(polygon, st.particle_spacing, fill_rows);
  for (const Point& p : points)
    model.particles.add(p.x, p.y, st.particle_mass(), st.rest_density, material, ParticleKind::wall);
  model.bodies.push_back(std::move(body));
  model.solids.push_back(polygon);
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
  const double g = st.gravity_factor(model.state.time) * std::abs(st.gravity_y);  // the component normal to the bed
  double* p = model.particles.field(model.fields.pressure).data();
  for (std::size_t i = 0; i < model.particles.size(); ++i)
    p[i] = model.settings.rest_density * g * std::max(surface_y - model.particles.y[i], 0.0);
}

}  // namespace sph::fluid
