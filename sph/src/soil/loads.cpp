#include "sph/soil/loads.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

namespace sph::soil {

namespace {

// Index k of the segment [x[k], x[k+1]] holding px (clamped to the ends).
std::size_t segment_of(const std::vector<double>& x, double px) {
  const auto it = std::upper_bound(x.begin(), x.end(), px);
  const auto k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - x.begin() - 1, 0));
  return std::min(k, x.size() - 2);
}

// A surface force is spread over the topmost particles of its column with these weights (see loads.hpp).
constexpr std::size_t kSpreadRows = 3;
constexpr double kSpreadWeights[kSpreadRows] = {0.25, 0.5, 0.25};

}  // namespace

double PiezometricLine::height(double px) const {
  if (px <= x.front()) return y.front();
  if (px >= x.back()) return y.back();
  const std::size_t k = segment_of(x, px);
  const double t = (px - x[k]) / (x[k + 1] - x[k]);
  return y[k] + t * (y[k + 1] - y[k]);
}

double PiezometricLine::pressure(double px, double py) const {
  const double head = height(px) - py;
  return head > 0.0 ? unit_weight * head : 0.0;
}

void PiezometricLine::gradient(double px, double py, double& gx, double& gy) const {
  gx = gy = 0.0;
  if (!(height(px) > py)) return;
  double slope = 0.0;
  if (px > x.front() && px < x.back()) {
    const std::size_t k = segment_of(x, px);
    slope = (y[k + 1] - y[k]) / (x[k + 1] - x[k]);
  }
  gx = unit_weight * slope;
  gy = -unit_weight;
}

std::string PiezometricLine::error() const {
  if (x.size() != y.size()) return "the line's x and y lists differ in length";
  if (x.size() < 2) return "the line needs at least 2 vertices";
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!std::isfinite(x[k]) || !std::isfinite(y[k])) return "vertex " + std::to_string(k) + " is not finite";
    if (k > 0 && !(x[k] > x[k - 1])) return "x must increase strictly (vertex " + std::to_string(k) + ")";
  }
  if (!(std::isfinite(unit_weight) && unit_weight > 0)) return "the unit weight of water must be > 0";
  return {};
}

namespace {

// The soil particles of each lattice column, columns numbered from the leftmost soil particle (x_min); registers
// the surface-force fields on first use.
std::map<long long, std::vector<std::size_t>> soil_columns(ParticleSet& p, SoilLoads& loads, double dx, double& x_min) {
  if (!loads.surface_force_x) {
    loads.surface_force_x = p.add_field({"surface_force_x", true, false});
    loads.surface_force_y = p.add_field({"surface_force_y", true, false});
  }
  x_min = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::material)) x_min = std::min(x_min, p.x[i]);
  std::map<long long, std::vector<std::size_t>> columns;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::material))
      columns[static_cast<long long>(std::floor((p.x[i] - x_min) / dx + 0.5))].push_back(i);
  return columns;
}

// The force (fx, fy) on a column's three topmost particles in the proportions 1/4, 1/2, 1/4. Returns how many.
std::size_t spread_on_column(ParticleSet& p, const SoilLoads& loads, std::vector<std::size_t>& members, double fx,
                             double fy) {
  const std::size_t n = std::min<std::size_t>(members.size(), kSpreadRows);
  std::partial_sort(members.begin(), members.begin() + static_cast<std::ptrdiff_t>(n), members.end(),
                    [&](std::size_t a, std::size_t b) { return p.y[a] > p.y[b] || (p.y[a] == p.y[b] && p.id[a] < p.id[b]); });
  double total = 0.0;
  for (std::size_t k = 0; k < n; ++k) total += kSpreadWeights[k];
  std::vector<double>& field_x = p.field(*loads.surface_force_x);
  std::vector<double>& field_y = p.field(*loads.surface_force_y);
  for (std::size_t k = 0; k < n; ++k) {
    if (fx != 0.0) field_x[members[k]] += fx * kSpreadWeights[k] / total;
    field_y[members[k]] += fy * kSpreadWeights[k] / total;
  }
  return n;
}

}  // namespace

std::size_t add_strip_load(ParticleSet& p, SoilLoads& loads, double from_x, double to_x, double pressure, double dx,
                           double pressure_end) {
  double x_min = 0.0;
  auto columns = soil_columns(p, loads, dx, x_min);
  const double slope = std::isnan(pressure_end) ? 0.0 : (pressure_end - pressure) / (to_x - from_x);
  std::size_t loaded = 0;
  for (auto& [column, members] : columns) {
    const double centre = x_min + static_cast<double>(column) * dx;
    const double lo = std::max(from_x, centre - 0.5 * dx), hi = std::min(to_x, centre + 0.5 * dx);
    const double overlap = hi - lo;
    if (!(overlap > 0.0)) continue;
    // the pressure at the overlap's middle times its width: exact for a linear pressure
    const double q = slope == 0.0 ? pressure : pressure + slope * (0.5 * (lo + hi) - from_x);
    loaded += spread_on_column(p, loads, members, 0.0, -(q * overlap));
  }
  return loaded;
}

std::size_t add_line_load(ParticleSet& p, SoilLoads& loads, double x, double force_x, double force_y, double dx) {
  double x_min = 0.0;
  auto columns = soil_columns(p, loads, dx, x_min);
  const auto centre = static_cast<long long>(std::floor((x - x_min) / dx + 0.5));
  // The column under x and its two neighbours in the proportions 1/4, 1/2, 1/4 (on one column alone the rows below
  // alternate by about +-7 % of the closed form); a missing neighbour's share goes to the others.
  const long long offsets[] = {-1, 0, 1};
  const double shares[] = {0.25, 0.5, 0.25};
  double total = 0.0;
  for (int k = 0; k < 3; ++k)
    if (columns.count(centre + offsets[k])) total += shares[k];
  std::size_t loaded = 0;
  for (int k = 0; k < 3; ++k) {
    const auto found = columns.find(centre + offsets[k]);
    if (found == columns.end()) continue;
    loaded += spread_on_column(p, loads, found->second, force_x * shares[k] / total, force_y * shares[k] / total);
  }
  return loaded;
}

}  // namespace sph::soil
