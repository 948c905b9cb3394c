#pragma once
// The MPS operators of the WC-MPS (seed eqs. 6-12, 17, 20) gathered over a particle's neighbours with the engine's
// cell list (sph/engine/neighbours.hpp), and the reference number density n0 and lambda of the initial lattice.
// Every neighbour within r_e of particle i takes part (j != i), whatever its kind: walls and dummy particles
// included (they exist to complete the sums near a wall, seed 2.7). The pair equations are in sph/mps/terms.hpp.
// SI units, 2-D.
#include <cmath>
#include <cstddef>

#include "sph/engine/cell_sort.hpp"
#include "sph/engine/neighbour_list.hpp"
#include "sph/engine/neighbours.hpp"
#include "sph/engine/particle_set.hpp"
#include "sph/mps/settings.hpp"
#include "sph/mps/terms.hpp"

namespace sph::mps {

// The reference values of an interior particle of the initial square lattice (seed eq. 12, computed discretely as
// the seed advises: the continuous lambda = r_e^2/7 is 16 % smaller at r_e = 4 dx).
struct LatticeConstants {
  double n0 = 0;  // number density sum_{j != i} w_ij [-]
  double lambda = 0;  // sum r^2 w / sum w [m^2]
};

// n0 and lambda of a particle with a full neighbourhood on the square lattice of spacing dx [m], weight radius
// re [m]: the direct sum over the lattice offsets (k dx, l dx), (k, l) != (0, 0), closer than re.
// Throws std::invalid_argument unless dx > 0 and re > dx (at least the first ring must be in reach).
LatticeConstants lattice_constants(double dx, double re);

// Where the operators look: a set sorted by its CellSortedSet with cells of side >= re, and the radius re [m];
// with `list`, the neighbour list built after that sort with radius re and the weight w_ij of each pair as its
// value, valid while the positions are those of the sort (the stepper's passes read it instead of the cells: the
// same neighbours in the same order and the same weights, so the same sums bit for bit).
struct Neighbourhood {
  const CellSortedSet& sorted;
  const ParticleSet& set;
  double re;
  const NeighbourList* list = nullptr;
};

// Every particle j != i within re of particle i with its weight: f(j, dx, dy, r2, w_ij), (dx, dy) = x_i - x_j as
// for_each_neighbour gives it.
template <class F>
void for_each_weighted_neighbour(const Neighbourhood& nb, std::size_t i, F&& f) {
  if (nb.list) {
    for_each_listed_pair(*nb.list, nb.set, i, f);
    return;
  }
  for_each_neighbour(nb.sorted, nb.set, i, nb.re, [&](std::size_t j, double dx, double dy, double r2) {
    f(j, dx, dy, r2, terms::weight(std::sqrt(r2), nb.re));
  });
}

// Every particle j != i within `radius` (<= re) of particle i at the current positions, through the list when
// there is one (a pair must then have been within re at the sort): f(j, dx, dy, r2) as for_each_neighbour.
template <class F>
void for_each_within(const Neighbourhood& nb, std::size_t i, double radius, F&& f) {
  if (nb.list)
    for_each_listed_neighbour(*nb.list, nb.set, i, radius, f);
  else
    for_each_neighbour(nb.sorted, nb.set, i, radius, f);
}

struct Vector2 {
  double x = 0, y = 0;
};

// [M2] n_i = sum_{j != i} w_ij [-].
double number_density(const Neighbourhood& nb, std::size_t i);
// Fills n[i] for every particle of the set.
void number_densities(const Neighbourhood& nb, double* n);

// [M4] <grad phi>_i = (d/n0) sum_j (phi_j - phi_i) r_ij / r^2 w_ij [unit of phi / m].
Vector2 gradient(const Neighbourhood& nb, std::size_t i, const double* phi, double n0);

// [M5] <div u>_i = (d/n0) sum_j (u_j - u_i) . r_ij / r^2 w_ij [1/s] for the vector field (u, v) [m/s].
double divergence(const Neighbourhood& nb, std::size_t i, const double* u, const double* v, double n0);

// [M6] <lap phi>_i = (2d/(lambda n0)) sum_j (phi_j - phi_i) w_ij [unit of phi / m^2].
double laplacian(const Neighbourhood& nb, std::size_t i, const double* phi, const LatticeConstants& lattice);

// [M8] D_i = (grad u + grad u^T)/2 by the MPS gradient of each velocity component [1/s].
terms::StrainRate strain_rate(const Neighbourhood& nb, std::size_t i, const double* u, const double* v, double n0);

// [M20, M21] the direct stress divergence of seed eq. 22, <div tau>_i = (2d/(lambda n0)) sum_j mu_ij (u_j - u_i)
// w_ij [N/m^3] for the velocity (u, v) [m/s] and the particle viscosities mu [Pa s], with mu_ij the harmonic mean
// or mu_i (settings.interaction_viscosity). Divide by rho_i for the acceleration.
Vector2 viscous_force(const Neighbourhood& nb, std::size_t i, const double* u, const double* v, const double* mu,
                      const LatticeConstants& lattice, InteractionViscosity interaction);

// The viscosity of the pair (i, j) [Pa s]: the harmonic mean of mu_i and mu_j, or mu_i (`interaction`).
inline double pair_viscosity(std::size_t i, std::size_t j, const double* mu, InteractionViscosity interaction) {
  return interaction == InteractionViscosity::harmonic_mean ? terms::harmonic_mean_viscosity(mu[i], mu[j]) : mu[i];
}

// The pair (i, j)'s share of viscous_force's sum before its prefactor, added to f: mu_ij (u_j - u_i) w_ij with mu_ij
// by `interaction` (for a pass that gathers other sums in the same loop).
inline void add_viscous_share(Vector2& f, std::size_t i, std::size_t j, double w, const double* u, const double* v,
                              const double* mu, InteractionViscosity interaction) {
  const double mu_ij = pair_viscosity(i, j, mu, interaction);
  f.x += terms::viscous_share(mu_ij, u[j] - u[i], w);
  f.y += terms::viscous_share(mu_ij, v[j] - v[i], w);
}

// viscous_force's prefactor 2d/(lambda n0) [1/m^2].
inline double viscous_prefactor(const LatticeConstants& lattice) {
  return terms::laplacian_prefactor(lattice.n0, lattice.lambda);
}

// The viscous force div(2 mu D) as a pair sum (stress_divergence "full") [N/m^3]: (2d/(lambda n0)) sum_j mu_ij w_ij
// (du/2 + 2 (e . du) e), du = u_j - u_i, e = r_ij/|r_ij|, mu_ij as in viscous_force. With the 2-D averages
// <e e> = I/2 and <e_a e_b e_c e_d> = (d_ab d_cd + d_ac d_bd + d_ad d_bc)/8 the first term gives mu lap(u)/2 and the
// second mu (lap u + 2 grad div u)/2: together mu (lap u + grad div u) = div(2 mu D) for a uniform mu. With the
// harmonic-mean mu_ij a pair's two forces are equal and opposite and their power is never positive.
Vector2 full_viscous_force(const Neighbourhood& nb, std::size_t i, const double* u, const double* v, const double* mu,
                           const LatticeConstants& lattice, InteractionViscosity interaction);

// The pair (i, j)'s share of full_viscous_force's sum before its prefactor, added to f: mu_ij w_ij (du/2 + 2 (e . du)
// e) with x_ij = x_j - x_i, y_ij and r2 = |x_ij|^2 (for a pass that gathers other sums in the same loop).
inline void add_full_viscous_share(Vector2& f, std::size_t i, std::size_t j, double x_ij, double y_ij, double r2,
                                   double w, const double* u, const double* v, const double* mu,
                                   InteractionViscosity interaction) {
  const double mu_ij = pair_viscosity(i, j, mu, interaction);
  const double du = u[j] - u[i], dv = v[j] - v[i];
  const double along = (du * x_ij + dv * y_ij) / r2;  // (e . du) / r
  f.x += mu_ij * w * (0.5 * du + 2.0 * along * x_ij);
  f.y += mu_ij * w * (0.5 * dv + 2.0 * along * y_ij);
}

// [M29] the indirect stress divergence of seed eq. 23: <div tau>_i = (<d tau_xx/dx> + <d tau_xy/dy>, <d tau_xy/dx> +
// <d tau_yy/dy>) [N/m^3] by the MPS gradient [M4] of the particles' stresses tau = 2 mu D [Pa] (symmetric: sxy is
// both off-diagonal components). One neighbour pass for the three gradients.
Vector2 stress_divergence(const Neighbourhood& nb, std::size_t i, const double* sxx, const double* syy,
                          const double* sxy, double n0);

// [M14] p'_i = sum_{j != i} p_j w_ij / sum_{j != i} w_ij [Pa] (Shepard, A4), not clamped (the yield stress clamps
// it); 0 for a particle without neighbours.
double smoothed_pressure(const Neighbourhood& nb, std::size_t i, const double* p);

// smoothed_pressure and strain_rate of particle i in one neighbour pass: the same sums in the same order, so the
// same values bit for bit.
struct PressureAndStrainRate {
  double smoothed_pressure = 0;  // [Pa]
  terms::StrainRate strain_rate;  // [1/s]
  double number_density = 0;  // n_i = sum w_ij, Shepard's denominator [-] (smoothed_pressure_and_strain_rate only)
};
PressureAndStrainRate smoothed_pressure_and_strain_rate(const Neighbourhood& nb, std::size_t i, const double* p,
                                                        const double* u, const double* v, double n0);

}  // namespace sph::mps
