#include "sph/particles.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace sph {

void Particles::add(double px, double py, double particle_mass, double density, std::uint16_t material_id,
                    ParticleKind particle_kind, double normal_x, double normal_y) {
  if (size() >= std::numeric_limits<std::uint32_t>::max()) throw std::length_error("too many particles");
  const auto new_id = static_cast<std::uint32_t>(size());
  for_each_double_array([](std::vector<double>& a) { a.push_back(0.0); });
  const std::size_t i = size() - 1;
  x[i] = px; y[i] = py; x0[i] = px; y0[i] = py;
  mass[i] = particle_mass;
  rho[i] = density;
  wall_nx[i] = normal_x;
  wall_ny[i] = normal_y;
  id.push_back(new_id);
  material.push_back(material_id);
  kind.push_back(static_cast<std::uint8_t>(particle_kind));
}

void Particles::reserve(std::size_t n) {
  for_each_array([n](auto& a) { a.reserve(n); });
}

std::size_t Particles::count(ParticleKind k) const {
  return static_cast<std::size_t>(std::count(kind.begin(), kind.end(), static_cast<std::uint8_t>(k)));
}

}  // namespace sph
