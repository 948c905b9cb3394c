#include "sph/fluid/stepper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "stepper_impl.hpp"
#include "sph/engine/run_loop.hpp"
#include "terms.hpp"

namespace sph::fluid {

namespace {

SolverChoice solver_choice(const Settings& st) {
  SolverChoice c;
  c.solver = st.solver;
  c.preconditioner = st.preconditioner;
  c.tolerance = st.solver_tolerance;
  c.max_iterations = st.solver_max_iterations;
  return c;
}

// The tolerance of the solves before the last of a step: they only give the walls' pressures for the next
// extrapolation (decision D22), so the looser of wall_pass_tolerance and the solver's tolerance.
double wall_pass_tolerance(const Settings& st) { return std::max(st.wall_pass_tolerance, st.solver_tolerance); }

}  // namespace

using detail::Index;
using detail::kFluid;
using detail::kSkinOverDx;


Step::Step(Model& model)
    : model_(model), impl_(std::make_unique<Impl>(model.settings.kernel, model.settings.smoothing_length())) {
  model.settings.validate();
  const double dx = model.settings.particle_spacing;
  const int reach = static_cast<int>(std::ceil(impl_->kernel.support() / dx)) + 1;
  double sum = 0;
  for (int a = -reach; a <= reach; ++a)
    for (int b = -reach; b <= reach; ++b) sum += impl_->kernel.value(dx * std::hypot(a, b)) * dx * dx;
  impl_->lattice_kernel_sum = sum;
}

Step::~Step() = default;

// The gravity acting at the current time (EngineSettings::gravity_factor: full, or ramped).
double Step::gravity_x() const { return model_.settings.gravity_factor(model_.state.time) * model_.settings.gravity_x; }
double Step::gravity_y() const { return model_.settings.gravity_factor(model_.state.time) * model_.settings.gravity_y; }

void Step::initialise() {
  impl_->sorted.reserve(model_.particles);
  ParticleSet& p = model_.particles;
  const double* speed = p.field(model_.fields.body_speed).data();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] == kFluid || p.material[i] == coupled_wall_material) continue;  // the coupling moves those
    if (!is_body(i)) {
      p.vx[i] = p.vy[i] = 0.0;  // fixed walls
      continue;
    }
    const RigidBody& b = model_.bodies[p.material[i] - 1u];  // a body's particles move with it
    p.vx[i] = speed[i] * b.direction_x;
    p.vy[i] = speed[i] * b.direction_y;
  }
  model_.state.rates_valid = true;  // the state carries no rates: the pressure of the last step is all it needs
}

double Step::stable_time_step() const {
  const Settings& st = model_.settings;
  const ParticleSet& p = model_.particles;
  double vmax2 = 0;
  for (std::size_t i = 0; i < p.size(); ++i)  // fluid and rigid bodies (fixed walls are at rest)
    vmax2 = std::max(vmax2, p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
  const double dx = st.particle_spacing;
  double dt = std::numeric_limits<double>::infinity();
  if (vmax2 > 0) dt = std::min(dt, st.cfl * dx / std::sqrt(vmax2));  // eq. 48
  const double g = std::hypot(st.gravity_x, st.gravity_y);
  if (g > 0) dt = std::min(dt, st.cfl * std::sqrt(dx / g));  // body force from rest (decision D9)
  if (st.viscosity > 0) dt = std::min(dt, st.viscous_alpha * dx * dx * st.rest_density / st.viscosity);  // eq. 49
  if (st.max_time_step > 0) dt = std::min(dt, st.max_time_step);
  return std::isfinite(dt) ? dt : dx;
}

// Steps 1 and 2 at r^n: V** = V^n + g dt + dt (mu/rho lap V*), walls at rest (no-slip).
void Step::viscous_step(double dt) {
  ParticleSet& p = model_.particles;
  const Settings& st = model_.settings;
  const PairList& pl = impl_->pairs;
  const Index n = static_cast<Index>(p.size());
  const double mu = st.viscosity, rho0 = st.rest_density, eta2 = st.eta() * st.eta();
  const double gx = gravity_x(), gy = gravity_y();
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] == kFluid) terms::body_force_step(p.vx[i], p.vy[i], gx, gy, dt);
  }
  impl_->ax.assign(p.size(), 0.0);
  impl_->ay.assign(p.size(), 0.0);
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] != kFluid || mu == 0) continue;
    double ax = 0, ay = 0;
    for (std::uint32_t q = pl.start[i]; q < pl.start[i + 1]; ++q) {
      const std::uint32_t j = pl.j[q];
      const double f = terms::viscous_factor(p.mass[j], mu, mu, rho0, rho0, pl.F[q], pl.r2[q], eta2);
      ax += f * (p.vx[i] - p.vx[j]);
      ay += f * (p.vy[i] - p.vy[j]);
    }
    impl_->ax[i] = ax;
    impl_->ay[i] = ay;
  }
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] != kFluid) continue;
    p.vx[i] += dt * impl_->ax[i];
    p.vy[i] += dt * impl_->ay[i];
  }
}

// rho* from continuity based on rho0 (eq. 32) and the kernel-sum density (eq. 43, decision D4), at r*.
void Step::provisional_density(double dt) {
  ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const PairList& pl = impl_->pairs;
  const Index n = static_cast<Index>(p.size());
  const double rho0 = model_.settings.rest_density, w0 = impl_->kernel.value(0.0);
  const double scale = 1.0 / impl_->lattice_kernel_sum;
  const bool correct = model_.settings.compression_correction;
  // the walls' velocity in the fluid's continuity sum: their own (0, or a rigid body's) plus the body-force
  // increment (decisions D7, D17)
  const double wvx = gravity_x() * dt, wvy = gravity_y() * dt;
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const bool fluid = p.kind[i] == kFluid;
    double div = 0, sum = terms::kernel_density_share(p.mass[i], w0);
    for (std::uint32_t q = pl.start[i]; q < pl.start[i + 1]; ++q) {
      const std::uint32_t j = pl.j[q];
      sum += terms::kernel_density_share(p.mass[j], pl.W[q]);
      if (!fluid) continue;
      const bool wall = p.kind[j] != kFluid;
      const double vjx = wall ? p.vx[j] + wvx : p.vx[j], vjy = wall ? p.vy[j] + wvy : p.vy[j];
      div += terms::continuity_share(p.mass[j], p.vx[i] - vjx, p.vy[i] - vjy, pl.F[q], pl.dx[q], pl.dy[q]);
    }
    a.kernel_density[i] = sum * scale;
    const double squeeze = correct && fluid ? terms::compression(a.kernel_density[i], rho0) : 0.0;
    a.provisional_density[i] = fluid ? rho0 + dt * div + squeeze : rho0;
  }
}

// The inverse kernel moment matrices at r* (renormalisation of the gradient: exact for a linear field on any
// particle arrangement, the identity on a full lattice).
void Step::moment_matrices() {
  const ParticleSet& p = model_.particles;
  const PairList& pl = impl_->pairs;
  const Index n = static_cast<Index>(p.size());
  const double rho0 = model_.settings.rest_density;
  impl_->lxx.assign(p.size(), 0.0);
  impl_->lxy.assign(p.size(), 0.0);
  impl_->lyy.assign(p.size(), 0.0);
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    double mxx = 0, mxy = 0, myy = 0;
    for (std::uint32_t q = pl.start[i]; q < pl.start[i + 1]; ++q) {
      if (impl_->dry[pl.j[q]]) continue;
      const double w = -p.mass[pl.j[q]] / rho0 * pl.F[q];
      mxx += w * pl.dx[q] * pl.dx[q];
      mxy += w * pl.dx[q] * pl.dy[q];
      myy += w * pl.dy[q] * pl.dy[q];
    }
    terms::invert_moment_matrix(mxx, mxy, myy, impl_->lxx[i], impl_->lxy[i], impl_->lyy[i]);
  }
}

// The renormalised gradient of a field f at particle i, L_i sum_j V_j (f_j - f_i) grad_i W_ij (0 where the
// renormalisation was refused).
void Step::renormalised_gradient(std::size_t i, const double* f, double& gx, double& gy) const {
  const ParticleSet& p = model_.particles;
  const PairList& pl = impl_->pairs;
  const double rho0 = model_.settings.rest_density;
  double sx = 0, sy = 0;
  for (std::uint32_t q = pl.start[i]; q < pl.start[i + 1]; ++q) {
    if (impl_->dry[pl.j[q]]) continue;
    const double w = p.mass[pl.j[q]] / rho0 * (f[pl.j[q]] - f[i]) * pl.F[q];
    sx += w * pl.dx[q];
    sy += w * pl.dy[q];
  }
  gx = impl_->lxx[i] * sx + impl_->lxy[i] * sy;
  gy = impl_->lxy[i] * sx + impl_->lyy[i] * sy;
}

// The roles in the pressure equation: fluid particles are unknowns, except free-surface ones (P = 0, given);
// wall particles hold the extrapolated pressure (given).
void Step::mark_roles() {
  ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const Settings& st = model_.settings;
  PoissonSystem& sys = impl_->system;
  sys.role.assign(p.size(), PressureRole::given);
  diag_.surface_particles = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    a.free_surface[i] = 0.0;
    if (p.kind[i] != kFluid) continue;
    const bool surface = terms::is_free_surface(a.kernel_density[i], st.surface_beta, st.rest_density);
    if (surface) {
      a.free_surface[i] = 1.0;
      a.pressure[i] = 0.0;
      ++diag_.surface_particles;
    } else {
      sys.role[i] = PressureRole::unknown;
    }
  }
}

// Wall pressure from the fluid around each wall particle (decisions D7, D8); 0 where no fluid is near.
void Step::extrapolate_wall_pressure() {
  ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const PairList& pl = impl_->pairs;
  const Settings& st = model_.settings;
  const Index n = static_cast<Index>(p.size());
  const double gx = gravity_x(), gy = gravity_y();
  const double* acceleration = p.field(model_.fields.body_acceleration).data();
  const auto coupled_ax = p.find_field(coupled_wall_acceleration_x);
  const auto coupled_ay = p.find_field(coupled_wall_acceleration_y);
  const double* cax = coupled_ax ? p.field(*coupled_ax).data() : nullptr;
  const double* cay = coupled_ay ? p.field(*coupled_ay).data() : nullptr;
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] == kFluid) continue;
    double ax = 0, ay = 0;  // a rigid body's acceleration: the Neumann condition dP/dn = rho (g - a).n (D18)
    if (is_body(i)) {
      const RigidBody& b = model_.bodies[p.material[i] - 1u];
      ax = acceleration[i] * b.direction_x;
      ay = acceleration[i] * b.direction_y;
    } else if (cax && cay && p.material[i] == coupled_wall_material) {  // another physics' (a coupled run's soil)
      ax = cax[i];
      ay = cay[i];
    }
    double num = 0, den = 0;
    for (std::uint32_t q = pl.start[i]; q < pl.start[i + 1]; ++q) {
      const std::uint32_t j = pl.j[q];
      if (p.kind[j] != kFluid) continue;  // walls read only fluid values (no data race)
      num += terms::wall_pressure_share(a.pressure[j], st.rest_density, gx - ax, gy - ay, pl.dx[q], pl.dy[q], pl.W[q]);
      den += pl.W[q];
    }
    a.pressure[i] = den > 0 ? std::max(num / den, 0.0) : 0.0;
  }
}

// Decision D13: wall particles whose pressure, extrapolated from the fluid's pressures of the last solve, is not
// positive (walls above the water line) are "dry": they leave the moment matrices and the renormalised gradient
// (they stay in the pressure equation as given values P = 0).
void Step::mark_dry_walls() {
  const ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  impl_->dry.assign(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i) impl_->dry[i] = p.kind[i] != kFluid && !(a.pressure[i] > 0.0);
}

// The coefficients B_ij (eq. 36), the sources (eq. 35) and b_i = sum_j B_ij x_ij (D14).
void Step::assemble_pressure_equation(double dt) {
  const ParticleSet& p = model_.particles;
  const PairList& pl = impl_->pairs;
  const Settings& st = model_.settings;
  PoissonSystem& sys = impl_->system;
  const double eta2 = st.eta() * st.eta();
  sys.start = pl.start;
  sys.col = pl.j;
  sys.coef.resize(pl.pair_count());
  sys.source.resize(p.size());
  sys.x = p.x;  // r*: the multigrid's aggregates
  sys.y = p.y;
  sys.aggregate_size = 2.0 * st.particle_spacing;
  impl_->bx.assign(p.size(), 0.0);
  impl_->by.assign(p.size(), 0.0);
  const Arrays a = model_.arrays();
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double ri = a.provisional_density[i];
    double bx = 0, by = 0;
    for (std::uint32_t q = pl.start[i]; q < pl.start[i + 1]; ++q) {
      const std::uint32_t j = pl.j[q];
      const double c = terms::laplacian_coefficient(p.mass[j], ri, a.provisional_density[j], pl.F[q], pl.r2[q], eta2);
      sys.coef[q] = c;
      bx += c * pl.dx[q];
      by += c * pl.dy[q];
    }
    impl_->bx[i] = bx;
    impl_->by[i] = by;
    sys.source[i] = terms::poisson_source(st.rest_density, ri, dt);
  }
  impl_->source0 = sys.source;
}

// Decision D14: the source of every unknown with the consistency term b_i . grad P_i, grad P_i the renormalised
// gradient of the current pressures (the last solve's, or the last step's before the first solve).
void Step::add_consistency_term() {
  const ParticleSet& p = model_.particles;
  PoissonSystem& sys = impl_->system;
  const double* pressure = p.field(model_.fields.pressure).data();
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (sys.role[i] != PressureRole::unknown) continue;
    double gx, gy;
    renormalised_gradient(i, pressure, gx, gy);
    sys.source[i] = impl_->source0[i] + terms::laplacian_consistency(impl_->bx[i], impl_->by[i], gx, gy);
  }
}

// Step 3: the pressure Poisson equation (eqs. 35-37), explicit (one Jacobi sweep) or solved, with the wall
// pressures extrapolated before each solve and after the last.
void Step::solve_pressure_equation(double dt) {
  const Settings& st = model_.settings;
  extrapolate_wall_pressure();
  mark_dry_walls();
  moment_matrices();
  assemble_pressure_equation(dt);
  const bool explicit_mode = st.pressure_mode == PressureMode::explicit_jacobi;
  if (!explicit_mode) impl_->solver.prepare(impl_->system, solver_choice(st));
  const int passes = explicit_mode ? 1 : st.wall_passes;
  diag_.solve_iterations = 0;
  diag_.fallbacks = 0;
  for (int pass = 0; pass < passes; ++pass) {
    if (pass > 0) extrapolate_wall_pressure();
    add_consistency_term();
    std::vector<double>& pressure = model_.particles.field(model_.fields.pressure);
    if (explicit_mode)
      diag_.solve = jacobi_sweep(impl_->system, pressure);
    else
      diag_.solve = impl_->solver.solve(impl_->system, pressure, pass + 1 < passes ? wall_pass_tolerance(st) : 0.0);
    diag_.solve_iterations += diag_.solve.iterations;
    diag_.fallbacks += diag_.solve.fell_back ? 1 : 0;
    if (!st.tension) clamp_tension(pressure);
  }
  extrapolate_wall_pressure();
  diag_.wall_passes = static_cast<std::size_t>(passes);
}

// Decision D21: no tension in the fluid. The unknowns' pressures below 0 are set to 0 after each solve (the walls'
// already are, D8): a splash's fragments under suction pulled each other together and blew up (the dam break
// against a wall 2a away at a/15, a/20; docs/isph.md D21).
void Step::clamp_tension(std::vector<double>& pressure) {
  const PoissonSystem& sys = impl_->system;
  std::size_t clamped = 0;
  for (std::size_t i = 0; i < pressure.size(); ++i)
    if (sys.role[i] == PressureRole::unknown && pressure[i] < 0.0) {
      pressure[i] = 0.0;
      ++clamped;
    }
  diag_.tension_clamped = clamped;
}

// V^{n+1} = V** + V_hat (eqs. 38-40, the surface doubling of eq. 46), densities rho*.
void Step::correct(double dt) {
  ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const PairList& pl = impl_->pairs;
  const Index n = static_cast<Index>(p.size());
  const bool mirror = model_.settings.surface_mirror;
  impl_->ax.assign(p.size(), 0.0);
  impl_->ay.assign(p.size(), 0.0);
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] != kFluid) continue;
    const double pi = a.pressure[i], ri = a.provisional_density[i];
    double gx = 0, gy = 0;
    for (std::uint32_t q = pl.start[i]; q < pl.start[i + 1]; ++q) {
      const std::uint32_t j = pl.j[q];
      const double f =
          terms::pressure_gradient_factor(p.mass[j], pi, ri, a.pressure[j], a.provisional_density[j], pl.F[q]);
      gx += f * pl.dx[q];
      gy += f * pl.dy[q];
    }
    const bool surface = a.free_surface[i] != 0.0;
    if (surface && !mirror && impl_->lxx[i] != 0.0) {  // decision D15: the renormalised surface gradient
      impl_->ax[i] = -(impl_->lxx[i] * gx + impl_->lxy[i] * gy);
      impl_->ay[i] = -(impl_->lxy[i] * gx + impl_->lyy[i] * gy);
      continue;
    }
    const double w = terms::surface_gradient_weight(mirror && surface);
    impl_->ax[i] = -w * gx;
    impl_->ay[i] = -w * gy;
  }
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] != kFluid) continue;
    p.vx[i] += dt * impl_->ax[i];
    p.vy[i] += dt * impl_->ay[i];
  }
}

// The step's one sort and its candidate pairs, at the current positions.
void Step::list_candidates() {
  ParticleSet& p = model_.particles;
  const double radius = impl_->kernel.support() + kSkinOverDx * model_.settings.particle_spacing;
  impl_->sorted.sort(p, radius);
  impl_->candidates.list(p, impl_->sorted, radius);
}

// Whether a particle has moved more than half the skin since the candidates were listed (at r^n: x_start).
bool Step::moved_beyond_half_skin() const {
  const ParticleSet& p = model_.particles;
  const double* xs = p.field(model_.fields.x_start).data();
  const double* ys = p.field(model_.fields.y_start).data();
  const double half = 0.5 * kSkinOverDx * model_.settings.particle_spacing, limit2 = half * half;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double ddx = p.x[i] - xs[i], ddy = p.y[i] - ys[i];
    if (ddx * ddx + ddy * ddy > limit2) return true;
  }
  return false;
}

void Step::advance(double dt) {
  ParticleSet& p = model_.particles;
  list_candidates();
  impl_->pairs.build(p, impl_->candidates, impl_->kernel);
  {
    const Arrays a = model_.arrays();
    for (std::size_t i = 0; i < p.size(); ++i) {
      a.x_start[i] = p.x[i];
      a.y_start[i] = p.y[i];
      a.vx_start[i] = p.vx[i];
      a.vy_start[i] = p.vy[i];
    }
  }
  viscous_step(dt);
  const double wvx = gravity_x() * dt, wvy = gravity_y() * dt;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool fluid = p.kind[i] == kFluid;
    p.x[i] = terms::temporary_position(p.x[i], fluid ? p.vx[i] : p.vx[i] + wvx, dt);  // walls: D12, D17
    p.y[i] = terms::temporary_position(p.y[i], fluid ? p.vy[i] : p.vy[i] + wvy, dt);
  }
  if (moved_beyond_half_skin()) list_candidates();  // a fast step: list again at r*
  impl_->pairs.build(p, impl_->candidates, impl_->kernel);
  provisional_density(dt);
  mark_roles();
  solve_pressure_equation(dt);
  correct(dt);
  body_forces();
  coupled_wall_forces();
  finish_positions(dt);
  move_bodies(dt);
  keep_off_walls();
  remove_escaped();
  diag_.time_step = dt;
  model_.state.time += dt;
  model_.state.step += 1;
}

// r^{n+1} by the trapezoidal rule (eqs. 31, 41-42) and the density error of the step.
void Step::finish_positions(double dt) {
  ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const double rho0 = model_.settings.rest_density;
  double err_max = 0, err_sum = 0;
  std::size_t nf = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != kFluid) {  // walls back to r^n (rigid bodies then move in move_bodies)
      p.x[i] = a.x_start[i];
      p.y[i] = a.y_start[i];
      continue;
    }
    p.x[i] = terms::trapezoidal_position(a.x_start[i], a.vx_start[i], p.vx[i], dt);
    p.y[i] = terms::trapezoidal_position(a.y_start[i], a.vy_start[i], p.vy[i], dt);
    const double e = std::abs(a.provisional_density[i] - rho0) / rho0;
    err_max = std::max(err_max, e);
    err_sum += e;
    ++nf;
  }
  diag_.max_density_error = err_max;
  diag_.mean_density_error = nf > 0 ? err_sum / static_cast<double>(nf) : 0.0;
}

// The fluid's energies plus the rigid bodies' (M v^2/2 and -M g.x_c at their centroids, M = density x area): the
// moving system's, so that the run loop's energy guard counts what a sliding body releases.
Energies Step::energies() const {
  Energies e = moving_energies(model_.particles, model_.settings);
  const ParticleSet& p = model_.particles;
  const double* travel = p.field(model_.fields.body_travel).data();
  const double* speed = p.field(model_.fields.body_speed).data();
  std::vector<char> seen(model_.bodies.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!is_body(i) || seen[p.material[i] - 1u]) continue;
    seen[p.material[i] - 1u] = 1;
    const RigidBody& b = model_.bodies[p.material[i] - 1u];
    const double x = b.centroid_x + travel[i] * b.direction_x, y = b.centroid_y + travel[i] * b.direction_y;
    e.kinetic += 0.5 * b.mass() * speed[i] * speed[i];
    e.potential -= b.mass() * (model_.settings.gravity_x * x + model_.settings.gravity_y * y);
  }
  return e;
}

Health Step::check_health() const {
  const ParticleSet& p = model_.particles;
  const ConstArrays a(model_.particles, model_.fields);
  Health h;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const char* bad = nullptr;
    if (!std::isfinite(p.x[i]) || !std::isfinite(p.y[i]))
      bad = "position";
    else if (!std::isfinite(p.vx[i]) || !std::isfinite(p.vy[i]))
      bad = "velocity";
    else if (!std::isfinite(a.pressure[i]))
      bad = "pressure";
    if (!bad) continue;
    std::ostringstream os;
    os << "particle " << p.id[i] << ": field " << bad << " is not finite at step " << model_.state.step;
    h.ok = false;
    h.diagnostic = os.str();
    return h;
  }
  return h;
}

}  // namespace sph::fluid
