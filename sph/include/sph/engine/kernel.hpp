#pragma once
// 2-D smoothing kernels with support radius 2h.
//   W(r, h)           kernel value [1/m^2]
//   gradient_factor   F(r, h) = (dW/dr) / r, so that grad_i W_ij = F(r_ij) (x_i - x_j). Finite at r = 0.
// Both kernels are evaluated through q = r/h; a kernel object caches h-dependent constants.
#include <cmath>
#include <numbers>

#include "sphslope/names.hpp"

namespace sph {

enum class KernelType { cubic_spline, wendland_c2 };
// The kernels' names in scene files and reports.
inline constexpr sphslope::NameTable<KernelType, 2> kernel_names{
    {{"cubic_spline", KernelType::cubic_spline}, {"wendland_c2", KernelType::wendland_c2}}};

// Monaghan & Lattanzio (1985) cubic B-spline, 2-D normalisation 10/(7 pi h^2):
//   W = s [1 - 1.5 q^2 + 0.75 q^3] (0 <= q < 1),  s 0.25 (2 - q)^3 (1 <= q < 2),  0 otherwise.
// (The thesis prints the outer branch squared; the cube is correct.)
class CubicSplineKernel {
 public:
  explicit CubicSplineKernel(double h)
      : h_(h), inv_h_(1.0 / h), sigma_(10.0 / (7.0 * std::numbers::pi * h * h)) {}
  double h() const { return h_; }
  double support() const { return 2.0 * h_; }
  double value(double r) const {
    const double q = r * inv_h_;
    if (q < 1.0) return sigma_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0) { const double t = 2.0 - q; return sigma_ * 0.25 * t * t * t; }
    return 0.0;
  }
  double gradient_factor(double r) const {
    const double q = r * inv_h_;
    if (q < 1.0) return sigma_ * inv_h_ * inv_h_ * (-3.0 + 2.25 * q);
    if (q < 2.0) { const double t = 2.0 - q; return -0.75 * sigma_ * inv_h_ * t * t / r; }
    return 0.0;
  }

 private:
  double h_, inv_h_, sigma_;
};

// Wendland (1995) C2 kernel in 2-D with support 2h (Dehnen & Aly 2012 normalisation):
//   W = 7/(4 pi h^2) (1 - q/2)^4 (2q + 1),  0 <= q < 2;   F = -35/(4 pi h^4) (1 - q/2)^3.
class WendlandC2Kernel {
 public:
  explicit WendlandC2Kernel(double h)
      : h_(h), inv_h_(1.0 / h), sigma_(7.0 / (4.0 * std::numbers::pi * h * h)) {}
  double h() const { return h_; }
  double support() const { return 2.0 * h_; }
  double value(double r) const {
    const double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    const double t2 = t * t;
    return sigma_ * t2 * t2 * (2.0 * q + 1.0);
  }
  double gradient_factor(double r) const {
    const double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * sigma_ * inv_h_ * inv_h_ * t * t * t;
  }

 private:
  double h_, inv_h_, sigma_;
};

}  // namespace sph
