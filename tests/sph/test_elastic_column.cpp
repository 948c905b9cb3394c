// Elastic soil column under gravity in a box with free-slip walls (laterally confined, oedometric):
// closed form sigma_yy = -rho g d (d = depth below the free surface), sigma_xx = sigma_zz = nu/(1-nu) sigma_yy.
// Tolerance: 5 % on sigma_yy and 10 % on sigma_xx, row averages, for rows deeper than 3 dx below the free
// surface and higher than 3 dx above the floor (kernel truncation / wall corners affect the outer rows).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "elastic_box.hpp"
#include "sph/engine/fill.hpp"
#include "sph/soil/run.hpp"

namespace test_elastic_column {

namespace {

sph::soil::Model elastic_column(sph::GravityMode mode, double damping) { return test_column::elastic_box(mode, damping); }

void check_profile(const sph::soil::Model& m, double H) {
  const auto& p = m.particles;
  const auto soil = m.soil();
  const double dx = m.settings.particle_spacing, g = 9.81, rho = 2000, k0 = 0.3 / 0.7;
  std::map<long, std::pair<double, int>> syy, sxx;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != 0) continue;
    const long row = std::lround((p.y0[i] - 0.5 * dx) / dx);
    syy[row].first += soil.syy[i];
    syy[row].second += 1;
    sxx[row].first += soil.sxx[i];
    sxx[row].second += 1;
  }
  int checked = 0;
  for (const auto& [row, acc] : syy) {
    const double y = (row + 0.5) * dx;
    const double depth = H - y;
    if (depth < 3 * dx || y < 3 * dx) continue;  // free-surface and floor-corner rows
    const double exact = -rho * g * depth;
    const double got = acc.first / acc.second;
    const double got_xx = sxx[row].first / sxx[row].second;
    INFO("depth " << depth << " m: sigma_yy " << got << " vs " << exact << ", sigma_xx " << got_xx << " vs " << k0 * exact);
    CHECK(std::fabs(got - exact) < 0.05 * std::fabs(exact));
    CHECK(std::fabs(got_xx - k0 * exact) < 0.10 * std::fabs(k0 * exact));
    ++checked;
  }
  CHECK(checked > 30);
}

}  // namespace

TEST_CASE("elastic column with K0 initial stress stays at sigma_yy = rho g depth", "[sph][validation][column]") {
  auto m = elastic_column(sph::GravityMode::geostatic_k0, 0.0);
  const auto sum = sph::soil::run(m, {});
  REQUIRE(sum.stopped_because == "end_time");
  check_profile(m, 1.0);
  // and it does not move: settlement below 1 mm (elastic compression is already in the initial state)
  double umax = 0;
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if (m.particles.kind[i] == 0) umax = std::max(umax, std::hypot(m.particles.x[i] - m.particles.x0[i], m.particles.y[i] - m.particles.y0[i]));
  CHECK(umax < 1e-3);
}

TEST_CASE("elastic column under sudden gravity with damping settles to sigma_yy = rho g depth", "[sph][validation][column]") {
  auto m = elastic_column(sph::GravityMode::sudden, 150.0);
  const auto sum = sph::soil::run(m, {});
  REQUIRE(sum.stopped_because == "end_time");
  check_profile(m, 1.0);
}

TEST_CASE("elastic column study", "[.study]") {
  const double T = std::getenv("SPH_T") ? std::atof(std::getenv("SPH_T")) : 0.3;
  const double Z = std::getenv("SPH_Z") ? std::atof(std::getenv("SPH_Z")) : 150;
  auto m = elastic_column(std::getenv("SPH_K0") ? sph::GravityMode::geostatic_k0 : sph::GravityMode::sudden, Z);
  m.settings.end_time = T;
  if (std::getenv("SPH_NOSLIP")) m.settings.wall_slip = sph::soil::WallSlip::no_slip;
  const auto sum = sph::soil::run(m, {});
  double vmax = 0, uy = 0; int n = 0;
  for (std::size_t i = 0; i < m.particles.size(); ++i) if (m.particles.kind[i] == 0) {
    vmax = std::max(vmax, std::hypot(m.particles.vx[i], m.particles.vy[i]));
    uy += m.particles.y[i] - m.particles.y0[i]; ++n; }
  std::printf("T=%g: vmax %g mean uy %g KE %g\n", T, vmax, uy / n, sum.kinetic_energy);
  const auto& p = m.particles;
  const auto soil = m.soil();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == 0 && std::fabs(p.x0[i] - (std::getenv("SPH_X") ? std::atof(std::getenv("SPH_X")) : 0.2375)) < 1e-9 && std::lround(p.y0[i] / 0.025 - 0.5) % 8 == 0)
      std::printf("  y0 %.4f  syy %.1f exact %.1f sxx %.1f sxy %.1f rho %.2f\n", p.y0[i], soil.syy[i], -2000 * 9.81 * (1 - p.y0[i]), soil.sxx[i], soil.sxy[i], p.rho[i]);
}

}  // namespace test_elastic_column
