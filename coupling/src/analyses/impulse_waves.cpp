// Heller & Hager (2010) impact parameters and near-field wave (coupling/analyses/impulse_waves.hpp).
#include "coupling/analyses/impulse_waves.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sphslope/units.hpp"

namespace coupling {

bool ImpulseWave::inside_ranges() const {
  return std::all_of(groups.begin(), groups.end(), [](const ImpactGroup& g) { return g.inside(); });
}

ImpulseWave heller_hager_impulse_wave(const SlideImpact& impact, double g, double water_density) {
  if (!(impact.speed > 0 && impact.thickness > 0 && impact.mass_per_width > 0 && impact.depth > 0 && g > 0 &&
        water_density > 0))
    throw std::invalid_argument("impulse wave: speed, thickness, mass, depth, g and water density must be > 0");
  if (!(impact.angle_deg > 0 && impact.angle_deg <= 90))
    throw std::invalid_argument("impulse wave: the ramp angle must be in (0, 90] degrees");
  const double h = impact.depth;
  ImpulseWave w;
  w.F = impact.speed / std::sqrt(g * h);
  w.S = impact.thickness / h;
  w.M = impact.mass_per_width / (water_density * h * h);
  w.P = w.F * std::sqrt(w.S) * std::pow(w.M, 0.25) * std::sqrt(std::cos(6.0 / 7.0 * impact.angle_deg * sphslope::degree));
  w.crest_amplitude = 4.0 / 9.0 * std::pow(w.P, 0.8) * h;
  w.wave_height = 5.0 / 9.0 * std::pow(w.P, 0.8) * h;
  w.crest_position = 5.5 * std::sqrt(w.P) * h;
  w.period = 9.0 * std::sqrt(w.P) * std::sqrt(h / g);
  w.celerity = std::sqrt(g * (h + w.crest_amplitude));
  // VAW manual Table 3-2 (the 2-D equations' experiments)
  w.groups = {{"F", w.F, 0.86, 6.83},
              {"S", w.S, 0.09, 1.64},
              {"M", w.M, 0.11, 10.02},
              {"alpha_deg", impact.angle_deg, 30.0, 90.0},
              {"P", w.P, 0.17, 8.13}};
  return w;
}

}  // namespace coupling
