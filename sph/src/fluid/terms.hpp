#pragma once
// The ISPH fluid's equations, one small inline function each, named after what it computes. The comment of each
// gives the seed paper's equation number (Hosseini Mobarra & Ghobadian 2020) and, in brackets, the row of
// the equation table in docs/isph.md. The loops that gather them over neighbours are in stepper.cpp and
// pressure.cpp. Notation: x_ij = x_i - x_j, r = |x_ij|, grad_i W_ij = F(r) x_ij with F = W'(r)/r < 0,
// so x_ij . grad_i W_ij = F r^2 <= 0.
#include <algorithm>
#include <cmath>

namespace sph::fluid::terms {

// [I1] eqs. 24-25, step 1: the body force alone, V* = V^n + g dt (no pressure in the predictor).
inline void body_force_step(double& vx, double& vy, double gx, double gy, double dt) {
  vx += gx * dt;
  vy += gy * dt;
}

// [I2] eq. 22, step 2: the viscous Laplacian of Morris et al. (1997) in the Shao & Lo (2003) form,
// (mu/rho lap V)_i = sum_j 4 m_j (mu_i + mu_j) (x_ij . grad_i W_ij) / ((rho_i + rho_j)^2 (r^2 + eta^2)) (V_i - V_j).
// Returns the pair's factor that multiplies (V_i - V_j). Densities: rho0 for both (decision D5).
inline double viscous_factor(double mj, double mu_i, double mu_j, double rho_i, double rho_j, double F, double r2,
                             double eta2) {
  const double rs = rho_i + rho_j;
  return 4.0 * mj * (mu_i + mu_j) * F * r2 / (rs * rs * (r2 + eta2));
}

// [I3] eqs. 29-30: temporary position r* = r^n + V** dt.
inline double temporary_position(double x, double v, double dt) { return x + v * dt; }

// [I4] eq. 32: the pair's share of the continuity sum, m_j (V_i - V_j) . grad_i W_ij; then
// rho*_i = rho0 + dt * sum (base rho0, not rho^n: decision D3).
inline double continuity_share(double mj, double dvx, double dvy, double F, double dx, double dy) {
  return mj * F * (dvx * dx + dvy * dy);
}

// [I4b] decision D3: the compression of particle i measured by its kernel-sum density (normalised by the sum of a
// particle at rest on the lattice), max(rho_sum_i - rho0, 0), added to rho* so that a compression left by earlier
// steps is pushed back (eq. 32 alone, based on rho0, forgets it). Expansion is left to gravity (a deficient kernel
// sum near the surface is not an expansion).
inline double compression(double kernel_density, double rho0) {
  return kernel_density > rho0 ? kernel_density - rho0 : 0.0;
}

// [I5] eq. 43 with decision D4: the free-surface indicator is the kernel sum rho_i = sum_j m_j W_ij (self
// included), not the continuity density of eq. 32 (which stays near rho0 at a still surface).
inline double kernel_density_share(double mj, double w) { return mj * w; }
inline bool is_free_surface(double kernel_density, double beta, double rho0) { return kernel_density < beta * rho0; }

// [I6] eqs. 36-37: the Laplacian coefficient of the pair, B_ij = m_j 8/(rho_i + rho_j)^2 (x_ij . grad_i W_ij) /
// (r^2 + eta^2) <= 0 (the (rho_i + rho_j)^2 of eq. 36, not the (rho_i^2 + rho_j^2) of eq. 9: decision D1), so that
// div((1/rho) grad P)_i = sum_j B_ij (P_i - P_j).
inline double laplacian_coefficient(double mj, double rho_i, double rho_j, double F, double r2, double eta2) {
  const double rs = rho_i + rho_j;
  return mj * 8.0 / (rs * rs) * F * r2 / (r2 + eta2);
}

// [I7] eq. 35: the density-invariance source of the pressure Poisson equation, (rho0 - rho*_i) / (rho0 dt^2).
inline double poisson_source(double rho0, double rho_star, double dt) { return (rho0 - rho_star) / (rho0 * dt * dt); }

// [I8] eq. 37: one point-Jacobi update of P_i from the neighbours' known pressures,
// P_i = (source_i + S_BP) / S_B with S_B = sum_j B_ij and S_BP = sum_j B_ij P_j (both sums over the neighbours
// that take part in the equation; S_B < 0).
inline double jacobi_pressure(double source, double sum_b, double sum_bp) { return (source + sum_bp) / sum_b; }

// [I9] eq. 38 (gradient form of eq. 7): the pair's factor of the pressure acceleration,
// -(1/rho grad P)_i = -sum_j m_j (P_i/rho_i^2 + P_j/rho_j^2) grad_i W_ij; returns m_j (P_i/rho_i^2 + P_j/rho_j^2) F,
// which multiplies -x_ij.
inline double pressure_gradient_factor(double mj, double p_i, double rho_i, double p_j, double rho_j, double F) {
  return mj * (p_i / (rho_i * rho_i) + p_j / (rho_j * rho_j)) * F;
}

// [I10] eq. 46: at a free-surface particle (P_s = 0) the mirror particle beyond the surface (P_m = -P_i) doubles
// the neighbours' share of the gradient (with grad_s W_sm = -grad_s W_si: the sign slip of eq. 45 corrected, D6).
inline double surface_gradient_weight(bool surface) { return surface ? 2.0 : 1.0; }

// [I12] decision D7 (replaces the mirror particles of section 2-8): a wall particle w takes the Shepard average of
// the pressure of the fluid around it plus the hydrostatic difference (Adami, Hu & Adams 2012),
// P_w = sum_f (P_f + rho_f g . x_wf) W_wf / sum_f W_wf, x_wf = x_w - x_f; this is the fluid particle f's share of
// the numerator. The wall pressure is not allowed below 0 (decision D8).
inline double wall_pressure_share(double p_f, double rho_f, double gx, double gy, double dx_wf, double dy_wf,
                                  double w) {
  return (p_f + rho_f * (gx * dx_wf + gy * dy_wf)) * w;
}

// [I13] decisions D14, D15: the inverse L = M^-1 of the symmetric kernel moment matrix M = [[mxx, mxy], [mxy, myy]],
// M = -sum_j V_j F_ij x_ij x_ij^T (the identity for a full support). Refused (L = 0) when the smallest
// eigenvalue of M is below 1/4: a particle with so little support (a splash) keeps the plain gradient.
inline void invert_moment_matrix(double mxx, double mxy, double myy, double& lxx, double& lxy, double& lyy) {
  const double det = mxx * myy - mxy * mxy, half_trace = 0.5 * (mxx + myy);
  const double smallest = half_trace - std::sqrt(std::max(half_trace * half_trace - det, 0.0));
  if (!(smallest >= 0.25)) {
    lxx = lxy = lyy = 0.0;
    return;
  }
  lxx = myy / det;
  lxy = -mxy / det;
  lyy = mxx / det;
}

// [I14] decision D14: the consistency term of the pressure equation, b_i . grad P_i with b_i = sum_j B_ij x_ij
// (0 for a full symmetric support). sum_j B_ij (P_i - P_j) = b_i . G for a linear field P of gradient G, so the
// equation sum_j B_ij (P_i - P_j) = s_i + b_i . grad P_i holds a hydrostatic field also where the support is cut
// by the free surface (without it the second row below the surface is 0.24 rho g dx too high).
inline double laplacian_consistency(double bx, double by, double gx, double gy) { return bx * gx + by * gy; }

// [I11] eqs. 31, 41-42: final position by the trapezoidal rule from the old position, r^{n+1} = r^n + dt/2 (V^n +
// V^{n+1}); the temporary r* is discarded.
inline double trapezoidal_position(double x_start, double v_start, double v_end, double dt) {
  return x_start + 0.5 * dt * (v_start + v_end);
}

}  // namespace sph::fluid::terms
