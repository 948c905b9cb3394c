#include "sph/mps/stepper.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <sstream>

#include "sph/engine/cell_sort.hpp"
#include "sph/engine/run_loop.hpp"
#include "sph/mps/effective_pressure.hpp"
#include "sph/mps/terms.hpp"

namespace sph::mps {

namespace {
using Index = std::int64_t;  // OpenMP loop index
constexpr std::uint8_t kMoving = static_cast<std::uint8_t>(ParticleKind::material);
// The candidates' margin beyond r_e in spacings: at the time step of eq. 30 (cfl 0.2, c0 >= 10 |u|max) a particle
// moves at most 0.02 dx per step, so the candidates last at least a dozen steps.
constexpr double list_skin = 0.5;

// The pair's share of eq. 24's sum before its prefactor, added to g: (p_j - base) w_ij / r^2 x_ij, with the
// engine's (dx, dy) = x_i - x_j = -x_ij.
inline void add_gradient_share(Vector2& g, double p_difference, double dx, double dy, double r2, double w) {
  const double f = terms::gradient_factor(p_difference, w, r2);
  g.x -= f * dx;
  g.y -= f * dy;
}
}  // namespace

struct Step::Impl {
  CellSortedSet sorted;  // by cells of side r_e + s at the last listing of the candidates
  NeighbourList candidates{false};  // the pairs within r_e + s at the listing positions (fields x/y_listed)
  bool candidates_listed = false;
  std::uint64_t listings = 0;
  NeighbourList list;  // the pairs within r_e at the current positions, with w_ij
  std::vector<std::uint8_t> near_fixed;  // 1 where a candidate is a wall, dummy or gate particle (at the listing)
  FieldId x_start = 0, y_start = 0;  // r^m during a step [m] (workspace, reordered with the set)
  std::vector<double> fx, fy;  // the non-pressure forces of the predictor [N/m^3]
  std::vector<double> weight_above;  // the hydrostatic p' of every particle [Pa] (effective_pressure hydrostatic)
  std::vector<double> sxx, syy, sxy;  // each particle's viscous stress 2 mu D [Pa] (stress_divergence indirect)
  std::vector<double> density;  // each material's reference density rho_i [kg/m^3] (seed eq. 26)
  std::vector<double> grain_fraction;  // each material's phi0 (water 0)
  std::vector<std::uint8_t> granular;  // 1 for each granular material
  bool mixture = false;  // materials of different densities: the EOS takes the mixture density <rho>
  double pore_density = 0;  // rho_w of the pore pressure (PorePressure::hydrostatic), else 0
  double gravity = 0;  // |g| at the current step [m/s^2] (the pore pressure)
  std::vector<double> depth;  // each particle's depth below the moving material's surface [m] (hydrostatic p', pores)
  std::unique_ptr<SurfaceStrips> strips;  // the moving material's surface at r^m (the depths of eq. 19)
};

Step::Step(Model& model) : model_(model), impl_(std::make_unique<Impl>()) {
  model.settings.validate();
  lattice_ = lattice_constants(model.settings.particle_spacing, model.settings.effective_radius());
  impl_->x_start = model.particles.add_field({"mps_x_start", false, false});
  impl_->y_start = model.particles.add_field({"mps_y_start", false, false});
  for (std::size_t m = 0; m < model.materials.size(); ++m) {
    impl_->density.push_back(model.density_of(m));
    impl_->grain_fraction.push_back(model.grain_fraction_of(m));
    impl_->granular.push_back(model.materials[m].type == Material::Type::granular ? 1 : 0);
  }
  impl_->mixture = !model.single_density();
  if (model.settings.pore_pressure == PorePressure::hydrostatic)
    impl_->pore_density = model.density_of(model.water_material().value());
}

// A particle's material index, clamped to the table (a set built elsewhere may carry larger labels on its walls).
std::size_t Step::material_of(std::size_t i) const {
  return std::min<std::size_t>(model_.particles.material[i], impl_->density.size() - 1);
}

Step::~Step() = default;

double Step::gravity_x() const { return model_.settings.gravity_factor(model_.state.time) * model_.settings.gravity_x; }
double Step::gravity_y() const { return model_.settings.gravity_factor(model_.state.time) * model_.settings.gravity_y; }

Neighbourhood Step::neighbourhood() const {
  return {impl_->sorted, model_.particles, model_.settings.effective_radius(), &impl_->list};
}

double Step::skin() const { return list_skin * model_.settings.particle_spacing; }

// Sorts by cells of side r_e + s, lists the candidates within r_e + s and keeps their positions.
void Step::list_candidates() {
  ParticleSet& p = model_.particles;
  const double radius = model_.settings.effective_radius() + skin();
  impl_->sorted.sort(p, radius);
  impl_->candidates.build(impl_->sorted, p, radius, [](double) { return 0.0; });
  near_fixed_particles();
  impl_->candidates_listed = true;
  ++impl_->listings;
}

std::uint64_t Step::candidate_listings() const { return impl_->listings; }

const NeighbourList& Step::pairs_at_predicted_positions() const { return impl_->list; }

// Marks each particle with a wall, dummy or gate particle among its candidates: the others cannot touch a wall
// before the next listing (collide_with_walls skips them).
void Step::near_fixed_particles() {
  const ParticleSet& p = model_.particles;
  const NeighbourList& c = impl_->candidates;
  impl_->near_fixed.resize(p.size());
  const auto n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const std::uint32_t* j = c.neighbours(i);
    const std::size_t count = c.count(i);
    std::uint8_t near = 0;
    for (std::size_t q = 0; q < count; ++q) near |= p.kind[j[q]] != kMoving ? 1 : 0;
    impl_->near_fixed[i] = near;
  }
}

// A resumed run: the set is in the order of the sort at the stored listing positions, so sorting at those
// positions again keeps the order (the sort is stable) and the candidates come out as they were.
void Step::relist_candidates_at_stored_positions() {
  ParticleSet& p = model_.particles;
  std::swap(p.x, p.field(model_.fields.x_listed));
  std::swap(p.y, p.field(model_.fields.y_listed));
  list_candidates();
  std::swap(p.x, p.field(model_.fields.x_listed));
  std::swap(p.y, p.field(model_.fields.y_listed));
}

bool Step::moved_beyond_half_skin() const {
  const ParticleSet& p = model_.particles;
  const double* xl = p.field(model_.fields.x_listed).data();
  const double* yl = p.field(model_.fields.y_listed).data();
  double d2 = 0;
  const auto n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static) reduction(max : d2)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double dx = p.x[i] - xl[i], dy = p.y[i] - yl[i];
    d2 = std::max(d2, dx * dx + dy * dy);
  }
  const double half = 0.5 * skin();
  return d2 > half * half;
}

// The pairs within r_e at the current positions with w_ij, from the candidates (listed again when needed): the
// passes until the next call read them (the wall collision reads them after the corrector's small move: a pair
// closer than d_c < r_e then was within r_e at r*). With number_density, each particle's n_i = sum w_ij [M2] summed
// in list order as the weights are computed (the sum number_densities would give, bit for bit) into the field
// number_density, whose storage is taken after the sort: a sort reorders the fields and may move them.
void Step::list_neighbours(bool number_density) {
  if (!impl_->candidates_listed || moved_beyond_half_skin()) {
    list_candidates();
    ParticleSet& p = model_.particles;
    p.field(model_.fields.x_listed) = p.x;
    p.field(model_.fields.y_listed) = p.y;
  }
  double* const sums = number_density ? model_.arrays().number_density : nullptr;
  const double re = model_.settings.effective_radius();
  impl_->list.build_from(impl_->candidates, model_.particles, re,
                         [re](double r2) { return terms::weight_within_support(r2, re); }, sums);
}

void Step::initialise() {
  ParticleSet& p = model_.particles;
  impl_->sorted.reserve(p);
  const double* gate = p.field(model_.gate).data();
  for (std::size_t i = 0; i < p.size(); ++i)  // walls are fixed; the gate keeps its (checkpointed) velocity
    if (p.kind[i] != kMoving && gate[i] == 0.0) p.vx[i] = p.vy[i] = 0.0;
  if (model_.state.rates_valid) relist_candidates_at_stored_positions();  // a resumed run
  list_neighbours();
  viscosities();  // mu of the current state, for the first time step
  model_.state.rates_valid = true;  // the carried state is p^m (checkpointed) and the positions and velocities
}

// [M24] (eq. 19): every particle's depth below the highest moving particle's centre within dx in x [m], from the
// strips of surface_strips().
void Step::depths_below_surface() {
  const SurfaceStrips& strips = *impl_->strips;
  impl_->depth.resize(model_.particles.size());
  for (std::size_t i = 0; i < impl_->depth.size(); ++i) impl_->depth[i] = strips.depth(i);
}

// [M25] (eq. 18), the hydrostatic p' of particle i at depth h below the moving material's surface: rho_i |g|
// (h + dx/2) (rho_i its material's density); 0 for a wall particle with no moving particle above it.
double Step::weight_above(std::size_t i, double h) const {
  if (model_.particles.kind[i] != kMoving && !(h > 0)) return 0.0;
  const double depth = h + 0.5 * model_.settings.particle_spacing;
  return hydrostatic_pressure(impl_->density[material_of(i)], impl_->gravity, depth);
}

// The hydrostatic p' of every particle (weight_above at impl_->depth).
void Step::hydrostatic_pressures() {
  const std::vector<double>& h = impl_->depth;
  std::vector<double>& w = impl_->weight_above;
  w.resize(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) w[i] = weight_above(i, h[i]);
}

// The moving material's surface at r^m, binned in strips of dx, for the depths of eq. 19.
void Step::surface_strips() {
  const ParticleSet& p = model_.particles;
  std::vector<std::uint8_t> surface(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) surface[i] = p.kind[i] == kMoving ? 1 : 0;
  impl_->strips = std::make_unique<SurfaceStrips>(p, surface, model_.settings.particle_spacing);
}

// smoothed_thin_layer: particle i's p' before the pore pressure [Pa], the smoothed p' or, where its neighbourhood is
// incomplete (n_i below n0 by more than rounding), the weight above it if that is larger.
double Step::thin_layer_pressure(std::size_t i, const PressureAndStrainRate& ps) const {
  constexpr double complete = 1.0 - 1e-6;  // an interior particle's n_i differs from n0 by rounding only
  if (!(ps.number_density < complete * lattice_.n0)) return ps.smoothed_pressure;
  return std::max(ps.smoothed_pressure, weight_above(i, impl_->strips->depth(i)));
}

// A6, PorePressure::hydrostatic: rho_w |g| (h + dx/2) for a granular particle, else 0 [Pa].
double Step::pore_pressure(std::size_t i) const {
  if (impl_->pore_density == 0 || !impl_->granular[material_of(i)]) return 0.0;
  const double depth = impl_->depth[i] + 0.5 * model_.settings.particle_spacing;
  return hydrostatic_pressure(impl_->pore_density, impl_->gravity, depth);
}

// Steps b and c at r^m: p' (Shepard, clamped >= 0, from p^m; or hydrostatic), then each particle's viscosity by
// its material; for the indirect stress divergence, each particle's stress 2 mu D.
void Step::viscosities() {
  ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const Settings& st = model_.settings;
  const auto n = static_cast<Index>(p.size());
  const bool hydrostatic = st.effective_pressure == EffectivePressure::hydrostatic;
  const bool thin_layer = st.effective_pressure == EffectivePressure::smoothed_thin_layer;
  const bool indirect = st.stress_divergence == StressDivergence::indirect;
  impl_->gravity = std::hypot(gravity_x(), gravity_y());
  const bool all_depths = hydrostatic || impl_->pore_density > 0;
  if (all_depths || thin_layer) surface_strips();  // thin_layer asks for the depths of a few particles only
  if (all_depths) depths_below_surface();
  if (hydrostatic) hydrostatic_pressures();
  if (indirect) {
    impl_->sxx.assign(p.size(), 0.0);
    impl_->syy.assign(p.size(), 0.0);
    impl_->sxy.assign(p.size(), 0.0);
  }
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const Material& mat = model_.materials[material_of(i)];
    const bool water = mat.type == Material::Type::water;
    const bool needs_rate = indirect || !water;
    const PressureAndStrainRate ps = pressure_and_strain_rate(i, hydrostatic, needs_rate);
    const double total = thin_layer && !water ? thin_layer_pressure(i, ps) : ps.smoothed_pressure;
    a.smoothed_pressure[i] = std::max(total - pore_pressure(i), 0.0);
    if (!needs_rate) {
      a.viscosity[i] = mat.viscosity;
      continue;
    }
    const terms::StrainRate& d = ps.strain_rate;
    a.viscosity[i] = water ? mat.viscosity
                           : effective_viscosity(mat.granular, a.smoothed_pressure[i], terms::strain_rate_norm(d),
                                                 st.regularisation, st.viscosity_cap);
    if (indirect) {
      impl_->sxx[i] = 2.0 * a.viscosity[i] * d.xx;
      impl_->syy[i] = 2.0 * a.viscosity[i] * d.yy;
      impl_->sxy[i] = 2.0 * a.viscosity[i] * d.xy;
    }
  }
}

// Particle i's total p' before the pore pressure (hydrostatic, or Shepard from p^m) and, when needed, its strain
// rate D: one neighbour pass when both come from the neighbours.
PressureAndStrainRate Step::pressure_and_strain_rate(std::size_t i, bool hydrostatic, bool needs_rate) const {
  const ParticleSet& p = model_.particles;
  const Neighbourhood nb = neighbourhood();
  const double* pressure = p.field(model_.fields.pressure).data();
  PressureAndStrainRate ps;
  if (hydrostatic) {
    ps.smoothed_pressure = impl_->weight_above[i];
    if (needs_rate) ps.strain_rate = strain_rate(nb, i, p.vx.data(), p.vy.data(), lattice_.n0);
  } else if (needs_rate) {
    ps = smoothed_pressure_and_strain_rate(nb, i, pressure, p.vx.data(), p.vy.data(), lattice_.n0);
  } else {
    ps.smoothed_pressure = smoothed_pressure(nb, i, pressure);
  }
  return ps;
}

// The base of eq. 24's differences: the smallest pressure among particle i and its neighbours that carry pressure
// (pressure_gradient_minimum), else p_i [Pa].
double Step::gradient_base(std::size_t i, const double* p) const {
  double base = p[i];
  if (!model_.settings.pressure_gradient_minimum) return base;
  const double* dummy = model_.particles.field(model_.dummy).data();
  for_each_weighted_neighbour(neighbourhood(), i, [&](std::size_t j, double, double, double, double) {
    if (dummy[j] == 0.0) base = std::min(base, p[j]);
  });
  return base;
}

// [M4] eq. 24 over the particles that carry pressure (moving and wall particles; dummy particles are left out).
Vector2 Step::pressure_gradient(std::size_t i, const double* p) const {
  const double* dummy = model_.particles.field(model_.dummy).data();
  const double base = gradient_base(i, p);
  Vector2 g;
  for_each_weighted_neighbour(neighbourhood(), i, [&](std::size_t j, double dx, double dy, double r2, double w) {
    if (dummy[j] == 0.0) add_gradient_share(g, p[j] - base, dx, dy, r2, w);
  });
  const double c = terms::gradient_prefactor(lattice_.n0);
  return {c * g.x, c * g.y};
}

// The predictor's viscous force, direct (eq. 22, viscous_force) or full (full_viscous_force), and pressure gradient
// (eq. 24, pressure_gradient) of particle i gathered in one pass over its neighbours after the base's: the same sums
// in the same order as the two functions, so the same values bit for bit.
template <bool Full>
Step::Forces Step::viscous_and_pressure_forces(std::size_t i, const double* p) const {
  const ParticleSet& set = model_.particles;
  const double* dummy = set.field(model_.dummy).data();
  const double* mu = set.field(model_.fields.viscosity).data();
  const double* u = set.vx.data();
  const double* v = set.vy.data();
  const InteractionViscosity interaction = model_.settings.interaction_viscosity;
  const double base = gradient_base(i, p);
  Vector2 f, g;
  for_each_weighted_neighbour(neighbourhood(), i, [&](std::size_t j, double dx, double dy, double r2, double w) {
    if constexpr (Full)
      add_full_viscous_share(f, i, j, -dx, -dy, r2, w, u, v, mu, interaction);  // x_ij = -(x_i - x_j)
    else
      add_viscous_share(f, i, j, w, u, v, mu, interaction);
    if (dummy[j] == 0.0) add_gradient_share(g, p[j] - base, dx, dy, r2, w);
  });
  const double cv = viscous_prefactor(lattice_), cg = terms::gradient_prefactor(lattice_.n0);
  return {{cv * f.x, cv * f.y}, {cg * g.x, cg * g.y}};
}

// Steps d and e: u* (eq. 28) and r* = r^m + u* dt for the moving particles; r^m kept for step h.
void Step::predict(double dt) {
  ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const Settings& st = model_.settings;
  const Neighbourhood nb = neighbourhood();
  const double alpha = st.pressure_split, gx = gravity_x(), gy = gravity_y();
  double* xs = p.field(impl_->x_start).data();
  double* ys = p.field(impl_->y_start).data();
  impl_->fx.assign(p.size(), 0.0);
  impl_->fy.assign(p.size(), 0.0);
  const auto n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] != kMoving) continue;
    Forces f;
    switch (st.stress_divergence) {
      case StressDivergence::direct: f = viscous_and_pressure_forces<false>(i, a.pressure); break;
      case StressDivergence::indirect:
        f = {stress_divergence(nb, i, impl_->sxx.data(), impl_->syy.data(), impl_->sxy.data(), lattice_.n0),
             pressure_gradient(i, a.pressure)};
        break;
      case StressDivergence::full: f = viscous_and_pressure_forces<true>(i, a.pressure); break;
    }
    const Vector2& v = f.viscous;
    const Vector2& g = f.pressure_gradient;
    const double rho = impl_->density[material_of(i)];  // rho_i, the phase's density (eqs. 25-26)
    impl_->fx[i] = terms::predicted_velocity(p.vx[i], dt, rho, rho * gx, v.x, g.x, alpha);
    impl_->fy[i] = terms::predicted_velocity(p.vy[i], dt, rho, rho * gy, v.y, g.y, alpha);
  }
  const double* gate = p.field(model_.gate).data();
  const double rise = gate_rise(dt);
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    xs[i] = p.x[i];
    ys[i] = p.y[i];
    if (gate[i] != 0.0) {  // the gate is at its new height at r* and stays there
      p.vy[i] = rise / dt;
      p.y[i] += rise;
    }
    if (p.kind[i] != kMoving) continue;
    p.vx[i] = impl_->fx[i];
    p.vy[i] = impl_->fy[i];
    p.x[i] += p.vx[i] * dt;
    p.y[i] += p.vy[i] * dt;
  }
}

// Step f at r*: p^{m+1} from n* (summed by list_neighbours at r*) by Tait's EOS with the free-surface rule (moving
// and wall particles), clipped at 0, 0 for dummy particles; the density rho0 n*/n0 for the frames.
void Step::equation_of_state() {
  ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const Settings& st = model_.settings;
  const double* dummy = p.field(model_.dummy).data();
  const double n0 = lattice_.n0;
  mixture_densities();
  const auto count = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < count; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double n = a.number_density[i];
    const bool surface = terms::is_free_surface(n, n0, st.surface_beta);
    a.free_surface[i] = surface ? 1.0 : 0.0;
    // negative EOS pressure is clipped to 0 (the code lineage's choice; docs/mps.md decision S2)
    const double rho = a.mixture_density[i];
    const double eos = terms::pressure(n, n0, rho, st.sound_speed, st.tait_gamma, st.surface_beta);
    a.pressure[i] = dummy[i] != 0.0 ? 0.0 : std::max(eos, 0.0);
    p.rho[i] = terms::density_from_number_density(rho, n, n0);
  }
}

// Seed 2.10 at r*: the mixture density <rho>_i = sum rho_j w_ij / sum w_ij and the volume fraction
// phi_i = sum phi0_j w_ij / sum w_ij over the moving particles j, a moving i itself with w = 1; a wall particle with
// no moving neighbour keeps its material's values. With one density (the single-phase model) <rho>_i is the
// material's density exactly and phi_i its phi0.
void Step::mixture_densities() {
  const ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const Neighbourhood nb = neighbourhood();
  const Impl& im = *impl_;
  const auto n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const std::size_t m = material_of(i);
    a.mixture_density[i] = im.density[m];
    a.volume_fraction[i] = im.grain_fraction[m];
    if (!im.mixture) continue;
    const bool moving = p.kind[i] == kMoving;
    double sum_w = moving ? 1.0 : 0.0;
    double rho = moving ? im.density[m] : 0.0, phi = moving ? im.grain_fraction[m] : 0.0;
    for_each_weighted_neighbour(nb, i, [&](std::size_t j, double, double, double, double w) {
      if (p.kind[j] != kMoving) return;
      const std::size_t mj = material_of(j);
      sum_w += w;
      rho += im.density[mj] * w;
      phi += im.grain_fraction[mj] * w;
    });
    if (sum_w == 0.0) continue;
    a.mixture_density[i] = rho / sum_w;
    a.volume_fraction[i] = phi / sum_w;
  }
}

// Steps g and h: u^{m+1} = u* + u' (eqs. 27, 29) with the gradient of p^{m+1} at r*, r^{m+1} = r^m + u^{m+1} dt.
void Step::correct(double dt) {
  ParticleSet& p = model_.particles;
  const Arrays a = model_.arrays();
  const Settings& st = model_.settings;
  const double* xs = p.field(impl_->x_start).data();
  const double* ys = p.field(impl_->y_start).data();
  const double* gate = p.field(model_.gate).data();
  impl_->fx.assign(p.size(), 0.0);
  impl_->fy.assign(p.size(), 0.0);
  const auto n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] != kMoving) continue;
    const Vector2 g = pressure_gradient(i, a.pressure);
    const double rho = impl_->density[material_of(i)];
    impl_->fx[i] = terms::velocity_correction(dt, rho, g.x, st.pressure_split);
    impl_->fy[i] = terms::velocity_correction(dt, rho, g.y, st.pressure_split);
  }
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] != kMoving) {  // walls back to r^m; the gate at its new height (predict)
      p.x[i] = xs[i];
      if (gate[i] == 0.0) p.y[i] = ys[i];
      continue;
    }
    p.vx[i] += impl_->fx[i];
    p.vy[i] += impl_->fy[i];
    p.x[i] = terms::new_position(xs[i], p.vx[i], dt);
    p.y[i] = terms::new_position(ys[i], p.vy[i], dt);
  }
}

// Step i: each moving particle against the fixed wall and dummy particles within d_c = wall_collision_distance dx
// that it approaches (v . e < 0, e the unit vector from the wall particle to it): v -= (1 + e_r)(v . e) e, one
// contact after the other, and the position moves by the velocity change times dt. The cells of the sort at r* still
// hold every pair closer than d_c < r_e after the corrector's small move.
void Step::collide_with_walls(double dt) {
  const Settings& st = model_.settings;
  if (st.wall_collision_distance <= 0) return;
  ParticleSet& p = model_.particles;
  const Neighbourhood nb = neighbourhood();
  const double dc = st.wall_collision_distance * st.particle_spacing;
  const double kick = 1.0 + st.wall_collision_restitution;
  const auto n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {  // a particle writes only its own state and reads the fixed walls'
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] != kMoving || !impl_->near_fixed[i]) continue;
    double vx = p.vx[i], vy = p.vy[i];
    for_each_within(nb, i, dc, [&](std::size_t j, double dx, double dy, double r2) {
      if (p.kind[j] == kMoving || r2 == 0.0) return;  // for_each_within passes r2 < d_c^2 only
      const double r = std::sqrt(r2);
      const double ex = dx / r, ey = dy / r;  // from j to i (dx = x_i - x_j)
      const double vn = (vx - p.vx[j]) * ex + (vy - p.vy[j]) * ey;  // relative to the wall particle (the gate moves)
      if (vn >= 0.0) return;
      vx -= kick * vn * ex;
      vy -= kick * vn * ey;
    });
    p.x[i] += (vx - p.vx[i]) * dt;
    p.y[i] += (vy - p.vy[i]) * dt;
    p.vx[i] = vx;
    p.vy[i] = vy;
  }
}

void Step::advance(double dt) {
  list_neighbours();
  viscosities();
  predict(dt);
  list_neighbours(true);  // n* summed with the weights at r*
  equation_of_state();
  correct(dt);
  collide_with_walls(dt);
  model_.state.time += dt;
  model_.state.step += 1;
}

// How far the gate rises over the next dt [m].
double Step::gate_rise(double dt) const {
  const Settings& st = model_.settings;
  return st.gate_rise(model_.state.time + dt) - st.gate_rise(model_.state.time);
}

double Step::stable_time_step() const {
  const ParticleSet& p = model_.particles;
  const Settings& st = model_.settings;
  const double* mu = p.field(model_.fields.viscosity).data();
  double u2 = 0, mu_max = 0;  // mu_max: the largest mu_i rho0 / rho_i, the kinematic viscosity times rho0
  const double rho0 = st.rest_density;
  const Impl& im = *impl_;
  const auto n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static) reduction(max : u2, mu_max)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (p.kind[i] != kMoving) continue;
    u2 = std::max(u2, p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
    const double rho = im.density[material_of(i)];
    mu_max = std::max(mu_max, rho == rho0 ? mu[i] : mu[i] * (rho0 / rho));
  }
  if (st.gate_rise(model_.state.time) < st.gate_lift_distance)  // the gate still rises
    u2 = std::max(u2, st.gate_lift_speed * st.gate_lift_speed);
  return terms::time_step(st.cfl, st.particle_spacing, st.sound_speed, std::sqrt(u2), rho0, mu_max);
}

std::vector<DerivedField> Step::derived_outputs() const {
  const ParticleSet& p = model_.particles;
  const double* mu = p.field(model_.fields.viscosity).data();
  DerivedField log_mu{"log10_viscosity", std::vector<double>(p.size())};
  for (std::size_t i = 0; i < p.size(); ++i) log_mu.values[i] = std::log10(mu[i]);
  return {log_mu};
}

Energies Step::energies() const { return moving_energies(model_.particles, model_.settings); }

Health Step::check_health() const {
  const ParticleSet& p = model_.particles;
  const auto& f = model_.fields;
  const double* pr = p.field(f.pressure).data();
  const double* n = p.field(f.number_density).data();
  const double* mu = p.field(f.viscosity).data();
  Health h;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const char* bad = nullptr;
    if (!std::isfinite(p.x[i]) || !std::isfinite(p.y[i])) bad = "position";
    else if (!std::isfinite(p.vx[i]) || !std::isfinite(p.vy[i])) bad = "velocity";
    else if (!std::isfinite(pr[i])) bad = "pressure";
    else if (!std::isfinite(n[i])) bad = "number_density";
    else if (!std::isfinite(mu[i])) bad = "viscosity";
    if (!bad) continue;
    std::ostringstream os;
    os << "particle " << p.id[i] << ": field " << bad << " is not finite at step " << model_.state.step;
    h.ok = false;
    h.diagnostic = os.str();
    return h;
  }
  return h;
}

}  // namespace sph::mps
