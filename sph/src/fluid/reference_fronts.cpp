#include "sph/fluid/reference_fronts.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace sph::fluid {

namespace {

// Martin & Moyce (1952), "An experimental study of the collapse of liquid columns on a rigid horizontal plane",
// Phil. Trans. R. Soc. Lond. A 244:312-324: surge-front positions of the n^2 = 2 column (width a = 2.25 in =
// 0.05715 m, height 2a), the paper's tabulated points (Tables 2 and 6).
// Provenance: the paper itself was not readable here; these are the arrays of TormodLandet/Ocellaris,
// scripts/plot_dam_break.py (commit 44fd559f), copied as numbers. The Z values sit on 0.25-inch steps (1/9 of a), the signature
// of readings at fixed stations. DualSPHysics' 01_DamBreak "Koshizuka & Oka 1996" file is the same data rescaled.
// Variables: T = n t sqrt(g/a) (n = sqrt(2)), Z = x_front / a with x measured from the back wall (Z(0) = 1).
constexpr std::array<FrontPoint, 15> martin_moyce_n2_2{{{0.41, 1.11},
                                                       {0.84, 1.22},
                                                       {1.19, 1.44},
                                                       {1.43, 1.67},
                                                       {1.63, 1.89},
                                                       {1.83, 2.11},
                                                       {1.98, 2.33},
                                                       {2.20, 2.56},
                                                       {2.32, 2.78},
                                                       {2.51, 3.00},
                                                       {2.65, 3.22},
                                                       {2.83, 3.44},
                                                       {2.98, 3.67},
                                                       {3.11, 3.89},
                                                       {3.33, 4.11}}};

}  // namespace

std::span<const FrontPoint> martin_moyce_1952_n2_2() { return martin_moyce_n2_2; }

double ritter_front_x(double dam_x, double depth, double g, double t) {
  return dam_x + 2.0 * std::sqrt(g * std::max(depth, 0.0)) * t;
}

double FrontSeries::at(double T_at) const {
  if (T.empty()) return 0.0;
  if (T_at <= T.front()) return Z.front();
  const auto it = std::upper_bound(T.begin(), T.end(), T_at);
  if (it == T.end()) return Z.back();
  const auto k = static_cast<std::size_t>(it - T.begin());
  const double w = (T_at - T[k - 1]) / (T[k] - T[k - 1]);
  return Z[k - 1] + w * (Z[k] - Z[k - 1]);
}

double front_rms_error(const FrontSeries& run, std::span<const FrontPoint> reference, double T_min, double T_max,
                       double shift) {
  double sum = 0;
  int n = 0;
  for (const FrontPoint& p : reference) {
    if (p.T < T_min || p.T > T_max) continue;
    const double e = run.at(p.T + shift) / p.Z - 1.0;
    sum += e * e;
    ++n;
  }
  return n > 0 ? std::sqrt(sum / n) : 0.0;
}

ShiftedFrontError best_shifted_front_error(const FrontSeries& run, std::span<const FrontPoint> reference,
                                           double T_min, double T_max, double min_shift, double step) {
  ShiftedFrontError best{front_rms_error(run, reference, T_min, T_max), 0.0};
  const int steps = static_cast<int>(std::floor(-min_shift / step + 1e-9));
  for (int k = 1; k <= steps; ++k) {
    const double shift = -step * k;
    const double e = front_rms_error(run, reference, T_min, T_max, shift);
    if (e < best.error) best = {e, shift};
  }
  return best;
}

}  // namespace sph::fluid
