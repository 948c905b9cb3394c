// Constitutive update (Bui et al. 2008, IJNAMG 32:1537, section 3): Drucker-Prager return, tension cracking,
// Jaumann objectivity and plane-strain Hooke's law.
#include <catch2/catch.hpp>

#include <cmath>

#include "sph/soil/material.hpp"

namespace test_constitutive {

using namespace sph;
using namespace sph::soil;

namespace {
MaterialConstants soil(double c, double phi, double psi = 0.0) {
  Material m;
  m.youngs_modulus = 20e6;
  m.poisson_ratio = 0.3;
  m.cohesion = c;
  m.friction_angle_deg = phi;
  m.dilatancy_angle_deg = psi;
  m.density = 2000;
  return MaterialConstants::from(m);
}
double sqrt_j2(const Stress& s) { return std::sqrt(second_deviatoric_invariant(s)); }
}  // namespace

TEST_CASE("Drucker-Prager constants are the plane-strain Mohr-Coulomb match", "[sph][constitutive]") {
  // seed-002 section 2.9: phi = 20 deg -> alpha = 0.11185, k = 0.92190 c
  const auto mc = soil(10e3, 20.0);
  CHECK(mc.alpha_phi == Approx(0.11185).epsilon(1e-4));
  CHECK(mc.k_c == Approx(0.92190 * 10e3).epsilon(1e-4));
  CHECK(mc.sound_speed == Approx(std::sqrt((mc.bulk_modulus + 4 * mc.shear_modulus / 3) / 2000)).epsilon(1e-12));
}

TEST_CASE("a trial stress outside the yield surface returns onto it", "[sph][constitutive]") {
  const auto mc = soil(10e3, 30.0);
  Stress s{-50e3, -150e3, -80e3, 60e3};
  REQUIRE(yield_function(mc, s) > 0);
  const double I1 = first_invariant(s);
  const auto res = return_to_yield_surface(mc, s);
  CHECK(res.scaled);
  CHECK_FALSE(res.tension_cracked);
  CHECK(std::fabs(yield_function(mc, s)) < 1e-9 * 1e5);
  CHECK(first_invariant(s) == Approx(I1).epsilon(1e-14));  // scaling keeps the mean stress
  CHECK(res.plastic_strain > 0);
  CHECK(res.plastic_work > 0);
  // a state inside is untouched
  Stress in{-100e3, -100e3, -100e3, 1e3};
  const Stress copy = in;
  const auto r2 = return_to_yield_surface(mc, in);
  CHECK_FALSE(r2.scaled);
  CHECK(in.xx == copy.xx);
  CHECK(in.xy == copy.xy);
}

TEST_CASE("tension beyond the apex is cracked back to I1 = k_c/alpha_phi (Bui 2008)", "[sph][constitutive]") {
  const auto mc = soil(5e3, 25.0);
  Stress s{80e3, 40e3, 30e3, 10e3};
  REQUIRE(mc.alpha_phi * first_invariant(s) - mc.k_c > 0);
  const auto res = return_to_yield_surface(mc, s);
  CHECK(res.tension_cracked);
  CHECK(first_invariant(s) == Approx(mc.k_c / mc.alpha_phi).epsilon(1e-12));
  // at the apex the deviator must vanish (r = 0)
  CHECK(sqrt_j2(s) < 1e-9);
  // cohesionless soil: any tension goes to zero stress
  const auto sand = soil(0.0, 30.0);
  Stress t{100.0, -20.0, 0.0, 30.0};
  return_to_yield_surface(sand, t);
  CHECK(std::fabs(t.xx) < 1e-12);
  CHECK(std::fabs(t.yy) < 1e-12);
  CHECK(std::fabs(t.xy) < 1e-12);
}

TEST_CASE("elastic loading below yield gives plane-strain Hooke's law exactly", "[sph][constitutive][validation]") {
  const auto mc = soil(1e9, 30.0);  // far from yield
  const Stress s{-100e3, -200e3, -90e3, 5e3};
  const double exx = 1e-3, eyy = -2e-3, exy = 0.5e-3;
  const auto r = stress_rate(mc, s, exx, eyy, exy, 0.0);
  const double lam = mc.lame_lambda, G = mc.shear_modulus;
  CHECK(r.rate.xx == Approx((lam + 2 * G) * exx + lam * eyy).epsilon(1e-13));
  CHECK(r.rate.yy == Approx(lam * exx + (lam + 2 * G) * eyy).epsilon(1e-13));
  CHECK(r.rate.zz == Approx(lam * (exx + eyy)).epsilon(1e-13));
  CHECK(r.rate.xy == Approx(2 * G * exy).epsilon(1e-13));
  CHECK(r.plastic_multiplier == 0.0);
}

TEST_CASE("plastic flow keeps the stress on the yield surface (consistency, Bui's lambda_dot)", "[sph][constitutive]") {
  for (double psi : {0.0, 10.0, 30.0}) {
    const auto mc = soil(10e3, 30.0, psi);
    Stress s{-50e3, -150e3, -80e3, 60e3};
    return_to_yield_surface(mc, s);
    // shear loading on the surface: the rate must be tangent to f = 0 (df/dsigma : dsigma = 0)
    const auto r = stress_rate(mc, s, 1e-4, -2e-4, 3e-4, 0.0);
    REQUIRE(r.plastic_multiplier > 0);
    const double dt = 1e-3;
    Stress next{s.xx + dt * r.rate.xx, s.yy + dt * r.rate.yy, s.zz + dt * r.rate.zz, s.xy + dt * r.rate.xy};
    // first-order consistency: |f(next)| << |elastic increment|
    const double scale = mc.shear_modulus * 3e-4 * dt;
    CHECK(std::fabs(yield_function(mc, next)) < 0.02 * scale);
    CHECK(r.plastic_strain_rate == Approx(r.plastic_multiplier * std::sqrt(2 * mc.alpha_psi * mc.alpha_psi + 1.0 / 3)));
  }
}

TEST_CASE("a rigid-body rotation leaves the stress invariants unchanged (Jaumann objectivity)", "[sph][constitutive]") {
  const auto mc = soil(1e9, 30.0);
  // rigid rotation v = Omega x r: dvx/dy = -Omega, dvy/dx = Omega -> no strain rate, spin w_xy = -Omega
  const double omega = 2.0;  // rad/s
  const double wxy = -omega;
  Stress s{-100e3, -30e3, -50e3, 20e3};
  const Stress s0 = s;
  const double t_end = 3.14159265358979323846 / omega / 2;  // quarter turn
  const int n = 20000;
  const double dt = t_end / n;
  for (int k = 0; k < n; ++k) {  // RK2 (midpoint)
    const auto r1 = stress_rate(mc, s, 0, 0, 0, wxy);
    Stress mid{s.xx + 0.5 * dt * r1.rate.xx, s.yy + 0.5 * dt * r1.rate.yy, s.zz, s.xy + 0.5 * dt * r1.rate.xy};
    const auto r2 = stress_rate(mc, mid, 0, 0, 0, wxy);
    s.xx += dt * r2.rate.xx;
    s.yy += dt * r2.rate.yy;
    s.xy += dt * r2.rate.xy;
  }
  CHECK(first_invariant(s) == Approx(first_invariant(s0)).epsilon(1e-9));
  CHECK(second_deviatoric_invariant(s) == Approx(second_deviatoric_invariant(s0)).epsilon(1e-8));
  // a quarter turn of the body swaps the in-plane normal stresses and flips the shear
  CHECK(s.xx == Approx(s0.yy).epsilon(1e-7));
  CHECK(s.yy == Approx(s0.xx).epsilon(1e-7));
  CHECK(s.xy == Approx(-s0.xy).epsilon(1e-6));
}

TEST_CASE("the return's plastic work is the work of the step's stresses, not the elastic energy of the trial",
          "[sph][constitutive]") {
  const auto sand = soil(0.0, 30.0);
  const double K = sand.bulk_modulus, G = sand.shear_modulus;
  SECTION("a particle at the apex that expands: stress zero before and after, no work done, no dissipation") {
    // An expansion of 1e-5 from sigma = 0 gives the elastic trial 3K d_eps_v/3 = K 1e-5 on each normal component.
    const double trial_p = K * 1e-5;
    const Stress start{0, 0, 0, 0};
    Stress s{trial_p, trial_p, trial_p, 0};
    const auto res = return_to_yield_surface(sand, s, &start);
    CHECK(res.tension_cracked);
    CHECK(res.plastic_strain > 0);  // the expansion is all plastic
    CHECK(res.plastic_work == 0.0);
    // taking the trial as the start counts the elastic energy of the trial, 1/2 sigma : C^-1 : sigma = 9 p^2/(18 K)
    Stress again{trial_p, trial_p, trial_p, 0};
    const auto at_trial = return_to_yield_surface(sand, again);
    CHECK(at_trial.plastic_work == Approx(trial_p * trial_p / (2.0 * K)).epsilon(1e-12));
  }
  SECTION("a trial that leaves the yield cone tangentially dissipates delta:delta/(4G), the chord's overshoot") {
    // On the cone at p = -100 kPa: pure shear s_xy = R with R = sqrt(J2) = -alpha I1 (c = 0). The trial adds the
    // deviatoric increment delta = (d, -d, 0, 0), orthogonal to s (s:delta = 0); the return scales the deviator back
    // to R, and the step's stresses did the work 1/2 (sigma_start + sigma_end) : d_eps of which the cone keeps no
    // elastic energy: delta:delta/(4G) (first order in delta/R).
    const double p = -100e3, R = -sand.alpha_phi * 3.0 * p;
    const Stress start{p, p, p, R};
    REQUIRE(std::fabs(yield_function(sand, start)) < 1e-9 * R);
    const double d = 1e-3 * R;
    Stress s{p + d, p - d, p, R};
    const auto res = return_to_yield_surface(sand, s, &start);
    CHECK(res.scaled);
    const double delta_delta = 2.0 * d * d;
    CHECK(res.plastic_work == Approx(delta_delta / (4.0 * G)).epsilon(0.01));
  }
}

TEST_CASE("a yielding particle's stress update takes sub-steps in proportion to its strain increment",
          "[sph][constitutive][substeps]") {
  const auto sand = soil(0.0, 30.0);
  const double G = sand.shear_modulus;
  const double p = -100e3, R = -sand.alpha_phi * 3.0 * p;  // yield radius k_c - alpha I1 at p (c = 0)
  const Stress s{p, p, p, R};
  const double dt = 1e-4;
  // pure shear strain rate exy: sqrt(J2) of the elastic deviatoric increment is 2G dt exy
  const auto count = [&](double share_of_radius, int n_max) {
    const double exy = share_of_radius * R / (2.0 * G * dt);
    return stress_substep_count(sand, s, 0.0, 0.0, exy, dt, n_max);
  };
  CHECK(count(0.05, 16) == 1);   // within a tenth of the radius: one update
  CHECK(count(0.35, 16) == 4);   // 0.35 R in sub-steps of at most 0.1 R
  CHECK(count(1.0, 16) == 10);
  CHECK(count(5.0, 16) == 16);   // capped
  CHECK(count(0.35, 2) == 2);
  // a volumetric increment has no deviatoric part in plane strain only through e_zz = 0: e_xx = e_yy = e gives
  // a deviator (e/3, e/3, -2e/3), sqrt(J2) = e/sqrt(3)
  const double e = 0.35 * R / (2.0 * G * dt) * std::sqrt(3.0);
  CHECK(stress_substep_count(sand, s, e, e, 0.0, dt, 16) == 4);
  // at the apex of a cohesionless cone the radius is zero: the largest count
  const Stress apex{0, 0, 0, 0};
  CHECK(stress_substep_count(sand, apex, 0.0, 0.0, 1e-9, dt, 16) == 16);
}

}  // namespace test_constitutive
