// Reference checks of the explicit three-step ISPH fluid (docs/isph.md section 4):
//  * a still water tank: pressure against rho g depth, volume kept, no spurious motion;
//  * the Martin & Moyce (1952) n^2 = 2 dam break against their tabulated surge-front positions
//    (sph::fluid::martin_moyce_1952_n2_2(), sph/src/fluid/reference_fronts.cpp, provenance there).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "sph/fluid/cases.hpp"
#include "sph/fluid/reference_fronts.hpp"
#include "sph/fluid/run.hpp"
#include "sphslope/units.hpp"

namespace test_isph_validation {

namespace {

using namespace sph::fluid;
constexpr double kG = sphslope::standard_gravity;
constexpr std::uint8_t kFluid = 0;

struct TankResult {
  double worst_pressure = 0;  // max over non-surface fluid of |P - rho0 g (y_s - y)| / (rho0 g H)
  double slope_ratio = 0;  // fitted -dP/dy over rho0 g
  double early_speed = 0;  // max fluid speed over (0, settle] [m/s]
  double late_speed = 0;  // max fluid speed over (settle, end] [m/s]
  double top_shift = 0;  // mean height of the top row's particles at the end minus at the start [m]
  double mass_change = 0;  // |fluid mass at the end - at the start| / at the start
  std::size_t outside = 0;  // fluid particle centres outside the tank's inner box
  std::size_t fluid = 0;
  double density_error = 0;  // max |rho* - rho0|/rho0 of the last step
};

// The pressure of every non-surface fluid particle against rho0 g (y_s - y), y_s = H - dx/2 the height of the
// top row's centres, where the free-surface condition P = 0 is imposed (decision D6).
void measure_pressure(const Model& m, double depth, TankResult& r) {
  const sph::ParticleSet& p = m.particles;
  const ConstArrays a(m.particles, m.fields);
  const double rg = m.settings.rest_density * kG, ys = depth - 0.5 * m.settings.particle_spacing;
  double sy = 0, sp = 0, syy = 0, syp = 0, n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != kFluid || a.free_surface[i] != 0.0) continue;
    const double y = p.y[i], pr = a.pressure[i];
    r.worst_pressure = std::max(r.worst_pressure, std::abs(pr - rg * (ys - y)) / (rg * depth));
    sy += y;
    sp += pr;
    syy += y * y;
    syp += y * pr;
    n += 1;
  }
  r.slope_ratio = -((n * syp - sy * sp) / (n * syy - sy * sy)) / rg;
}

double fluid_mass(const Model& m) {
  double mass = 0;
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if (m.particles.kind[i] == kFluid) mass += m.particles.mass[i];
  return mass;
}

double top_row_height(const Model& m, double depth) {
  double sum = 0, n = 0;
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if (m.particles.kind[i] == kFluid && m.particles.y0[i] > depth - m.settings.particle_spacing) {
      sum += m.particles.y[i];
      n += 1;
    }
  return sum / n;
}

constexpr double kTankSettle = 1.0, kTankEnd = 2.0;  // [s]

TankResult run_tank(PressureMode mode) {
  const double width = 0.4, depth = 0.4;
  Settings st;
  st.particle_spacing = 0.02;
  st.pressure_mode = mode;
  st.end_time = kTankEnd;
  Model m = make_still_tank(st, width, depth);
  const double mass0 = fluid_mass(m), top0 = top_row_height(m, depth);
  const std::size_t fluid0 = m.particles.count(sph::ParticleKind::material);
  TankResult r;
  const auto sum = run(m, {}, {}, [&](const Step& s, const sph::RunState& rs) {
    r.density_error = s.diagnostics().max_density_error;
    double& speed = rs.time <= kTankSettle ? r.early_speed : r.late_speed;
    for (std::size_t i = 0; i < m.particles.size(); ++i)
      if (m.particles.kind[i] == kFluid) speed = std::max(speed, std::hypot(m.particles.vx[i], m.particles.vy[i]));
  });
  REQUIRE(sum.stopped_because == "end_time");
  measure_pressure(m, depth, r);
  r.mass_change = std::abs(fluid_mass(m) - mass0) / mass0;
  r.top_shift = top_row_height(m, depth) - top0;
  for (std::size_t i = 0; i < m.particles.size(); ++i) {
    if (m.particles.kind[i] != kFluid) continue;
    ++r.fluid;
    if (m.particles.x[i] <= 0 || m.particles.x[i] >= width || m.particles.y[i] <= 0) ++r.outside;
  }
  REQUIRE(r.fluid == fluid0);
  std::printf(
      "still tank (%s, dx = %.3f m, %zu fluid, %llu steps, %.2f s wall): worst particle pressure error %.4f rho g H, "
      "-dp/dy / rho g = %.4f, max speed %.4f m/s to %.1f s and %.4f m/s after (%.2f %% of sqrt(gH)), top row moved "
      "%.2f mm, mass change %.1e, density error %.4f\n",
      pressure_mode_key(mode), st.particle_spacing, r.fluid, static_cast<unsigned long long>(sum.steps),
      sum.wall_seconds, r.worst_pressure, r.slope_ratio, r.early_speed, kTankSettle, r.late_speed,
      100.0 * r.late_speed / std::sqrt(kG * depth), 1e3 * r.top_shift, r.mass_change, r.density_error);
  return r;
}

}  // namespace

// Water at rest, 0.4 m x 0.4 m, dx = 0.02 m (400 fluid particles), hydrostatic start, 2 s. Reference: hydrostatics,
// P = rho0 g (y_s - y) with y_s the height of the top row's centres (the free-surface condition's place), and a
// fluid at rest. Tolerances (docs/isph.md section 5, measured values there):
//  * every non-surface particle's pressure within 0.5 % of rho0 g H of hydrostatic at the end (measured 0.13 %;
//    before decision D14 the second row below the surface alone was 0.24 rho0 g dx = 1.2 % of rho0 g H too high);
//  * the fitted -dP/dy within 0.5 % of rho0 g (measured 0.03 % iterative, 0.12 % explicit);
//  * mass: no particle lost or added, total mass unchanged to round-off; volume: the top row's mean height moved by
//    less than dx/10 (before decisions D12-D16 the surface particles sank by 0.25 dx in 2 s);
//  * motion: the largest speed after a settling second below 1.5 % of sqrt(g H) = 0.030 m/s (measured 1.0 %
//    iterative, 1.3 % explicit; 11 % before the fix). Not 1 %: an undamped shear mode of the particle lattice
//    (alternate columns sliding vertically, restoring stiffness about 150 s^-2 against 1750 s^-2 for the
//    checkerboard) stays excited at about 1 %. The bound holds only to about 2.5 s at this spacing: later a
//    surface particle at a wall corner is lifted out (docs/isph.md section 5, an open item), which is why the run
//    stops at 2 s.
TEST_CASE("ISPH still water tank: hydrostatic pressure, mass kept, fluid at rest", "[sph][isph][validation]") {
  const double depth = 0.4, dx = 0.02;
  const double celerity = std::sqrt(kG * depth);
  for (PressureMode mode : {PressureMode::iterative, PressureMode::explicit_jacobi}) {
    INFO("pressure mode " << pressure_mode_key(mode));
    const TankResult r = run_tank(mode);
    CHECK(r.outside == 0);
    CHECK(r.worst_pressure < 0.005);
    CHECK(r.slope_ratio == Approx(1.0).margin(0.005));
    CHECK(r.mass_change < 1e-12);
    CHECK(std::abs(r.top_shift) < 0.1 * dx);
    CHECK(r.late_speed < 0.015 * celerity);
  }
}

// Decision D16: a checkerboard displacement of the particles (alternate particles moved by +-0.02 dx along the
// diagonal, in the interior of the still tank) must be pushed back. With the cubic spline at h = 1.5 dx the nearest
// neighbours sit at the inflection of W (q = 2/3) and the displacement grows (measured +0.40 m/s^2, growth rate
// about 30/s, the still tank's spurious motion before the fix); with the Wendland C2 kernel it is restored
// (measured -0.98 m/s^2).
TEST_CASE("ISPH checkerboard displacement is restored with the fluid's kernel and grows with the cubic spline",
          "[sph][isph]") {
  auto projected_acceleration = [](sph::KernelType kernel) {
    Settings st;
    st.kernel = kernel;
    st.particle_spacing = 0.02;
    st.max_time_step = 1e-3;
    Model m = make_still_tank(st, 0.4, 0.4);
    sph::ParticleSet& p = m.particles;
    const double d = 0.02 * st.particle_spacing;
    auto sign = [&](std::size_t i) {
      const int c = static_cast<int>(std::floor(p.x0[i] / st.particle_spacing));
      const int r = static_cast<int>(std::floor(p.y0[i] / st.particle_spacing));
      return (c + r) % 2 != 0 ? -1.0 : 1.0;
    };
    auto inside = [&](std::size_t i) {
      return p.kind[i] == kFluid && p.x0[i] > 0.1 && p.x0[i] < 0.3 && p.y0[i] > 0.05 && p.y0[i] < 0.3;
    };
    for (std::size_t i = 0; i < p.size(); ++i)
      if (inside(i)) {
        p.x[i] += sign(i) * d;
        p.y[i] += sign(i) * d;
      }
    sph::RunOptions opt;
    opt.max_steps = 1;
    run(m, opt);
    double sum = 0, n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (inside(i)) {
        sum += sign(i) * (p.vx[i] + p.vy[i]) / std::sqrt(2.0);
        n += 1;
      }
    return sum / n / m.state.time;
  };
  const double wendland = projected_acceleration(Settings{}.kernel);
  const double cubic = projected_acceleration(sph::KernelType::cubic_spline);
  std::printf(
      "checkerboard 0.02 dx: mean acceleration along the displacement %+.3f m/s^2 (Wendland C2), %+.3f (cubic)\n",
      wendland, cubic);
  CHECK(Settings{}.kernel == sph::KernelType::wendland_c2);
  CHECK(wendland < -0.5);
  CHECK(cubic > 0.2);
}

namespace {

// Least-squares slope dZ/dT of the run over [t0, t1].
double front_slope(const FrontSeries& run, double t0, double t1) {
  double st = 0, sz = 0, stt = 0, stz = 0, n = 0;
  for (std::size_t k = 0; k < run.T.size(); ++k) {
    if (run.T[k] < t0 || run.T[k] > t1) continue;
    st += run.T[k];
    sz += run.Z[k];
    stt += run.T[k] * run.T[k];
    stz += run.T[k] * run.Z[k];
    n += 1;
  }
  return (n * stz - st * sz) / (n * stt - st * st);
}

}  // namespace

// Martin & Moyce (1952), n^2 = 2, a = 2.25 in, water (mu = 1e-3 Pa s), dx = a/20 (800 fluid particles), iterative
// pressure. Criteria (docs/isph.md section 4):
//  * RMS relative error of Z over the tabulated points with 0.84 <= T <= 3.33, allowing one time shift
//    dT in [-0.3, 0] (the experiment's gate takes a finite time to open; a computation starts with the column
//    free): <= 5 %. Without a shift: <= 15 %, a bound against gross failure only (a front at Ritter's speed,
//    Z = 1 + 2T, is 55 % off; a column that does not spread, about 60 %).
//  * late front speed dZ/dT over 2 <= T <= 3.33 within [1.2, 1.6] (measured 1.35; Ritter 2): catches both an
//    over-damped and an inviscid-shallow-water behaviour.
TEST_CASE("ISPH dam break (Martin & Moyce 1952, n^2 = 2): surge front against the tabulated data",
          "[sph][isph][validation]") {
  const std::span<const FrontPoint> ref = martin_moyce_1952_n2_2();
  REQUIRE(ref.size() == 15);
  const double a = 0.05715, n = std::sqrt(2.0), tank = 6.0 * a;
  const double t_scale = n * std::sqrt(kG / a);  // T = n t sqrt(g/a)
  Settings st;
  st.particle_spacing = a / 20.0;
  st.pressure_mode = PressureMode::iterative;
  st.end_time = (ref.back().T + 0.05) / t_scale;
  Model m = make_dam_break(st, a, 2.0, tank);
  FrontSeries run_front;
  const auto sum = run(m, {}, {}, [&](const Step&, const sph::RunState& rs) {
    run_front.T.push_back(rs.time * t_scale);
    run_front.Z.push_back(front_position(m) / a);
  });
  REQUIRE(sum.stopped_because == "end_time");
  const double plain = front_rms_error(run_front, ref, 0.84, 3.33);
  const ShiftedFrontError shifted = best_shifted_front_error(run_front, ref, 0.84, 3.33, -0.3, 0.01);
  const double best = shifted.error, best_shift = shifted.shift;
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

}  // namespace test_isph_validation
