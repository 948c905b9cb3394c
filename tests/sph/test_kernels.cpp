// Kernel normalisation and gradient consistency on a regular lattice, and the cell-list search
// against brute force. Reference: the SPH consistency conditions (Liu & Liu 2003, ch. 3):
//   sum_j V_j W_ij = 1  and  sum_j V_j (x_j - x_i) (x) grad_i W_ij = I  (with grad_i W = F (x_i - x_j), F < 0).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "sph/engine/kernel.hpp"
#include "sph/engine/neighbour_search.hpp"

namespace test_kernels {

namespace {

template <class Kernel>
void check_lattice(double h_over_dx) {
  const double dx = 0.01, h = h_over_dx * dx;
  const Kernel k(h);
  double sum_w = 0, mxx = 0, mxy = 0, myx = 0, myy = 0;
  const int n = 6;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      const double xj = (i + 0.3) * dx, yj = (j - 0.2) * dx;  // lattice offset from the evaluation point
      const double r = std::hypot(xj, yj);
      const double V = dx * dx;
      sum_w += V * k.value(r);
      const double F = k.gradient_factor(r);
      const double gx = F * (0 - xj), gy = F * (0 - yj);  // grad_i W with x_i = origin
      mxx += V * xj * gx;
      mxy += V * xj * gy;
      myx += V * yj * gx;
      myy += V * yj * gy;
    }
  INFO("h/dx = " << h_over_dx << " sum W V = " << sum_w << " M = [" << mxx << ", " << mxy << "; " << myx << ", " << myy << "]");
  CHECK(std::fabs(sum_w - 1.0) < 1e-3);
  CHECK(std::fabs(mxx - 1.0) < 0.03);
  CHECK(std::fabs(myy - 1.0) < 0.03);
  CHECK(std::fabs(mxy) < 0.02);
  CHECK(std::fabs(myx) < 0.02);
}

template <class Kernel>
void check_integral(double h) {
  // integral of W over the plane = 1 (fine quadrature), independent of the lattice
  const Kernel k(h);
  double s = 0;
  const int n = 4000;
  const double R = 2 * h, dr = R / n;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) * dr;
    s += 2 * 3.14159265358979323846 * r * k.value(r) * dr;
  }
  CHECK(std::fabs(s - 1.0) < 1e-6);
  // gradient factor consistent with the derivative of the value
  for (double q : {0.1, 0.5, 0.99, 1.01, 1.5, 1.9}) {
    const double r = q * h, e = 1e-7 * h;
    const double dwdr = (k.value(r + e) - k.value(r - e)) / (2 * e);
    CHECK(k.gradient_factor(r) * r == Approx(dwdr).epsilon(1e-5));
  }
}

}  // namespace

TEST_CASE("cubic spline: unit integral, derivative, lattice normalisation and gradient consistency", "[sph][kernel]") {
  check_integral<sph::CubicSplineKernel>(0.013);
  check_lattice<sph::CubicSplineKernel>(1.3);
  check_lattice<sph::CubicSplineKernel>(1.5);
  check_lattice<sph::CubicSplineKernel>(1.2);
}

TEST_CASE("Wendland C2: unit integral, derivative, lattice normalisation and gradient consistency", "[sph][kernel]") {
  check_integral<sph::WendlandC2Kernel>(0.013);
  check_lattice<sph::WendlandC2Kernel>(1.5);
  check_lattice<sph::WendlandC2Kernel>(2.0);
}

TEST_CASE("cell-list neighbour search equals brute force on random points", "[sph][neighbours]") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> ux(-0.3, 0.7), uy(0.0, 0.25);
  const std::size_t n = 3000;
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) { x[i] = ux(rng); y[i] = uy(rng); }
  x[7] = x[8];  // coincident coordinates / duplicates must not break anything
  y[7] = y[8];
  const double radius = 0.024;
  sph::CellList cl;
  cl.build(x.data(), y.data(), n, radius);
  std::vector<double> sx(n), sy(n);
  for (std::size_t k = 0; k < n; ++k) { sx[k] = x[cl.order()[k]]; sy[k] = y[cl.order()[k]]; }
  // order is a permutation
  std::vector<std::uint32_t> o = cl.order();
  std::sort(o.begin(), o.end());
  for (std::size_t k = 0; k < n; ++k) REQUIRE(o[k] == k);
  std::size_t total = 0;
  for (std::size_t k = 0; k < n; ++k) {
    std::vector<std::uint32_t> found;
    cl.for_each_candidate(k, [&](std::uint32_t j) {
      const double dx = sx[k] - sx[j], dy = sy[k] - sy[j];
      if (j != k && dx * dx + dy * dy < radius * radius) found.push_back(cl.order()[j]);
    });
    std::sort(found.begin(), found.end());
    const auto ref = sph::brute_force_neighbours(x.data(), y.data(), n, cl.order()[k], radius);
    REQUIRE(found == ref);
    total += found.size();
  }
  CHECK(total > n);  // the test is not vacuous
}

}  // namespace test_kernels
