#pragma once
// The sliding granular layer of the floor-friction tests (test_basal_friction.cpp, test_wall_friction.cpp): the
// aluminium bars of the collapse tests, `rows` particles thick and 1 m long (x from 0.5 to 1.5 m), at rest under its
// geostatic (K0) stress on the floor of a 3 m box (floor only), set sliding at 1 m/s at its middle (x = 1 m) and
// stretched at `stretch` [1/s] (v = 1 + stretch (x - 1)); the floor's condition is the model's settings.wall_slip.
#include "sph/engine/fill.hpp"
#include "sph/soil/benchmarks.hpp"
#include "sph/soil/model.hpp"

namespace test_layer {

inline sph::soil::Model sliding_layer(int rows, double dx, double stretch,
                                      sph::soil::WallSlip slip = sph::soil::WallSlip::no_slip,
                                      double friction_angle_deg = 0.0) {
  sph::soil::Model m;
  const sph::soil::Material mat = sph::soil::aluminium_bars();
  m.materials.push_back(mat);
  auto& s = m.settings;
  s.particle_spacing = dx;
  s.gravity_mode = sph::GravityMode::geostatic_k0;
  s.output_interval = 0;
  s.wall_slip = slip;
  s.wall_friction_angle_deg = friction_angle_deg;
  sph::add_soil(m.particles,
                sph::lattice_points_in_region(0.5, 0, 1.5, rows * dx, dx, [](double, double) { return true; }), dx,
                0, mat.density);
  sph::BoxWalls floor;
  floor.x_min = 0;
  floor.x_max = 3.0;
  floor.y_min = 0;
  floor.height = 0.1;
  floor.left = floor.right = false;
  sph::add_box_walls(m.particles, floor, dx, s.smoothing_length(), 0, mat.density);
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if (m.particles.kind[i] == static_cast<std::uint8_t>(sph::ParticleKind::material))
      m.particles.vx[i] = 1.0 + stretch * (m.particles.x[i] - 1.0);
  return m;
}

}  // namespace test_layer
