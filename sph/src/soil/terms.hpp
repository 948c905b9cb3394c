#pragma once
// The soil model's per-pair equations (Bui, Fukagawa, Sako & Ohno 2008, IJNAMG 32:1537), one small inline function
// each, named after its equation; the tag in brackets is the row of the equation table in docs/sph.md. The
// parallel loop that gathers them over the neighbours of a particle is SoilStep's evaluate_rates
// (sph/src/soil_step.cpp). Notation: x_ij = x_i - x_j, v_ij = v_i - v_j, grad_i W_ij = F(r) x_ij, V_j = m_j/rho_j.
// Each function keeps the floating-point operations in the order the results were pinned with (tests/golden).
#include <algorithm>
#include <cmath>

namespace sph::soil::terms {

// The geometry of a pair within the kernel support: x_ij, r and grad_i W_ij [K1, K2].
struct PairGeometry {
  double dx, dy, r2, r, gwx, gwy;
};

// [C] Continuity: the pair's share of drho_i/dt = sum_j m_j (v_i - v_j) . grad_i W_ij, with v_j the neighbour's own
// velocity (a wall's is zero: its ghost velocity only imposes the slip condition; Adami, Hu & Adams 2012, sec. 2.3).
inline double continuity(double mj, double svx, double svy, const PairGeometry& g) {
  return mj * (svx * g.gwx + svy * g.gwy);
}

// [L] Velocity gradient L_ab = sum_j V_j (v_j - v_i)_a dW_ij/dx_i,b, accumulated from v_ij = v_i - v_j.
struct VelocityGradient {
  double xx = 0, xy = 0, yx = 0, yy = 0;
  void add(double vj, double dvx, double dvy, const PairGeometry& g) {
    xx -= vj * dvx * g.gwx;
    xy -= vj * dvx * g.gwy;
    yx -= vj * dvy * g.gwx;
    yy -= vj * dvy * g.gwy;
  }
};

// rho_bar of the pair: the arithmetic mean density [AV, X].
inline double mean_density(double rho_i, double rho_j) { return 0.5 * (rho_i + rho_j); }

// [AV] Monaghan artificial viscosity Pi_ij = (-alpha c_bar mu + beta mu^2) / rho_bar,
// mu = h min(v_ij . x_ij, 0) / (r^2 + eta^2): approaching pairs only.
inline double artificial_viscosity(double h, double eta2, double alpha, double beta, double c_i, double c_j,
                                   double rho_bar, double dvx, double dvy, const PairGeometry& g) {
  const double vr = std::min(dvx * g.dx + dvy * g.dy, 0.0);
  const double mu = h * vr / (g.r2 + eta2);
  return (-alpha * 0.5 * (c_i + c_j) * mu + beta * mu * mu) / rho_bar;
}

// [AS] The weight f_ij^n of the artificial stress (Gray, Monaghan & Swift 2001), f_ij = W(r_ij) / W(dx).
inline double artificial_stress_weight(double w_r, double inv_w_dx, double exponent) {
  const double f = w_r * inv_w_dx;
  return f > 0 ? std::exp(exponent * std::log(f)) : 0.0;
}

// [M] Momentum: the pair's share of dv_i/dt = sum_j m_j T_ij . grad_i W_ij, with the symmetric pair tensor
// T_ij = sigma_i/rho_i^2 + sigma_j/rho_j^2 - Pi_ij I (+ f^n (R_i + R_j)) given by its components.
inline void momentum(double mj, double txx, double tyy, double txy, const PairGeometry& g, double& ax, double& ay) {
  ax += mj * (txx * g.gwx + txy * g.gwy);
  ay += mj * (txy * g.gwx + tyy * g.gwy);
}

// [Δt] The Courant time step of the soil, cfl h / (c_max (1 + 1.2 alpha) + |v|max (1 + 2.4 beta)) (Monaghan's
// bound with the artificial viscosity's share; |v|max = 0 for the model at rest). SoilStep::stable_time_step takes
// the smaller of this and the acceleration bound; time_step_estimate plans runs with it.
inline double courant_time_step(double cfl, double h, double c_max, double alpha, double beta, double v_max) {
  return cfl * h / (c_max * (1.0 + 1.2 * alpha) + v_max * (1.0 + 2.4 * beta));
}

// [X] XSPH (Monaghan 1992): the pair's weight m_j / rho_bar W_ij in v_i += chi sum_j (m_j/rho_bar) (v_j - v_i) W_ij.
inline double xsph_weight(double mj, double rho_bar, double w_r) { return mj / rho_bar * w_r; }

}  // namespace sph::soil::terms
