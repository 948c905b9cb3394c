#pragma once
// The WC-MPS equations, one small inline function each, named after what it computes. The comment of each gives
// the seed's equation number (Jafari Nodoushan, Shakibaeinia & Hosseini 2016) and, in brackets, its row in the equation
// table of docs/mps.md. The loops that gather the pair terms over neighbours are in sph/src/mps/operators.cpp.
// Notation (MPS, the paper's): x_ij = x_j - x_i, y_ij = y_j - y_i, r = |r_ij|, phi_ij = phi_j - phi_i. The engine's
// neighbour iteration hands over x_i - x_j: the loops negate it. 2-D (d = 2). SI units.
// The paper prints phi_i - phi_j in eqs. 9, 10 and 11 (a sign typo, seed A7); the functions below use
// phi_j - phi_i, as its own eq. 24 does.
#include <algorithm>
#include <cmath>

namespace sph::mps::terms {

inline constexpr int dimensions = 2;  // d of the operators (the engine is 2-D)

// [M1] eq. 8: the weight w(r) = (1 - r/r_e)^3 for 0 <= r < r_e, 0 beyond (Shakibaeinia & Jin 2010); w(0) = 1.
inline double weight(double r, double re) {
  if (r >= re) return 0.0;
  const double s = 1.0 - r / re;
  return s * s * s;
}

// weight(sqrt(r2), re) for a pair already known to lie within the support (r2 < r_e^2, the neighbour list's filter),
// without weight's branch, so that a loop over a particle's pairs can be vectorised: the same operations in the
// same order, so the same value bit for bit wherever sqrt(r2) < r_e.
inline double weight_within_support(double r2, double re) {
  const double s = 1.0 - std::sqrt(r2) / re;
  return s * s * s;
}

// [M2] eq. 6: the particle number density n_i = sum_{j != i} w_ij; this is the pair's share.
inline double number_density_share(double w) { return w; }

// [M3] eq. 7: the density from the number density, rho_i = rho0 n_i / n0 [kg/m^3].
inline double density_from_number_density(double rho0, double n, double n0) { return rho0 * n / n0; }

// [M4] eq. 9 (sign fixed, A7) and eq. 24: the pair's share of the gradient sum,
// <grad phi>_i = (d/n0) sum_j (phi_j - phi_i) r_ij / r^2 w_ij; returns the factor (phi_j - phi_i) w / r^2 that
// multiplies r_ij = (x_ij, y_ij). The pressure gradient uses the same plain difference (eq. 24: no p_min).
inline double gradient_factor(double phi_ij, double w, double r2) { return phi_ij * w / r2; }

// [M5] eq. 10 (sign fixed, A7): the pair's share of the divergence sum,
// <div u>_i = (d/n0) sum_j (u_ij . r_ij) / r^2 w_ij, with u_ij = u_j - u_i.
inline double divergence_share(double u_ij, double v_ij, double x_ij, double y_ij, double w, double r2) {
  return (u_ij * x_ij + v_ij * y_ij) * w / r2;
}

// [M6] eq. 11 (sign fixed, A7): the pair's share of the Laplacian sum,
// <lap phi>_i = (2d/(lambda n0)) sum_j (phi_j - phi_i) w_ij.
inline double laplacian_share(double phi_ij, double w) { return phi_ij * w; }

// [M7] eq. 12: the pair's shares of lambda = sum_j r^2 w_ij / sum_j w_ij [m^2] (numerator; the denominator is n0).
inline double lambda_share(double r2, double w) { return r2 * w; }

// The prefactors of the sums above: d/n0 (gradient, divergence, strain rate) and 2d/(lambda n0) (Laplacian).
inline double gradient_prefactor(double n0) { return dimensions / n0; }
inline double laplacian_prefactor(double n0, double lambda) { return 2.0 * dimensions / (lambda * n0); }

// [M8] eq. 17 with A1: the pair's shares of the strain-rate (rate of deformation) tensor D = (grad u + grad u^T)/2,
// D_xx = (d/n0) sum u_ij x_ij w/r^2, D_yy = (d/n0) sum v_ij y_ij w/r^2,
// D_xy = (d/n0) sum (u_ij y_ij + v_ij x_ij) w/(2 r^2) (= the paper's (1/n0) sum (...) with d = 2). [1/s]
struct StrainRate {
  double xx = 0, yy = 0, xy = 0;
};
inline void add_strain_rate_share(StrainRate& s, double u_ij, double v_ij, double x_ij, double y_ij, double w,
                                  double r2) {
  const double f = w / r2;
  s.xx += u_ij * x_ij * f;
  s.yy += v_ij * y_ij * f;
  s.xy += 0.5 * (u_ij * y_ij + v_ij * x_ij) * f;
}

// [M9] eq. 3 with A1: |D| = sqrt(II_D) = sqrt(D:D / 2) [1/s]; in simple shear at rate gdot, |D| = gdot / 2.
inline double strain_rate_norm(const StrainRate& d) {
  return std::sqrt(0.5 * (d.xx * d.xx + d.yy * d.yy) + d.xy * d.xy);
}

// [M10] A1: the engineering shear rate gdot = 2 |D| [1/s].
inline double shear_rate(double norm_d) { return 2.0 * norm_d; }

// [M11] eq. 13: Tait's equation of state on the number density, p = (rho0 c0^2/gamma) ((n/n0)^gamma - 1) [Pa]
// (gamma = 7, A11). Negative below n0; clipping is an open decision (docs/mps.md).
inline double tait_pressure(double n, double n0, double rho0, double c0, double gamma) {
  return rho0 * c0 * c0 / gamma * (std::pow(n / n0, gamma) - 1.0);
}

// [M12] eq. 15: a free-surface particle has n <= beta n0; its pressure is set to 0.
inline bool is_free_surface(double n, double n0, double beta) { return n <= beta * n0; }

// [M13] eqs. 13 + 15: the pressure of a particle, 0 at the free surface, else Tait's.
inline double pressure(double n, double n0, double rho0, double c0, double gamma, double beta) {
  return is_free_surface(n, n0, beta) ? 0.0 : tait_pressure(n, n0, rho0, c0, gamma);
}

// [M14] eq. 20 with A4: the pair's shares of the Shepard-smoothed pressure p'_i = sum_{j != i} p_j w / sum w.
inline double smoothed_pressure_share(double p_j, double w) { return p_j * w; }

// [M15] eq. 3 with A5: the yield stress tau_y = c cos(phi) + p' sin(phi) with p' clamped at 0 (seed 2.9) [Pa];
// friction angle phi in radians, cohesion c in Pa.
inline double yield_stress(double cohesion, double friction_angle, double p_eff) {
  return cohesion * std::cos(friction_angle) + std::max(p_eff, 0.0) * std::sin(friction_angle);
}

// (1 - exp(-x)) / x as a function of x >= 0, accurate near 0 (limit 1).
inline double one_minus_exp_over(double x) { return x > 0 ? -std::expm1(-x) / x : 1.0; }

// [M16] eq. 16 as printed (A2 "as_printed"): mu = tau_y (1 - exp(-m |D|)) / (2 |D|) + mu0 |D|^(N-1) [Pa s];
// m [s], mu0 [Pa s^N]. At |D| = 0: +infinity for N < 1, mu0 + m tau_y / 2 for N = 1, m tau_y / 2 for N > 1.
inline double viscosity_as_printed(double tau_y, double norm_d, double mu0, double n_index, double m) {
  const double yield_part = 0.5 * m * tau_y * one_minus_exp_over(m * norm_d);
  if (norm_d <= 0) return n_index < 1 ? HUGE_VAL : yield_part + (n_index == 1 ? mu0 : 0.0);
  return yield_part + mu0 * std::pow(norm_d, n_index - 1.0);
}

// [M17] eq. 5 written in gdot = 2 |D| (A2 "consistent"): mu = tau_y (1 - exp(-m gdot)) / gdot + mu0 gdot^(N-1)
// [Pa s]. As m gdot -> infinity it is eq. 2's ideal Herschel-Bulkley tau_y / gdot + mu0 gdot^(N-1); at gdot = 0:
// +infinity for N < 1, mu0 + m tau_y for N = 1 (the paper's mu_max), m tau_y for N > 1.
inline double viscosity_consistent(double tau_y, double norm_d, double mu0, double n_index, double m) {
  const double gdot = shear_rate(norm_d);
  const double yield_part = m * tau_y * one_minus_exp_over(m * gdot);
  if (gdot <= 0) return n_index < 1 ? HUGE_VAL : yield_part + (n_index == 1 ? mu0 : 0.0);
  return yield_part + mu0 * std::pow(gdot, n_index - 1.0);
}

// [M18] eq. 2: the ideal Herschel-Bulkley viscosity above yield, tau_y / gdot + mu0 gdot^(N-1) [Pa s] (gdot > 0).
inline double viscosity_ideal(double tau_y, double gdot, double mu0, double n_index) {
  return tau_y / gdot + mu0 * std::pow(gdot, n_index - 1.0);
}

// [M19] seed A3: the viscosity cap, mu = min(mu, mu_cap) [Pa s] (mu_cap also where the law is infinite, |D| = 0).
inline double capped_viscosity(double mu, double mu_cap) { return std::min(mu, mu_cap); }

// [M20] section 6-2: the interaction viscosity of a pair, the harmonic mean mu_ij = 2 mu_i mu_j / (mu_i + mu_j)
// (default; mu_ij <= 2 min(mu_i, mu_j), 0 if either is 0), or the particle's own mu_i (the paper's comparison,
// Figs 8-9) [Pa s].
inline double harmonic_mean_viscosity(double mu_i, double mu_j) {
  const double sum = mu_i + mu_j;
  return sum > 0 ? 2.0 * mu_i * mu_j / sum : 0.0;
}

// [M21] eq. 22, the direct stress divergence: <div tau>_i = (2d/(lambda n0)) sum_j mu_ij (u_j - u_i) w_ij
// [N/m^3]; this is the pair's share mu_ij (u_j - u_i) w_ij of one velocity component (the paper's
// (4D/(lambda n0)) sum mu_i mu_j/(mu_i + mu_j) (...) is the same with the harmonic mean).
inline double viscous_share(double mu_ij, double u_ij, double w) { return mu_ij * u_ij * w; }

// [M22] eq. 30 with A9 (|u|_max, not the printed |mu|_max): dt = C_r min(dl / (c0 + |u|max), rho dl^2 / (2 d
// mu_max)) [s]; no viscous limit when mu_max <= 0.
inline double time_step(double courant, double dl, double c0, double u_max, double rho, double mu_max) {
  const double acoustic = dl / (c0 + u_max);
  const double viscous = mu_max > 0 ? rho * dl * dl / (2.0 * dimensions * mu_max) : HUGE_VAL;
  return courant * std::min(acoustic, viscous);
}

// [M26] eq. 28, the predictor (one velocity component): u* = u^m + (dt/rho_i) (f + <div tau>^m - (1 - alpha)
// <grad p>^m) [m/s], with f the body force per unit volume rho_i g [N/m^3] and alpha the pressure split (the
// relaxation factor of eqs. 28-29, named pressure_split in the settings: A23).
inline double predicted_velocity(double u, double dt, double rho, double body_force, double viscous, double grad_p,
                                 double pressure_split) {
  return u + dt / rho * (body_force + viscous - (1.0 - pressure_split) * grad_p);
}

// [M27] eq. 29, the corrector: u' = -alpha (dt/rho_i) <grad p>^{m+1}, with p^{m+1} from the EOS at the predicted
// positions r* = r^m + u* dt; then u^{m+1} = u* + u' (eq. 27) [m/s].
inline double velocity_correction(double dt, double rho, double grad_p_new, double pressure_split) {
  return -pressure_split * dt / rho * grad_p_new;
}

// [M28] A24: the new position from the old one and the new velocity, r^{m+1} = r^m + u^{m+1} dt [m] (not from r*).
inline double new_position(double x_old, double u_new, double dt) { return x_old + u_new * dt; }

// [M23] section 4-2 (Dalrymple & Rogers 2006): the density varies by less than about 1 % when c0 >= 10 |u|max.
inline constexpr double sound_speed_factor = 10.0;
inline bool sound_speed_sufficient(double c0, double u_max) { return c0 >= sound_speed_factor * u_max; }

}  // namespace sph::mps::terms
