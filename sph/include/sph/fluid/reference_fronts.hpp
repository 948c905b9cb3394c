#pragma once
// Reference surge fronts of a dam break and the errors of a computed front against them: the tabulated front of
// Martin & Moyce (1952), n^2 = 2 (the one copy of the table in the project: the validation test, the isph stage's
// front figure and the study read it here), and Ritter's (1892) dry-bed front. Dimensionless variables as in
// Martin & Moyce: T = n t sqrt(g/a), Z = x/a with x from the back wall, a the column's width, n^2 a its height.
#include <span>
#include <vector>

namespace sph::fluid {

struct FrontPoint {
  double T = 0, Z = 0;  // n t sqrt(g/a), x_front / a
};

// Martin & Moyce (1952), n^2 = 2, a = 2.25 in = 0.05715 m: the 15 tabulated surge-front points, T from 0.41 to
// 3.33 (provenance in reference_fronts.cpp).
std::span<const FrontPoint> martin_moyce_1952_n2_2();
inline constexpr double martin_moyce_1952_n2_2_n = 1.4142135623730951;  // n = sqrt(2)

// Ritter's (1892) front on a dry bed: x_dam + 2 sqrt(g h0) t [m] (t [s], h0 the reservoir depth [m], g [m/s^2]).
double ritter_front_x(double dam_x, double depth, double g, double t);

// A computed front, T increasing, read between its samples by linear interpolation (held constant beyond them).
struct FrontSeries {
  std::vector<double> T, Z;
  double at(double T_at) const;
};

// The root-mean-square of Z_run(T_k + shift) / Z_k - 1 over the reference points with T_min <= T_k <= T_max
// (0 when there are none).
double front_rms_error(const FrontSeries& run, std::span<const FrontPoint> reference, double T_min, double T_max,
                       double shift = 0.0);

// The smallest of front_rms_error over the shifts 0, -step, -2 step, ... down to min_shift (< 0), with its shift.
struct ShiftedFrontError {
  double error = 0, shift = 0;
};
ShiftedFrontError best_shifted_front_error(const FrontSeries& run, std::span<const FrontPoint> reference,
                                           double T_min, double T_max, double min_shift, double step);

}  // namespace sph::fluid
