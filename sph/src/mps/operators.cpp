#include "sph/mps/operators.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>


namespace sph::mps {

LatticeConstants lattice_constants(double dx, double re) {
  if (!(dx > 0) || !(re > dx) || !std::isfinite(re))
    throw std::invalid_argument("mps lattice constants: need dx > 0 and r_e > dx (r_e = re_over_dx * dx)");
  const int reach = static_cast<int>(std::ceil(re / dx));
  double sum_w = 0, sum_r2w = 0;
  for (int k = -reach; k <= reach; ++k)
    for (int l = -reach; l <= reach; ++l) {
      if (k == 0 && l == 0) continue;
      const double r2 = (k * dx) * (k * dx) + (l * dx) * (l * dx);
      if (r2 >= re * re) continue;
      const double w = terms::weight(std::sqrt(r2), re);
      sum_w += terms::number_density_share(w);
      sum_r2w += terms::lambda_share(r2, w);
    }
  return {sum_w, sum_r2w / sum_w};
}

// The neighbour iteration of the engine, with the MPS's notation: x_ij = x_j - x_i (the engine gives x_i - x_j),
// the squared distance r2 and the weight w_ij.
template <class F>
static void for_each_mps_neighbour(const Neighbourhood& nb, std::size_t i, F&& f) {
  for_each_weighted_neighbour(nb, i, [&](std::size_t j, double dx, double dy, double r2, double w) {
    f(j, -dx, -dy, r2, w);
  });
}

double number_density(const Neighbourhood& nb, std::size_t i) {
  double n = 0;
  for_each_mps_neighbour(nb, i,
                         [&](std::size_t, double, double, double, double w) { n += terms::number_density_share(w); });
  return n;
}

void number_densities(const Neighbourhood& nb, double* n) {
  const auto count = static_cast<std::int64_t>(nb.set.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < count; ++k) n[k] = number_density(nb, static_cast<std::size_t>(k));
}

Vector2 gradient(const Neighbourhood& nb, std::size_t i, const double* phi, double n0) {
  Vector2 g;
  for_each_mps_neighbour(nb, i, [&](std::size_t j, double x_ij, double y_ij, double r2, double w) {
    const double f = terms::gradient_factor(phi[j] - phi[i], w, r2);
    g.x += f * x_ij;
    g.y += f * y_ij;
  });
  const double c = terms::gradient_prefactor(n0);
  return {c * g.x, c * g.y};
}

Vector2 stress_divergence(const Neighbourhood& nb, std::size_t i, const double* sxx, const double* syy,
                          const double* sxy, double n0) {
  Vector2 d;
  for_each_mps_neighbour(nb, i, [&](std::size_t j, double x_ij, double y_ij, double r2, double w) {
    const double fxx = terms::gradient_factor(sxx[j] - sxx[i], w, r2);
    const double fyy = terms::gradient_factor(syy[j] - syy[i], w, r2);
    const double fxy = terms::gradient_factor(sxy[j] - sxy[i], w, r2);
    d.x += fxx * x_ij + fxy * y_ij;
    d.y += fxy * x_ij + fyy * y_ij;
  });
  const double c = terms::gradient_prefactor(n0);
  return {c * d.x, c * d.y};
}

Vector2 full_viscous_force(const Neighbourhood& nb, std::size_t i, const double* u, const double* v, const double* mu,
                           const LatticeConstants& lattice, InteractionViscosity interaction) {
  Vector2 f;
  for_each_mps_neighbour(nb, i, [&](std::size_t j, double x_ij, double y_ij, double r2, double w) {
    add_full_viscous_share(f, i, j, x_ij, y_ij, r2, w, u, v, mu, interaction);
  });
  const double c = viscous_prefactor(lattice);
  return {c * f.x, c * f.y};
}

double divergence(const Neighbourhood& nb, std::size_t i, const double* u, const double* v, double n0) {
  double sum = 0;
  for_each_mps_neighbour(nb, i, [&](std::size_t j, double x_ij, double y_ij, double r2, double w) {
    sum += terms::divergence_share(u[j] - u[i], v[j] - v[i], x_ij, y_ij, w, r2);
  });
  return terms::gradient_prefactor(n0) * sum;
}

double laplacian(const Neighbourhood& nb, std::size_t i, const double* phi, const LatticeConstants& lattice) {
  double sum = 0;
  for_each_mps_neighbour(nb, i, [&](std::size_t j, double, double, double, double w) {
    sum += terms::laplacian_share(phi[j] - phi[i], w);
  });
  return terms::laplacian_prefactor(lattice.n0, lattice.lambda) * sum;
}

terms::StrainRate strain_rate(const Neighbourhood& nb, std::size_t i, const double* u, const double* v, double n0) {
  terms::StrainRate s;
  for_each_mps_neighbour(nb, i, [&](std::size_t j, double x_ij, double y_ij, double r2, double w) {
    terms::add_strain_rate_share(s, u[j] - u[i], v[j] - v[i], x_ij, y_ij, w, r2);
  });
  const double c = terms::gradient_prefactor(n0);
  return {c * s.xx, c * s.yy, c * s.xy};
}

Vector2 viscous_force(const Neighbourhood& nb, std::size_t i, const double* u, const double* v, const double* mu,
                      const LatticeConstants& lattice, InteractionViscosity interaction) {
  Vector2 f;
  for_each_mps_neighbour(nb, i, [&](std::size_t j, double, double, double, double w) {
    add_viscous_share(f, i, j, w, u, v, mu, interaction);
  });
  const double c = viscous_prefactor(lattice);
  return {c * f.x, c * f.y};
}

double smoothed_pressure(const Neighbourhood& nb, std::size_t i, const double* p) {
  double sum_pw = 0, sum_w = 0;
  for_each_mps_neighbour(nb, i, [&](std::size_t j, double, double, double, double w) {
    sum_pw += terms::smoothed_pressure_share(p[j], w);
    sum_w += w;
  });
  return sum_w > 0 ? sum_pw / sum_w : 0.0;
}

PressureAndStrainRate smoothed_pressure_and_strain_rate(const Neighbourhood& nb, std::size_t i, const double* p,
                                                        const double* u, const double* v, double n0) {
  double sum_pw = 0, sum_w = 0;
  terms::StrainRate s;
  for_each_mps_neighbour(nb, i, [&](std::size_t j, double x_ij, double y_ij, double r2, double w) {
    sum_pw += terms::smoothed_pressure_share(p[j], w);
    sum_w += w;
    terms::add_strain_rate_share(s, u[j] - u[i], v[j] - v[i], x_ij, y_ij, w, r2);
  });
  const double c = terms::gradient_prefactor(n0);
  return {sum_w > 0 ? sum_pw / sum_w : 0.0, {c * s.xx, c * s.yy, c * s.xy}, sum_w};
}

}  // namespace sph::mps
