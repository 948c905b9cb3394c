// The fluid stepper's boundaries (sph/fluid/stepper.hpp): the fluid's force on the rigid bodies and their motion,
// the wall clearance (decision D23) and the removal of particles that leave the domain (D11).
#include <algorithm>
#include <cmath>
#include <vector>

#include "stepper_impl.hpp"
#include "terms.hpp"

namespace sph::fluid {

using detail::Index;
using detail::kFluid;

bool Step::is_body(std::size_t i) const {
  const ParticleSet& p = model_.particles;
  return p.kind[i] != kFluid && p.material[i] > 0 && p.material[i] <= model_.bodies.size();
}

// The fluid's pressure force on every rigid body at r* (decision D19): the reaction of the pair forces of the
// symmetric gradient I9, m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) grad_j W_ji summed over the body's particles j and their
// fluid neighbours i; per particle in parallel, then summed in particle order (the same for any thread count).
void Step::body_forces() {
  const std::size_t nb = model_.bodies.size();
  diag_.body_force_x.assign(nb, 0.0);
  diag_.body_force_y.assign(nb, 0.0);
  if (nb == 0) return;
  const ParticleSet& p = model_.particles;
  const ConstArrays a(model_.particles, model_.fields);
  const PairList& pl = impl_->pairs;
  const Index n = static_cast<Index>(p.size());
  impl_->ax.assign(p.size(), 0.0);
  impl_->ay.assign(p.size(), 0.0);
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto jb = static_cast<std::size_t>(k);
    if (!is_body(jb)) continue;
    double fx = 0, fy = 0;
    for (std::uint32_t q = pl.start[jb]; q < pl.start[jb + 1]; ++q) {
      const std::uint32_t i = pl.j[q];
      if (p.kind[i] != kFluid) continue;
      // pl.dx = x_j - x_i here: grad_j W_ji = F (x_j - x_i); the force on j is -m_j m_i (...) grad_j W_ji
      const double f = -p.mass[jb] * terms::pressure_gradient_factor(p.mass[i], a.pressure[jb], a.provisional_density[jb],
                                                                       a.pressure[i], a.provisional_density[i], pl.F[q]);
      fx += f * pl.dx[q];
      fy += f * pl.dy[q];
    }
    impl_->ax[jb] = fx;
    impl_->ay[jb] = fy;
  }
  for (std::size_t j = 0; j < p.size(); ++j)
    if (is_body(j)) {
      diag_.body_force_x[p.material[j] - 1u] += impl_->ax[j];
      diag_.body_force_y[p.material[j] - 1u] += impl_->ay[j];
    }
}

// The fluid's pressure force on each coupled wall particle in excess of the reference pressure's: the pair forces of
// body_forces() with P - p_ref at both particles (p_ref at their positions r*), summed per wall particle.
void Step::coupled_wall_forces() {
  diag_.coupled_force_x.clear();
  diag_.coupled_force_y.clear();
  if (!reference_) return;
  const ParticleSet& p = model_.particles;
  bool any = false;
  for (std::size_t i = 0; i < p.size() && !any; ++i) any = p.material[i] == coupled_wall_material && p.kind[i] != kFluid;
  if (!any) return;
  const ConstArrays a(model_.particles, model_.fields);
  const PairList& pl = impl_->pairs;
  const Index n = static_cast<Index>(p.size());
  diag_.coupled_force_x.assign(p.size(), 0.0);
  diag_.coupled_force_y.assign(p.size(), 0.0);
  std::vector<double> excess(p.size());  // P - p_ref, once per particle (not per pair)
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    excess[i] = a.pressure[i] - reference_(p.x[i], p.y[i]);
  }
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto jw = static_cast<std::size_t>(k);
    if (p.material[jw] != coupled_wall_material || p.kind[jw] == kFluid) continue;
    const double pw = excess[jw];
    double fx = 0, fy = 0;
    for (std::uint32_t q = pl.start[jw]; q < pl.start[jw + 1]; ++q) {
      const std::uint32_t i = pl.j[q];
      if (p.kind[i] != kFluid) continue;
      const double pi = excess[i];
      // as in body_forces(): pl.dx = x_j - x_i, the force on j is -m_j m_i (...) grad_j W_ji
      const double f = -p.mass[jw] * terms::pressure_gradient_factor(p.mass[i], pw, a.provisional_density[jw], pi,
                                                                       a.provisional_density[i], pl.F[q]);
      fx += f * pl.dx[q];
      fy += f * pl.dy[q];
    }
    diag_.coupled_force_x[jw] = fx;
    diag_.coupled_force_y[jw] = fy;
  }
}

// The rigid bodies to t + dt: the prescribed law, or gravity and the fluid's force along the direction (free,
// frictionless, trapezoidal travel as the fluid's positions); held at stop_travel once reached (D19). Their
// particles are placed at x0 + s e with the velocity v e.
void Step::move_bodies(double dt) {
  if (model_.bodies.empty()) return;
  ParticleSet& p = model_.particles;
  double* travel = p.field(model_.fields.body_travel).data();
  double* speed = p.field(model_.fields.body_speed).data();
  double* acceleration = p.field(model_.fields.body_acceleration).data();
  const double t_end = model_.state.time + dt;
  const double gx = gravity_x(), gy = gravity_y();
  std::vector<double> s(model_.bodies.size(), 0.0), v(model_.bodies.size(), 0.0), acc(model_.bodies.size(), 0.0);
  std::vector<char> seen(model_.bodies.size(), 0);
  for (std::size_t i = 0; i < p.size() ; ++i) {  // the bodies' state at t (held by each of their particles)
    if (!is_body(i) || seen[p.material[i] - 1u]) continue;
    const std::size_t b = p.material[i] - 1u;
    seen[b] = 1;
    s[b] = travel[i];
    v[b] = speed[i];
  }
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const RigidBody& body = model_.bodies[b];
    const double s0 = s[b], v0 = v[b];
    if (s0 >= body.stop_travel || t_end <= body.start_time) {
      v[b] = acc[b] = 0.0;
      continue;
    }
    if (body.motion == RigidBody::Motion::free) {
      const double force = diag_.body_force_x[b] * body.direction_x + diag_.body_force_y[b] * body.direction_y;
      acc[b] = gx * body.direction_x + gy * body.direction_y + force / body.mass();
      v[b] = v0 + acc[b] * dt;
      s[b] = s0 + 0.5 * dt * (v0 + v[b]);
    } else {
      body.prescribed(t_end, s[b], v[b]);
      acc[b] = (v[b] - v0) / dt;
    }
    if (s[b] >= body.stop_travel) {  // the stop: abrupt, as the experiment's
      s[b] = body.stop_travel;
      v[b] = acc[b] = 0.0;
    }
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!is_body(i)) continue;
    const std::size_t b = p.material[i] - 1u;
    const RigidBody& body = model_.bodies[b];
    travel[i] = s[b];
    speed[i] = v[b];
    acceleration[i] = acc[b];
    p.x[i] = p.x0[i] + s[b] * body.direction_x;
    p.y[i] = p.y0[i] + s[b] * body.direction_y;
    p.vx[i] = v[b] * body.direction_x;
    p.vy[i] = v[b] * body.direction_y;
  }
}

// Decision D23: a fluid particle closer than the clearance to a wall or body particle at r^{n+1} is moved out along
// the walls' normal there, n = the kernel-weighted sum of the unit vectors from its wall neighbours to it, by the
// clearance less its distance to the nearest, and its velocity along -n (relative to that wall particle's) removed.
// The tangential velocity is kept: the wall is frictionless to this correction (using each wall particle's line of
// centres instead braked a thin sheet sliding along a floor: the Ritter front at 0.52 of its speed). Wall
// neighbours in the candidates' order (the same for any thread count); only the fluid particle moves.
void Step::keep_off_walls() {
  ParticleSet& p = model_.particles;
  diag_.wall_contacts = 0;
  const double clear = model_.settings.wall_clearance * model_.settings.particle_spacing;
  if (clear <= 0) return;
  const CandidateList& c = impl_->candidates;
  const FluidKernel& kernel = impl_->kernel;
  const double support2 = kernel.support() * kernel.support();
  std::size_t contacts = 0;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp parallel for schedule(static) reduction(+ : contacts)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    if (p.kind[i] != kFluid) continue;
    double nearest2 = clear * clear;
    std::size_t wall = p.size();
    for (std::uint32_t k = c.start[i]; k < c.start[i + 1]; ++k) {  // the nearest wall particle within the clearance
      const std::uint32_t j = c.j[k];
      if (p.kind[j] == kFluid) continue;
      const double rx = p.x[i] - p.x[j], ry = p.y[i] - p.y[j];
      const double r2 = rx * rx + ry * ry;
      if (r2 > 0 && r2 < nearest2) {
        nearest2 = r2;
        wall = j;
      }
    }
    if (wall == p.size()) continue;  // the common case: no wall particle that close
    double nx = 0, ny = 0;
    for (std::uint32_t k = c.start[i]; k < c.start[i + 1]; ++k) {  // the walls' normal there
      const std::uint32_t j = c.j[k];
      if (p.kind[j] == kFluid) continue;
      const double rx = p.x[i] - p.x[j], ry = p.y[i] - p.y[j];
      const double r2 = rx * rx + ry * ry;
      if (r2 <= 0 || r2 >= support2) continue;
      const double r = std::sqrt(r2), w = kernel.value(r) / r;
      nx += w * rx;
      ny += w * ry;
    }
    const double norm = std::sqrt(nx * nx + ny * ny);
    if (norm <= 0) continue;
    nx /= norm;
    ny /= norm;
    const double push = clear - std::sqrt(nearest2);
    p.x[i] += push * nx;
    p.y[i] += push * ny;
    const double vn = (p.vx[i] - p.vx[wall]) * nx + (p.vy[i] - p.vy[wall]) * ny;
    if (vn < 0) {
      p.vx[i] -= vn * nx;
      p.vy[i] -= vn * ny;
    }
    ++contacts;
  }
  diag_.wall_contacts = contacts;
}

// Fluid particles outside the domain are removed (the seed paper deletes particles that leave; D11).
void Step::remove_escaped() {
  ParticleSet& p = model_.particles;
  const Settings& st = model_.settings;
  diag_.removed_particles = 0;
  std::vector<std::uint8_t> drop(p.size(), 0);
  bool any = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != kFluid) continue;
    const bool out = !(p.x[i] >= st.domain_x_min && p.x[i] <= st.domain_x_max && p.y[i] >= st.domain_y_min &&
                       p.y[i] <= st.domain_y_max);
    drop[i] = out;
    any = any || out;
  }
  if (any) diag_.removed_particles = p.remove(drop);
}

}  // namespace sph::fluid
