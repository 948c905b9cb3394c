#include "sph/coupled/exchange.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace sph::coupled {

namespace {

constexpr auto kMaterial = static_cast<std::uint8_t>(ParticleKind::material);
// The water table's average reaches this many columns to each side (a tent, weights 5, 4, ..., 1): the free-surface
// particles' heights jitter from column to column by about a millimetre at rest, and a table that follows them
// pushed the soil below sideways (gamma_w times the table's slope, the same at every depth) at 19 mm/s in the still
// test, 0.7 mm/s with this average (test_coupled.cpp). A wave shorter than eight spacings is not resolved by the
// ISPH anyway, and its pressure fades within a fraction of its length below the surface.
constexpr std::size_t kReach = 4;

}  // namespace

SoilBoundary::SoilBoundary(fluid::Model& water, const soil::Model& soil) {
  const double dx_w = water.settings.particle_spacing, dx_s = soil.settings.particle_spacing;
  if (!(std::abs(dx_w - dx_s) <= 1e-12 * dx_w)) {
    std::ostringstream os;
    os << "coupled run: the soil's particle spacing (" << dx_s << " m) must equal the water's (" << dx_w << " m)";
    throw std::invalid_argument(os.str());
  }
  ParticleSet& p = water.particles;
  const bool present = p.find_field(id_field).has_value();
  soil_id_ = p.add_field({id_field, true, false});
  // the soil's accelerations, set with its positions (step workspace: the soil's rates are in its checkpoint)
  acceleration_x_ = p.add_field({fluid::coupled_wall_acceleration_x, false, false});
  acceleration_y_ = p.add_field({fluid::coupled_wall_acceleration_y, false, false});
  if (present) {
    for (std::size_t i = 0; i < p.size(); ++i) count_ += p.material[i] == fluid::coupled_wall_material ? 1 : 0;
    return;
  }
  const ParticleSet& s = soil.particles;
  const double mass = water.settings.particle_mass(), rho0 = water.settings.rest_density;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.kind[i] != kMaterial) continue;
    const std::size_t k = p.add(s.x[i], s.y[i], mass, rho0, fluid::coupled_wall_material, ParticleKind::wall);
    p.field(soil_id_)[k] = static_cast<double>(s.id[i]);
    ++count_;
  }
  update(water, soil);
}

namespace {

// Calls visit(k, i) for every twin k in the water's set and its soil particle i.
template <class Visit>
void for_each_twin(const ParticleSet& water, FieldId soil_id, const ParticleSet& s, Visit&& visit) {
  std::vector<std::size_t> index_of;  // soil index by soil id
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.id[i] >= index_of.size()) index_of.resize(s.id[i] + 1, s.size());
    index_of[s.id[i]] = i;
  }
  const double* id = water.field(soil_id).data();
  for (std::size_t k = 0; k < water.size(); ++k) {
    if (water.material[k] != fluid::coupled_wall_material || water.kind[k] == kMaterial) continue;
    const auto sid = static_cast<std::size_t>(id[k]);
    if (sid >= index_of.size() || index_of[sid] == s.size())
      throw std::logic_error("coupled run: a soil twin in the water refers to no soil particle");
    visit(k, index_of[sid]);
  }
}

}  // namespace

void SoilBoundary::take_forces(const fluid::Model& water, const std::vector<double>& fx,
                               const std::vector<double>& fy, soil::Model& soil, FieldId force_x,
                               FieldId force_y) const {
  std::vector<double>& sx = soil.particles.field(force_x);
  std::vector<double>& sy = soil.particles.field(force_y);
  std::fill(sx.begin(), sx.end(), 0.0);
  std::fill(sy.begin(), sy.end(), 0.0);
  if (fx.empty()) return;
  for_each_twin(water.particles, soil_id_, soil.particles, [&](std::size_t k, std::size_t i) {
    sx[i] = fx[k];
    sy[i] = fy[k];
  });
}

void SoilBoundary::update(fluid::Model& water, const soil::Model& soil) const {
  const ParticleSet& s = soil.particles;
  ParticleSet& p = water.particles;
  const std::vector<double>& soil_ax = s.field(soil.fields.ax);  // dv/dt of its last evaluation
  const std::vector<double>& soil_ay = s.field(soil.fields.ay);
  double* ax = p.field(acceleration_x_).data();
  double* ay = p.field(acceleration_y_).data();
  for_each_twin(p, soil_id_, s, [&](std::size_t k, std::size_t i) {
    p.x[k] = s.x[i];
    p.y[k] = s.y[i];
    p.vx[k] = s.vx[i];
    p.vy[k] = s.vy[i];
    ax[k] = soil_ax[i];
    ay[k] = soil_ay[i];
  });
}

std::optional<soil::PiezometricLine> water_table(const fluid::Model& water) {
  const ParticleSet& p = water.particles;
  const double dx = water.settings.particle_spacing;
  std::map<long long, double> top;  // column -> the highest fluid particle's y
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != kMaterial) continue;
    const auto c = static_cast<long long>(std::floor(p.x[i] / dx));
    auto it = top.find(c);
    if (it == top.end())
      top.emplace(c, p.y[i]);
    else if (p.y[i] > it->second)
      it->second = p.y[i];
  }
  if (top.empty()) return std::nullopt;
  soil::PiezometricLine line;
  line.unit_weight = water.settings.rest_density * std::hypot(water.settings.gravity_x, water.settings.gravity_y);
  std::vector<long long> cols;
  std::vector<double> heights;
  for (const auto& [c, y] : top) {
    cols.push_back(c);
    heights.push_back(y);
  }
  for (std::size_t k = 0; k < cols.size(); ++k) {  // a tent average over the neighbouring columns that hold water
    double sum = 0, weight = 0;
    for (std::size_t j = k >= kReach ? k - kReach : 0; j < cols.size() && j <= k + kReach; ++j) {
      const auto d = std::llabs(cols[j] - cols[k]);
      if (d > static_cast<long long>(kReach)) continue;
      const double w = static_cast<double>(kReach + 1) - static_cast<double>(d);
      sum += w * heights[j];
      weight += w;
    }
    line.x.push_back((static_cast<double>(cols[k]) + 0.5) * dx);
    line.y.push_back(sum / weight);
  }
  if (line.x.size() == 1) {  // one column: level across it
    line.x = {line.x[0] - 0.5 * dx, line.x[0] + 0.5 * dx};
    line.y.push_back(line.y[0]);
  }
  return line;
}

}  // namespace sph::coupled
