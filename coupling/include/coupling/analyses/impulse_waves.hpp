#pragma once
// A slide's impact parameters and the impulse wave they predict in a 2-D channel: Heller & Hager (2010), "Impulse
// product parameter in landslide generated impulse waves", J. Waterway, Port, Coastal, Ocean Eng. 136(3), and the
// VAW manual (Heller, Hager & Minor 2009, VAW-Mitteilung 211; 2nd ed. Evers et al. 2019, VAW-Mitteilung 254), Eqs.
// 3.12-3.18, with the validity ranges of its Table 3-2 (docs/coupled.md, "Impact parameters").
#include <string>
#include <vector>

namespace coupling {

// What the slide is at impact (per metre of channel width).
struct SlideImpact {
  double speed = 0;           // v_s: the slide centroid's speed [m/s]
  double thickness = 0;       // s: the slide's thickness normal to the ramp [m]
  double mass_per_width = 0;  // m_s / b: the slide's bulk mass per metre width [kg/m]
  double angle_deg = 0;       // alpha: the ramp's angle to the horizontal [deg]
  double depth = 0;           // h: the still-water depth [m]
};

// One dimensionless group against its range in Table 3-2.
struct ImpactGroup {
  std::string name;  // "F", "S", "M", "alpha_deg", "P"
  double value = 0, low = 0, high = 0;
  bool inside() const { return value >= low && value <= high; }
};

struct ImpulseWave {
  double F = 0, S = 0, M = 0, P = 0;  // v_s / sqrt(g h); s / h; m_s / (rho_w b h^2); Eq. 3.12
  double crest_amplitude = 0;         // a_M = (4/9) P^(4/5) h [m]
  double wave_height = 0;             // H_M = (5/9) P^(4/5) h [m]
  double crest_position = 0;          // x_M = (11/2) P^(1/2) h, from the impact (shore) line [m]
  double period = 0;                  // T_M = 9 P^(1/2) (h / g)^(1/2) [s]
  double celerity = 0;                // c = [g (h + a_M)]^(1/2) [m/s]
  std::vector<ImpactGroup> groups;    // F, S, M, alpha and P with their ranges
  bool inside_ranges() const;
};

// The impulse product parameter P = F S^(1/2) M^(1/4) cos(6 alpha / 7)^(1/2) and the near-field wave it predicts.
// Throws std::invalid_argument unless speed, thickness, mass, depth, g and water_density are > 0 and 0 < alpha <= 90.
ImpulseWave heller_hager_impulse_wave(const SlideImpact& impact, double g, double water_density);

}  // namespace coupling
