#pragma once
// Soil material: linear elasticity + Drucker-Prager perfect plasticity (Bui et al. 2008, IJNAMG 32:1537),
// plane strain, tension positive. The constitutive functions here are pure and header-inline so the
// per-particle loop can use them without calls through pointers.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace sph::soil {

struct Material {
  std::string name = "soil";
  double density = 2000.0;          // reference density [kg/m^3]
  double youngs_modulus = 10e6;     // [Pa]
  double poisson_ratio = 0.3;       // [-]
  double cohesion = 0.0;            // [Pa]
  double friction_angle_deg = 30.0; // [deg]
  double dilatancy_angle_deg = 0.0; // [deg]; psi = phi gives associated flow
  bool plastic = true;              // false: linear elastic (no yield)
  double k0 = std::numeric_limits<double>::quiet_NaN();  // geostatic ratio; NaN -> nu/(1-nu)

  // Throws std::invalid_argument naming the bad field.
  void validate() const;
};

// Constants derived once from a Material.
struct MaterialConstants {
  double density = 0;
  double bulk_modulus = 0;   // K = E / (3(1-2nu))
  double shear_modulus = 0;  // G = E / (2(1+nu))
  double lame_lambda = 0;    // K - 2G/3
  double alpha_phi = 0;      // tan(phi)/sqrt(9 + 12 tan^2 phi)
  double k_c = 0;            // 3c/sqrt(9 + 12 tan^2 phi)   (infinite for an elastic material)
  double alpha_psi = 0;      // tan(psi)/sqrt(9 + 12 tan^2 psi)
  double sound_speed = 0;    // P-wave speed sqrt((K + 4G/3)/rho)
  double k0 = 0;             // geostatic sigma_h / sigma_v
  bool plastic = true;
  // Derived once, with the expressions the functions below would evaluate at every call (so bitwise the same):
  double lambda_denominator = 0;         // 9 alpha_phi alpha_psi K + G
  double plastic_strain_per_lambda = 0;  // sqrt(2 alpha_psi^2 + 1/3)
  double half_inv_shear = 0;             // 0.5 / G
  double inv_9_bulk = 0;                 // 1 / (9 K)
  double apex_i1 = 0;                    // k_c / alpha_phi, the I1 of the apex (alpha_phi > 0)

  static MaterialConstants from(const Material& m);
};

// Plane-strain stress state (tension positive).
struct Stress {
  double xx = 0, yy = 0, zz = 0, xy = 0;
};

inline double first_invariant(const Stress& s) { return s.xx + s.yy + s.zz; }
// J2 = 1/2 s:s with the deviator s of the full 3-D (plane-strain) tensor.
inline double second_deviatoric_invariant(const Stress& s) {
  const double p = (s.xx + s.yy + s.zz) / 3.0;
  const double dx = s.xx - p, dy = s.yy - p, dz = s.zz - p;
  return 0.5 * (dx * dx + dy * dy + dz * dz) + s.xy * s.xy;
}
// Drucker-Prager yield function f = alpha_phi I1 + sqrt(J2) - k_c (f > 0: outside).
inline double yield_function(const MaterialConstants& mc, const Stress& s) {
  return mc.alpha_phi * first_invariant(s) + std::sqrt(second_deviatoric_invariant(s)) - mc.k_c;
}

// Result of the rate evaluation for one particle.
struct StressRate {
  Stress rate;                   // d sigma / dt (Jaumann rotation included)
  double plastic_multiplier = 0; // lambda_dot >= 0
  double plastic_strain_rate = 0;// sqrt(2/3 eps_p_dot : eps_p_dot)
  double plastic_work_rate = 0;  // sigma : eps_p_dot  [Pa/s] (per unit volume)
};

// Elasto-plastic stress rate of Bui et al. (2008), non-associated Drucker-Prager:
//   sigma_dot = 2G e_dot + K eps_dot_kk I - lambda_dot (3 alpha_psi K I + G/sqrt(J2) s) + Jaumann terms
//   lambda_dot = (3 alpha_phi K eps_dot_kk + G/sqrt(J2) s:eps_dot) / (9 alpha_phi alpha_psi K + G)
// applied only when the state is on the yield surface (f >= -tol) and lambda_dot > 0.
// Strain rate (exx, eyy, exy tensor shear; ezz = 0) and spin wxy = 1/2 (dvx/dy - dvy/dx).
// Jaumann (Bui's form): dsxx += 2 sxy wxy, dsyy -= 2 sxy wxy, dsxy += wxy (syy - sxx); szz unrotated.
inline StressRate stress_rate(const MaterialConstants& mc, const Stress& s, double exx, double eyy, double exy,
                              double wxy) {
  const double K = mc.bulk_modulus, G = mc.shear_modulus;
  const double ekk = exx + eyy;
  const double third = ekk / 3.0;
  StressRate out;
  out.rate.xx = 2.0 * G * (exx - third) + K * ekk;
  out.rate.yy = 2.0 * G * (eyy - third) + K * ekk;
  out.rate.zz = 2.0 * G * (-third) + K * ekk;
  out.rate.xy = 2.0 * G * exy;

  const double I1 = s.xx + s.yy + s.zz;
  const double p = I1 / 3.0;
  const double dxx = s.xx - p, dyy = s.yy - p, dzz = s.zz - p;
  const double J2 = 0.5 * (dxx * dxx + dyy * dyy + dzz * dzz) + s.xy * s.xy;
  const double sqrtJ2 = std::sqrt(J2);
  const double f = mc.alpha_phi * I1 + sqrtJ2 - mc.k_c;
  const double tol = 1e-8 * (std::fabs(mc.alpha_phi * I1) + sqrtJ2 + std::fabs(mc.k_c)) + 1e-300;
  if (mc.plastic && f >= -tol && sqrtJ2 > 0.0) {
    const double s_dot_e = dxx * exx + dyy * eyy + 2.0 * s.xy * exy;
    const double lambda = (3.0 * mc.alpha_phi * K * ekk + (G / sqrtJ2) * s_dot_e) / mc.lambda_denominator;
    if (lambda > 0.0) {
      const double iso = 3.0 * mc.alpha_psi * K * lambda;
      const double dev = G / sqrtJ2 * lambda;
      out.rate.xx -= iso + dev * dxx;
      out.rate.yy -= iso + dev * dyy;
      out.rate.zz -= iso + dev * dzz;
      out.rate.xy -= dev * s.xy;
      out.plastic_multiplier = lambda;
      // eps_p_dot = lambda (alpha_psi I + s/(2 sqrt J2)) => |.|^2 = lambda^2 (3 alpha_psi^2 + 1/2)
      out.plastic_strain_rate = lambda * mc.plastic_strain_per_lambda;
      out.plastic_work_rate = lambda * (mc.alpha_psi * I1 + sqrtJ2);
    }
  }
  out.rate.xx += 2.0 * s.xy * wxy;
  out.rate.yy -= 2.0 * s.xy * wxy;
  out.rate.xy += wxy * (s.yy - s.xx);
  return out;
}

// The number of sub-steps, at most n_max, of a yielding particle's stress update over dt with the strain rate
// (exx, eyy, exy; ezz = 0) from the stress s: enough that each sub-step's elastic deviatoric trial increment,
// 2G dt/n sqrt(J2(e_dot)), is at most a tenth of the yield radius k_c - alpha_phi I1 at s (the return's error grows
// with the overshoot relative to that radius); n_max where the radius is zero (a cohesionless particle at the apex).
// Measured on the granular collapse of docs/performance.md: a tenth and three tenths give the same deposit to 1 %.
inline int stress_substep_count(const MaterialConstants& mc, const Stress& s, double exx, double eyy, double exy,
                                double dt, int n_max) {
  constexpr double share = 0.1;
  const double third = (exx + eyy) / 3.0;
  const double dxx = exx - third, dyy = eyy - third;
  const double increment =
      2.0 * mc.shear_modulus * dt * std::sqrt(0.5 * (dxx * dxx + dyy * dyy + third * third) + exy * exy);
  const double radius = mc.k_c - mc.alpha_phi * (s.xx + s.yy + s.zz);
  if (!(radius > 0.0) || !(increment < share * radius * n_max)) return n_max;
  return std::max(1, static_cast<int>(std::ceil(increment / (share * radius))));
}

// Result of the return to the admissible domain.
struct ReturnResult {
  double plastic_strain = 0;  // equivalent plastic strain increment of the correction
  double plastic_work = 0;    // 1/2 (sigma_start + sigma_returned) : d eps_p [Pa]
  bool tension_cracked = false;
  bool scaled = false;
};

// Bui et al. (2008) stress correction, applied after every stress update:
//  1. tension cracking: if alpha_phi I1 - k_c > 0 (beyond the apex) shift the normal stresses by
//     -(I1 - k_c/alpha_phi)/3 so that I1 = k_c/alpha_phi (shear unchanged);
//  2. scaling back: if sqrt(J2) > k_c - alpha_phi I1, scale the deviator by r = (k_c - alpha_phi I1)/sqrt(J2).
// The removed stress is counted as plastic strain: d eps_p = -C^-1 : d sigma (C elastic stiffness).
// Its plastic work is the work the step's stress did on that strain, 1/2 (sigma_start + sigma_returned) : d eps_p,
// with sigma_start the stress at the step's start (the work of the step's strain at the mean of the stresses that
// acted, less the elastic energy stored). Counting it at the trial stress instead, 1/2 (sigma_trial +
// sigma_returned), adds the elastic energy of a trial overshoot that no force paid for: a particle at the apex
// (sigma = 0 before and after, expanding) would dissipate the energy of its tensile trial stress at every step, a
// plastic work that grows with the step and exceeded the released potential energy five times over in a granular
// collapse (docs/sph.md, "Time step", the energy audit). step_start == nullptr takes the trial stress as the start.
inline ReturnResult return_to_yield_surface(const MaterialConstants& mc, Stress& s,
                                            const Stress* step_start = nullptr) {
  ReturnResult res;
  const Stress before = s;
  const Stress start = step_start ? *step_start : s;
  double I1 = s.xx + s.yy + s.zz;
  if (mc.alpha_phi > 0.0 && mc.alpha_phi * I1 - mc.k_c > 0.0) {
    const double shift = (I1 - mc.apex_i1) / 3.0;
    s.xx -= shift;
    s.yy -= shift;
    s.zz -= shift;
    I1 = s.xx + s.yy + s.zz;
    res.tension_cracked = true;
  }
  const double p = I1 / 3.0;
  double dxx = s.xx - p, dyy = s.yy - p, dzz = s.zz - p;
  const double sqrtJ2 = std::sqrt(0.5 * (dxx * dxx + dyy * dyy + dzz * dzz) + s.xy * s.xy);
  const double limit = mc.k_c - mc.alpha_phi * I1;
  if (sqrtJ2 > limit) {
    const double r = limit > 0.0 ? limit / sqrtJ2 : 0.0;
    s.xx = r * dxx + p;
    s.yy = r * dyy + p;
    s.zz = r * dzz + p;
    s.xy = r * s.xy;
    res.scaled = true;
  }
  if (res.tension_cracked || res.scaled) {
    const double d_xx = s.xx - before.xx, d_yy = s.yy - before.yy, d_zz = s.zz - before.zz, d_xy = s.xy - before.xy;
    const double dI1 = d_xx + d_yy + d_zz;
    const double dp = dI1 / 3.0;
    const double inv2G = mc.half_inv_shear, inv9K = mc.inv_9_bulk;
    const double exx = -((d_xx - dp) * inv2G + dI1 * inv9K);
    const double eyy = -((d_yy - dp) * inv2G + dI1 * inv9K);
    const double ezz = -((d_zz - dp) * inv2G + dI1 * inv9K);
    const double exy = -(d_xy * inv2G);
    res.plastic_strain = std::sqrt(2.0 / 3.0 * (exx * exx + eyy * eyy + ezz * ezz + 2.0 * exy * exy));
    res.plastic_work = 0.5 * ((s.xx + start.xx) * exx + (s.yy + start.yy) * eyy + (s.zz + start.zz) * ezz +
                              2.0 * (s.xy + start.xy) * exy);
  }
  return res;
}

}  // namespace sph::soil
