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
#include "sphslope/units.hpp"

namespace {

using namespace sph::fluid;
constexpr double kG = sphslope::standard_gravity;
constexpr std::uint8_t kFluid = 0;

struct TankResult {
  double slope_ratio = 0;  // fitted -dp/dy over rho0 g
  double worst_band = 0;  // max over 4 depth bands of |mean p - rho0 g (H - mean y)| / (rho0 g H)
  double late_speed = 0;  // max fluid speed over the second half of the run [m/s]
  double top = 0;  // highest fluid particle centre at the end [m]
  double mean_density = 0;  // mean normalised kernel-sum density of the non-surface fluid [kg/m^3]
  std::size_t outside = 0;  // fluid particle centres outside the tank's inner box
  std::size_t fluid = 0;
  double density_error = 0;  // max |rho* - rho0|/rho0 of the last step
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
    sy += y;
    sp += pr;
    syy += y * y;
    syp += y * pr;
    n += 1;
    kd += a.kernel_density[i];
    const int b = std::clamp(static_cast<int>(4.0 * y / depth), 0, 3);
    band_p[b] += pr;
    band_y[b] += y;
    band_n[b] += 1;
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
  std::printf(
      "still tank (%s, dx = %.3f m, %zu fluid, %llu steps, %.2f s wall): -dp/dy / rho g = %.4f, worst band "
      "error %.4f, late max speed %.4f m/s, top %.4f m, mean kernel density %.1f, density error %.4f\n",
      pressure_mode_key(mode), st.particle_spacing, r.fluid, static_cast<unsigned long long>(sum.steps),
      sum.wall_seconds, r.slope_ratio, r.worst_band, r.late_speed, r.top, r.mean_density, r.density_error);
  return r;
}

}  // namespace

TEST_CASE("ISPH still water tank: hydrostatic pressure, volume kept, no spurious motion", "[sph][isph][validation]") {
  const double depth = 0.4, dx = 0.02;
  const double celerity = std::sqrt(kG * depth);
  SECTION("iterative pressure (CG to 1e-8)") {
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

namespace {

struct Series {
  std::vector<double> t, z;
  // linear interpolation (the series is sampled every step, far finer than the reference's spacing)
  double at(double x) const {
    if (x <= t.front()) return z.front();
    const auto it = std::upper_bound(t.begin(), t.end(), x);
    if (it == t.end()) return z.back();
    const std::size_t k = static_cast<std::size_t>(it - t.begin());
    const double w = (x - t[k - 1]) / (t[k] - t[k - 1]);
    return z[k - 1] + w * (z[k] - z[k - 1]);
  }
};

Series read_reference(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  Series s;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'T') continue;
    std::istringstream row(line);
    double t = 0, z = 0;
    char comma = 0;
    row >> t >> comma >> z;
    s.t.push_back(t);
    s.z.push_back(z);
  }
  return s;
}

// RMS relative front error against the reference points with t_min <= T, comparing the run at T + shift.
double rms_error(const Series& run, const Series& ref, double t_min, double shift) {
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < ref.t.size(); ++k) {
    if (ref.t[k] < t_min) continue;
    const double e = run.at(ref.t[k] + shift) / ref.z[k] - 1.0;
    sum += e * e;
    ++n;
  }
  return std::sqrt(sum / n);
}

// Least-squares slope dZ/dT of the run over [t0, t1].
double front_slope(const Series& run, double t0, double t1) {
  double st = 0, sz = 0, stt = 0, stz = 0, n = 0;
  for (std::size_t k = 0; k < run.t.size(); ++k) {
    if (run.t[k] < t0 || run.t[k] > t1) continue;
    st += run.t[k];
    sz += run.z[k];
    stt += run.t[k] * run.t[k];
    stz += run.t[k] * run.z[k];
    n += 1;
  }
  return (n * stz - st * sz) / (n * stt - st * st);
}

}  // namespace

// Martin & Moyce (1952), n^2 = 2, a = 2.25 in, water (mu = 1e-3 Pa s), dx = a/20 (800 fluid particles), iterative
// pressure. Criteria (docs/isph.md section 4, after shared/references/fluids-granular.md section 7):
//  * RMS relative error of Z over the tabulated points with 0.84 <= T <= 3.33, allowing one time shift
//    dT in [-0.3, 0] (the experiment's gate takes a finite time to open; a computation starts with the column
//    free): <= 5 %. Without a shift: <= 15 %, a bound against gross failure only (a front at Ritter's speed,
//    Z = 1 + 2T, is 55 % off; a column that does not spread, about 60 %).
//  * late front speed dZ/dT over 2 <= T <= 3.33 within [1.2, 1.6] (measured 1.35; Ritter 2): catches both an
//    over-damped and an inviscid-shallow-water behaviour.
TEST_CASE("ISPH dam break (Martin & Moyce 1952, n^2 = 2): surge front against the tabulated data",
          "[sph][isph][validation]") {
  const Series ref =
      read_reference(std::string(SPHSLOPE_SOURCE_DIR) + "/tests/sph/data/martin_moyce_1952_n2_2_front.csv");
  REQUIRE(ref.t.size() == 15);
  const double a = 0.05715, n = std::sqrt(2.0), tank = 6.0 * a;
  const double t_scale = n * std::sqrt(kG / a);  // T = n t sqrt(g/a)
  Settings st;
  st.particle_spacing = a / 20.0;
  st.pressure_mode = PressureMode::iterative;
  st.end_time = (ref.t.back() + 0.05) / t_scale;
  Model m = make_dam_break(st, a, 2.0, tank);
  Series run_front;
  const auto sum = run(m, {}, {}, [&](const Step&, const sph::RunState& rs) {
    run_front.t.push_back(rs.time * t_scale);
    run_front.z.push_back(front_position(m) / a);
  });
  REQUIRE(sum.stopped_because == "end_time");
  const double plain = rms_error(run_front, ref, 0.84, 0.0);
  double best = plain, best_shift = 0.0;
  for (int k = 1; k <= 30; ++k) {
    const double e = rms_error(run_front, ref, 0.84, -0.01 * k);
    if (e < best) best = e, best_shift = -0.01 * k;
  }
  const double slope = front_slope(run_front, 2.0, 3.33);
  // no fluid particle has crossed the first row of wall particles (centres at dx/2 outside the wall faces)
  std::size_t outside = 0;
  double lowest = 1.0, leftmost = 1.0;
  const double half = 0.5 * st.particle_spacing;
  for (std::size_t i = 0; i < m.particles.size(); ++i) {
    if (m.particles.kind[i] != kFluid) continue;
    const double x = m.particles.x[i], y = m.particles.y[i];
    lowest = std::min(lowest, y);
    leftmost = std::min(leftmost, x);
    if (x <= -half || x >= tank + half || y <= -half) ++outside;
  }
  std::printf("lowest fluid particle centre y = %.5f m, leftmost x = %.5f m (dx/2 = %.5f m)\n", lowest, leftmost, half);
  std::printf(
      "dam break M&M n2 = 2 (dx = a/20, %zu fluid, %llu steps, %.2f s wall): Z(T = 3.33) = %.3f (ref 4.11), "
      "RMS error %.4f unshifted, %.4f with dT = %.2f, late slope dZ/dT = %.3f\n",
      sum.soil_particles, static_cast<unsigned long long>(sum.steps), sum.wall_seconds, run_front.at(3.33), plain, best,
      best_shift, slope);
  CHECK(outside == 0);
  CHECK(best <= 0.05);
  CHECK(plain <= 0.15);
  CHECK(slope >= 1.2);
  CHECK(slope <= 1.6);
}
