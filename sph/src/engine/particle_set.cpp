#include "sph/engine/particle_set.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace sph {

namespace {
constexpr std::string_view core_names[] = {"x", "y", "vx", "vy", "density", "mass", "x0", "y0", "id", "material",
                                           "kind"};
}  // namespace

std::size_t ParticleSet::add(double px, double py, double particle_mass, double density, std::uint16_t material_id,
                             ParticleKind particle_kind) {
  if (size() >= std::numeric_limits<std::uint32_t>::max()) throw std::length_error("too many particles");
  const auto new_id = static_cast<std::uint32_t>(size());
  for_each_double_array([](std::vector<double>& a) { a.push_back(0.0); });
  const std::size_t i = size() - 1;
  x[i] = px;
  y[i] = py;
  x0[i] = px;
  y0[i] = py;
  mass[i] = particle_mass;
  rho[i] = density;
  id.push_back(new_id);
  material.push_back(material_id);
  kind.push_back(static_cast<std::uint8_t>(particle_kind));
  return i;
}

void ParticleSet::reserve(std::size_t n) {
  for_each_array([n](auto& a) { a.reserve(n); });
}

std::size_t ParticleSet::remove(const std::vector<std::uint8_t>& drop) {
  if (drop.size() != size()) throw std::invalid_argument("ParticleSet::remove: one flag per particle expected");
  const std::size_t n = size();
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) kept += drop[i] == 0;
  if (kept == n) return 0;
  for_each_array([&](auto& a) {
    std::size_t at = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (drop[i] == 0) a[at++] = a[i];
    a.resize(kept);
  });
  return n - kept;
}

std::size_t ParticleSet::count(ParticleKind k) const {
  return static_cast<std::size_t>(std::count(kind.begin(), kind.end(), static_cast<std::uint8_t>(k)));
}

double ParticleSet::total_mass(ParticleKind k) const {
  double m = 0;
  for (std::size_t i = 0; i < size(); ++i)
    if (kind[i] == static_cast<std::uint8_t>(k)) m += mass[i];
  return m;
}

FieldId ParticleSet::add_field(const FieldSpec& spec) {
  if (std::find(std::begin(core_names), std::end(core_names), spec.name) != std::end(core_names))
    throw std::invalid_argument("particle field '" + spec.name + "' clashes with a core field");
  if (const auto existing = find_field(spec.name)) {
    const FieldSpec& old = specs_[*existing];
    if (old.checkpoint != spec.checkpoint || old.write_vtu != spec.write_vtu)
      throw std::invalid_argument("particle field '" + spec.name + "' registered twice with different options");
    return *existing;
  }
  specs_.push_back(spec);
  fields_.emplace_back(size(), 0.0);
  fields_.back().reserve(x.capacity());
  return static_cast<FieldId>(fields_.size() - 1);
}

std::optional<FieldId> ParticleSet::find_field(std::string_view name) const {
  for (std::size_t k = 0; k < specs_.size(); ++k)
    if (specs_[k].name == name) return static_cast<FieldId>(k);
  return std::nullopt;
}

}  // namespace sph
