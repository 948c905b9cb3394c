// What the isph stage measures on the particles (coupling/analyses/isph_measures.hpp).
#include "coupling/analyses/isph_measures.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "coupling/scene/json_reader.hpp"
#include "sph/engine/kernel.hpp"

namespace coupling {

namespace {
constexpr std::uint8_t kFluid = 0;
}

std::size_t fluid_past_walls(const sph::ParticleSet& p, const Tank& tank, double dx) {
  const double half = 0.5 * dx;
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == kFluid && (p.x[i] < tank.x_min - half || p.x[i] > tank.x_max + half || p.y[i] < tank.y_min - half))
      ++n;
  return n;
}

std::string WallCrossingObserver::after_step(const sph::ParticleSet& p, const sph::RunState& state,
                                             const sph::Energies&) {
  const std::size_t n = fluid_past_walls(p, tank_, dx_);
  most_ = std::max(most_, n);
  if (n > 0 && !first_time_) first_time_ = state.time;
  return {};
}

void WallCrossingObserver::restore(std::size_t most, std::optional<double> first_time) {
  most_ = most;
  first_time_ = first_time;
}

IsphSnapshot take_snapshot(const sph::ParticleSet& p, sph::FieldId pressure, double time, double dx) {
  IsphSnapshot s;
  s.time = time;
  s.spacing = dx;
  s.x = p.x;
  s.y = p.y;
  s.pressure = p.field(pressure);
  s.kind = p.kind;
  return s;
}

SnapshotObserver::SnapshotObserver(std::vector<double> times, sph::FieldId pressure, double dx, Writer write)
    : times_(std::move(times)), pressure_(pressure), dx_(dx), write_(std::move(write)) {}

std::string SnapshotObserver::after_step(const sph::ParticleSet& p, const sph::RunState& state,
                                         const sph::Energies&) {
  while (next_ < times_.size() && state.time + 1e-12 >= times_[next_]) {
    if (write_) files_.push_back(write_(times_[next_], take_snapshot(p, pressure_, state.time, dx_)));
    ++next_;
  }
  return {};
}

void SnapshotObserver::restore(double time, std::vector<std::string> earlier) {
  while (next_ < times_.size() && times_[next_] <= time + 1e-12) ++next_;
  files_ = std::move(earlier);
}

namespace {

// The kernel sum of a lattice particle over its neighbours (a, b) dx away with b <= rows_up_to (0: nothing above
// it, the top row; 1: one row above it), lengths in units of dx (the kernel's h is h/dx).
template <class Kernel>
double half_lattice_sum(const Kernel& kernel, int rows_up_to) {
  const int reach = static_cast<int>(std::ceil(kernel.support())) + 1;
  double sum = 0;
  for (int a = -reach; a <= reach; ++a)
    for (int b = -reach; b <= std::min(rows_up_to, reach); ++b) sum += kernel.value(std::hypot(a, b));
  return sum;
}

template <class Kernel>
SurfaceRows rows_of(const Kernel& kernel) {
  const double full = half_lattice_sum(kernel, 1 << 20);
  return {half_lattice_sum(kernel, 0) / full, half_lattice_sum(kernel, 1) / full};
}

}  // namespace

SurfaceRows surface_row_kernel_sums(sph::KernelType kernel, double h_over_dx) {
  if (kernel == sph::KernelType::wendland_c2) return rows_of(sph::WendlandC2Kernel(h_over_dx));
  return rows_of(sph::CubicSplineKernel(h_over_dx));
}

std::optional<StillTankCheck> still_tank_check(const sph::fluid::Model& model, const IsphAnalysis& a) {
  if (a.water.size() != 1) return std::nullopt;
  const TankRectangle& w = a.water.front();
  const double dx = a.settings.particle_spacing, tol = 1e-9 * std::max(1.0, a.tank.x_max - a.tank.x_min);
  if (std::abs(w.x_min - a.tank.x_min) > tol || std::abs(w.x_max - a.tank.x_max) > tol ||
      std::abs(w.y_min - a.tank.y_min) > tol)
    return std::nullopt;
  const sph::ParticleSet& p = model.particles;
  const sph::fluid::ConstArrays f = model.arrays();
  const double g = std::hypot(a.settings.gravity_x, a.settings.gravity_y), rho_g = a.settings.rest_density * g;
  StillTankCheck c;
  c.depth = w.y_max - w.y_min;
  c.rho_g_depth = rho_g * c.depth;
  c.expected_ratio = 1.0 - 0.5 * dx / c.depth;
  c.celerity = std::sqrt(g * c.depth);
  double n = 0, sy = 0, sp = 0, syy = 0, syp = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != kFluid) continue;
    c.max_speed_end = std::max(c.max_speed_end, std::hypot(p.vx[i], p.vy[i]));
    if (f.free_surface[i] != 0.0) continue;
    const double y = p.y[i] - a.tank.y_min, pr = f.pressure[i];
    n += 1;
    sy += y;
    sp += pr;
    syy += y * y;
    syp += y * pr;
  }
  const double det = n * syy - sy * sy;
  if (n < 2 || !(det > 0)) return std::nullopt;
  const double slope = (n * syp - sy * sp) / det;
  c.floor_pressure = (sp - slope * sy) / n;  // the line at y = the floor
  c.gradient_ratio = -slope / rho_g;
  return c;
}

std::string snapshot_file_name(double requested_time) {
  return "isph_snapshot_" + format_number(requested_time) + "s.svg";
}

}  // namespace coupling
