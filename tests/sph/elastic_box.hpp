#pragma once
// The elastic soil column of the column tests (test_elastic_column.cpp, test_loads.cpp): 0.5 m wide, 1 m high,
// E = 5 MPa, nu = 0.3, dx = 25 mm, h = 1.3 dx, in a free-slip box 1.2 m high (floor and, by default, both sides),
// 0.3 s, no output.
#include "sph/engine/fill.hpp"
#include "sph/soil/model.hpp"

namespace test_column {

constexpr double width = 0.5, height = 1.0, density = 2000.0;

inline sph::soil::Model elastic_box(sph::GravityMode mode, double damping, double rho = density, bool side_walls = true) {
  sph::soil::Model m;
  sph::soil::Material mat;
  mat.name = "elastic";
  mat.density = rho;
  mat.youngs_modulus = 5e6;
  mat.poisson_ratio = 0.3;
  mat.plastic = false;
  m.materials.push_back(mat);
  auto& s = m.settings;
  s.particle_spacing = 0.025;
  s.h_over_dx = 1.3;
  s.gravity_mode = mode;
  s.damping = damping;
  s.wall_slip = sph::soil::WallSlip::free_slip;
  s.end_time = 0.3;
  s.output_interval = 0;
  sph::add_soil(m.particles,
                sph::lattice_points_in_region(0, 0, width, height, s.particle_spacing,
                                              [](double, double) { return true; }),
                s.particle_spacing, 0, rho);
  sph::BoxWalls box;
  box.x_min = 0;
  box.x_max = width;
  box.y_min = 0;
  box.height = 1.2 * height;
  box.left = box.right = side_walls;
  sph::add_box_walls(m.particles, box, s.particle_spacing, s.smoothing_length(), 0, rho);
  return m;
}

}  // namespace test_column
