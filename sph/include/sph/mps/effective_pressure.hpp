#pragma once
// The "static" effective pressure of the yield criterion (seed eqs. 18-19, option A of section 2.9), the paper's
// comparison against its smoothed EOS pressure (eq. 20, sph::mps::smoothed_pressure): the weight of the granular
// material above each particle. SI units, 2-D.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/engine/particle_set.hpp"

namespace sph::mps {

// [M24] eq. 19: h_i = max(y_j) - y_i over the particles j with |x_j - x_i| < strip_half_width (the paper's delta-l,
// A10: the spacing by default) that define the granular surface (surface[j] != 0: the paper's phi_j > 0.5, to be
// decided with the phases, A10), i included when it counts itself [m]; 0 if no such particle is in the strip or
// all lie below i. Particles are binned by x in strips of that width, so the cost is the set times the particles of
// three strips.
std::vector<double> depth_below_surface(const ParticleSet& set, const std::vector<std::uint8_t>& surface,
                                        double strip_half_width);

// depth_below_surface for one particle at a time: the surface particles binned by x in strips once, then depth(i)
// of any particle of the set (a const read, so threads may ask at once) [m]. For a pass that needs the depth of a
// few particles only (the thin layers of EffectivePressure::smoothed_thin_layer). The set must not move meanwhile.
class SurfaceStrips {
 public:
  SurfaceStrips(const ParticleSet& set, const std::vector<std::uint8_t>& surface, double strip_half_width);
  double depth(std::size_t i) const;

 private:
  long strip_of(double x) const;
  const ParticleSet& set_;
  double half_width_ = 0, x_min_ = 0;
  std::vector<std::vector<std::size_t>> strips_;  // the surface particles of each strip
};

// [M25] eq. 18: p'_i = rho_b g h_i [Pa] with the bulk density rho_b [kg/m^3] and |g| [m/s^2].
inline double hydrostatic_pressure(double bulk_density, double gravity, double depth) {
  return bulk_density * gravity * depth;
}

}  // namespace sph::mps
