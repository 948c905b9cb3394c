// The monitors of a particle flow in a tank (coupling/analyses/tank_monitors.hpp).
#include "coupling/analyses/tank_monitors.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace coupling {

namespace {
constexpr std::uint8_t kTankMoving = 0;  // kind 0: the physics' moving material (fluid, sediment)
}

double surface_at(const sph::ParticleSet& p, double x, double dx, double floor) {
  double surface = floor;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == kTankMoving && std::abs(p.x[i] - x) < dx) surface = std::max(surface, p.y[i] + 0.5 * dx);
  return surface;
}

double front_of(const sph::ParticleSet& p, double dx) {
  double front = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == kTankMoving) front = std::max(front, p.x[i] + 0.5 * dx);
  return front;
}

double farthest_in_contact(std::vector<double> xs, double gap) {
  std::sort(xs.begin(), xs.end(), std::greater<>());
  for (std::size_t k = 0; k + 1 < xs.size(); ++k)
    if (xs[k] - xs[k + 1] <= gap) return xs[k];
  return xs.back();
}

double contact_front(const sph::ParticleSet& p, double dx) {
  std::vector<double> xs;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == kTankMoving) xs.push_back(p.x[i]);
  if (xs.empty()) return -std::numeric_limits<double>::infinity();
  return farthest_in_contact(std::move(xs), 1.5 * dx) + 0.5 * dx;
}

TankMonitorObserver::TankMonitorObserver(const TankMonitors& monitors, const Tank& tank, double dx)
    : monitors_(monitors), tank_(tank), dx_(dx) {
  for (const Gauge& g : monitors.gauges) table_.columns.push_back(g.name + "_m");
  if (monitors.front) table_.columns.push_back("front_x_m");
  if (monitors.wall_height) table_.columns.push_back("wall_height_m");
}

std::string TankMonitorObserver::after_step(const sph::ParticleSet& p, const sph::RunState& state,
                                            const sph::Energies&) {
  if (state.time + 1e-12 >= next_) sample(p, state.time);
  return {};
}

void TankMonitorObserver::restore(const std::string& csv, double time) {
  if (!restore_rows(table_, csv, time)) return;
  next_ = (std::floor(table_.times.back() / monitors_.interval + 1e-9) + 1.0) * monitors_.interval;
}

void TankMonitorObserver::sample(const sph::ParticleSet& p, double time) {
  std::vector<double> row;
  for (const Gauge& g : monitors_.gauges) row.push_back(surface_at(p, g.x, dx_, tank_.y_min) - monitors_.still_water);
  if (monitors_.front) row.push_back(front_of(p, dx_));
  // the first column of the lattice against the left wall has its centres at x_min + dx/2
  if (monitors_.wall_height) row.push_back(surface_at(p, tank_.x_min + 0.5 * dx_, dx_, tank_.y_min) - tank_.y_min);
  table_.times.push_back(time);
  table_.rows.push_back(std::move(row));
  next_ = (std::floor(time / monitors_.interval + 1e-9) + 1.0) * monitors_.interval;  // on the interval grid
}

}  // namespace coupling
