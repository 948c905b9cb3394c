#include "sph/soil/benchmarks.hpp"

#include <algorithm>
#include <cmath>

#include "sph/engine/fill.hpp"
#include "sph/engine/neighbour_search.hpp"

namespace sph::soil {

Material aluminium_bars() {
  Material al;
  al.name = "aluminium bars (Bui et al. 2008)";
  al.density = 2650.0;
  al.youngs_modulus = 0.84e6;
  al.poisson_ratio = 0.3;
  al.cohesion = 0.0;
  al.friction_angle_deg = 19.8;
  al.dilatancy_angle_deg = 0.0;
  return al;
}

Model make_column_collapse(const ColumnCollapseCase& c) {
  Model m;
  const Material al = aluminium_bars();
  m.materials.push_back(al);
  Settings& s = m.settings;
  s.particle_spacing = c.dx;
  s.h_over_dx = c.h_over_dx;
  s.kernel = c.kernel;
  s.end_time = c.end_time;
  s.wall_slip = c.wall_slip;
  s.gravity_mode = GravityMode::sudden;
  const auto pts = lattice_points_in_region(0.0, 0.0, c.length, c.height, c.dx, [](double, double) { return true; });
  add_soil(m.particles, pts, c.dx, 0, al.density);
  BoxWalls box;
  box.x_min = 0.0;
  box.x_max = c.floor_length;
  box.y_min = 0.0;
  box.height = c.height * 1.2;
  add_box_walls(m.particles, box, c.dx, s.smoothing_length(), 0, al.density);
  return m;
}

DepositShape measure_deposit(const Model& model, double floor_y, double back_wall_x) {
  const ParticleSet& p = model.particles;
  const double dx = model.settings.particle_spacing;
  std::vector<double> xs, ys;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == 0) {
      xs.push_back(p.x[i]);
      ys.push_back(p.y[i]);
    }
  CellList cells;
  cells.build(xs.data(), ys.data(), xs.size(), 1.5 * dx);
  std::vector<double> sx(xs.size()), sy(ys.size());
  for (std::size_t k = 0; k < xs.size(); ++k) {
    sx[k] = xs[cells.order()[k]];
    sy[k] = ys[cells.order()[k]];
  }
  DepositShape d;
  const double r2 = 2.25 * dx * dx;
  for (std::size_t i = 0; i < sx.size(); ++i) {
    int nb = 0;
    cells.for_each_candidate(i, [&](std::uint32_t j) {
      const double ddx = sx[i] - sx[j], ddy = sy[i] - sy[j];
      if (j != i && ddx * ddx + ddy * ddy < r2) ++nb;
    });
    if (nb < 2) continue;
    d.runout = std::max(d.runout, sx[i] + 0.5 * dx - back_wall_x);
    d.height = std::max(d.height, sy[i] + 0.5 * dx - floor_y);
  }
  return d;
}

}  // namespace sph::soil
