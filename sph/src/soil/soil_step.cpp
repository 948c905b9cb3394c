#include "sph/soil/soil_step.hpp"

#include "step_impl.hpp"
#include "terms.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace sph::soil {

namespace {
constexpr std::size_t kBlock = 1024;  // fixed block size: reductions are independent of the thread count

using Index = std::int64_t;
using namespace detail;

template <class F>
void block_sums(const std::vector<std::uint32_t>& idx, std::vector<double>& a, std::vector<double>& b,
                std::vector<double>& c, F&& f, double& sa, double& sb, double& sc) {
  const std::size_t n = idx.size();
  const std::size_t nb = (n + kBlock - 1) / kBlock;
  a.assign(nb, 0.0);
  b.assign(nb, 0.0);
  c.assign(nb, 0.0);
#pragma omp parallel for schedule(static)
  for (Index bb = 0; bb < static_cast<Index>(nb); ++bb) {
    const std::size_t lo = static_cast<std::size_t>(bb) * kBlock, hi = std::min(n, lo + kBlock);
    double xa = 0, xb = 0, xc = 0;
    for (std::size_t k = lo; k < hi; ++k) f(idx[k], xa, xb, xc);
    a[static_cast<std::size_t>(bb)] = xa;
    b[static_cast<std::size_t>(bb)] = xb;
    c[static_cast<std::size_t>(bb)] = xc;
  }
  sa = sb = sc = 0;
  for (std::size_t k = 0; k < nb; ++k) {
    sa += a[k];
    sb += b[k];
    sc += c[k];
  }
}


}  // namespace

SoilStep::SoilStep(Model& model) : model_(model), impl_(std::make_unique<Impl>()) {
  model_.validate();
  const Settings& st = model_.settings;
  if (st.gravity_mode == GravityMode::geostatic_k0 && (st.gravity_x != 0.0 || !(st.gravity_y < 0.0)))
    throw std::invalid_argument("settings.gravity_mode geostatic_k0 needs gravity along -y (gravity_x = 0, gravity_y < 0)");
  h_ = st.smoothing_length();
  for (const auto& m : model_.materials) mc_.push_back(MaterialConstants::from(m));
  c_max_ = 0;
  for (const auto& c : mc_) c_max_ = std::max(c_max_, c.sound_speed);
  artificial_stress_ = model_.uses_artificial_stress();
  auto& w = *impl_;
  const std::size_t n = model_.particles.size();
  register_workspace(model_.particles, &w);
  if (st.wall_slip == WallSlip::frictional) w.wall_push = register_wall_friction_state(model_.particles);
  for (auto* a : {&w.pxx, &w.pyy, &w.pxy, &w.volume, &w.sound, &w.is_soil, &w.rxx, &w.ryy, &w.rxy, &w.xsph_dx,
                  &w.xsph_dy})
    a->assign(n, 0.0);
  if (st.kernel_gradient == KernelGradient::corrected)
    for (auto* a : {&w.bxx, &w.bxy, &w.byy}) a->assign(n, 0.0);
  if (st.stress_substeps > 1)
    for (auto* a : {&w.lxx, &w.lyy, &w.lexy, &w.lwxy}) a->assign(n, 0.0);
  w.sorted.reserve(model_.particles);
  index_kinds(model_.particles, w);  // valid for the current order; sorts keep them up to date
  w.soil.reserve(n);
  w.walls.reserve(n);
  const double dx = st.particle_spacing;
  w.eval = select_evaluators(st.kernel);
  w.w_dx = st.kernel == KernelType::cubic_spline ? CubicSplineKernel(h_).value(dx) : WendlandC2Kernel(h_).value(dx);
  if (!(w.w_dx > 0)) throw std::invalid_argument("settings.h_over_dx too small: W(dx) = 0");
}

SoilStep::~SoilStep() = default;

void SoilStep::register_workspace(ParticleSet& particles, Impl* impl) {
  // Half-step values live only within a step (written before the step's sort, read after it): reordered with the
  // particles, never checkpointed or written to frames.
  auto workspace = [&](const char* name) { return particles.add_field({name, false, false}); };
  const FieldId vxh = workspace("half_step_vx"), vyh = workspace("half_step_vy"),
                rhoh = workspace("half_step_density"), sxxh = workspace("half_step_stress_xx"),
                syyh = workspace("half_step_stress_yy"), szzh = workspace("half_step_stress_zz"),
                sxyh = workspace("half_step_stress_xy"), sxx0 = workspace("step_start_stress_xx"),
                syy0 = workspace("step_start_stress_yy"), szz0 = workspace("step_start_stress_zz"),
                sxy0 = workspace("step_start_stress_xy");
  if (impl) {
    impl->vxh = vxh;
    impl->vyh = vyh;
    impl->rhoh = rhoh;
    impl->sxxh = sxxh;
    impl->syyh = syyh;
    impl->szzh = szzh;
    impl->sxyh = sxyh;
    impl->sxx0 = sxx0;
    impl->syy0 = syy0;
    impl->szz0 = szz0;
    impl->sxy0 = sxy0;
  }
}

void SoilStep::apply_geostatic_stress() {
  ParticleSet& p = model_.particles;
  const SoilArrays sa = model_.soil();
  const double g = -model_.settings.gravity_y;
  const double dx = model_.settings.particle_spacing;
  std::vector<std::uint32_t> soil;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::material)) soil.push_back(static_cast<std::uint32_t>(i));
  if (soil.empty()) return;
  double xmin = p.x[soil[0]];
  for (auto i : soil) xmin = std::min(xmin, p.x[i]);
  auto column = [&](std::uint32_t i) { return static_cast<long long>(std::floor((p.x[i] - xmin) / dx + 0.5)); };
  // sort by (column, y descending, id) so that the walk is deterministic
  std::sort(soil.begin(), soil.end(), [&](std::uint32_t a, std::uint32_t b) {
    const auto ca = column(a), cb = column(b);
    if (ca != cb) return ca < cb;
    if (p.y[a] != p.y[b]) return p.y[a] > p.y[b];
    return p.id[a] < p.id[b];
  });
  // Effective vertical stress: the weight above (and a surface force on the column's top), less the rise of the
  // pore pressure from the column's top (docs/sph.md, "Loads"): sigma'_yy = -(sum rho g dx) + u(y) - u(top).
  const PiezometricLine* water = model_.loads.water ? &*model_.loads.water : nullptr;
  const double* surface_fy =
      model_.loads.surface_force_y ? p.field(*model_.loads.surface_force_y).data() : nullptr;
  long long current = std::numeric_limits<long long>::min();
  double above = 0;  // sum rho dx g of the particles above in this column (and surface forces), per metre width
  double top_u = 0;  // pore pressure at the column's top
  for (auto i : soil) {
    const long long c = column(i);
    if (c != current) {
      current = c;
      above = 0;
      top_u = water ? water->pressure(p.x[i], p.y[i] + 0.5 * dx) : 0.0;
    }
    if (surface_fy) above -= surface_fy[i] / dx;
    const double rho_g_dx = p.rho[i] * g * dx;
    double syy = -(above + 0.5 * rho_g_dx);
    if (water) syy += water->pressure(p.x[i], p.y[i]) - top_u;
    above += rho_g_dx;
    const double k0 = mc_[p.material[i]].k0;
    sa.syy[i] = syy;
    sa.sxx[i] = k0 * syy;
    sa.szz[i] = k0 * syy;
    sa.sxy[i] = 0.0;
    Stress s{sa.sxx[i], sa.syy[i], sa.szz[i], sa.sxy[i]};
    return_to_yield_surface(mc_[p.material[i]], s);  // a K0 state may violate the yield criterion near faces
    sa.sxx[i] = s.xx; sa.syy[i] = s.yy; sa.szz[i] = s.zz; sa.sxy[i] = s.xy;
  }
}

void SoilStep::evaluate() { evaluate_at(model_.state.time); }

void SoilStep::evaluate_at(double time) {
  // Gravity is set once per evaluation (not tested per particle): full, or its ramped fraction at `time`.
  impl_->set_gravity(model_.settings, time);
  impl_->eval.all(*this, model_, *impl_);
}

void SoilStep::initialise() {
  RunState& rs = model_.state;
  if (model_.settings.gravity_mode == GravityMode::geostatic_k0 && !rs.initial_stress_applied && rs.step == 0) {
    apply_geostatic_stress();
    rs.initial_stress_applied = true;
    rs.rates_valid = false;
  }
  if (!rs.rates_valid) {
    evaluate();
    rs.rates_valid = true;
  } else {
    // resumed state: keep the stored order (the next step sorts exactly as the uninterrupted run did)
    index_kinds(model_.particles, *impl_);
  }
}

double SoilStep::stable_time_step() const {
  const ParticleSet& p = model_.particles;
  const SoilArrays sa = model_.soil();
  const auto& soil = impl_->soil;
  const Index ns = static_cast<Index>(soil.size());
  double a2max = 0, v2max = 0;
#pragma omp parallel for schedule(static) reduction(max : a2max, v2max)
  for (Index k = 0; k < ns; ++k) {
    const std::size_t i = soil[static_cast<std::size_t>(k)];
    a2max = std::max(a2max, sa.ax[i] * sa.ax[i] + sa.ay[i] * sa.ay[i]);
    v2max = std::max(v2max, p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
  }
  const Settings& st = model_.settings;
  const double vmax = std::sqrt(v2max);
  const double dt_c = terms::courant_time_step(st.cfl, h_, c_max_, st.viscosity.alpha, st.viscosity.beta, vmax);
  const double amax = std::sqrt(a2max);
  const double dt_a = amax > 0 ? st.acceleration_safety * std::sqrt(h_ / amax) : std::numeric_limits<double>::infinity();
  return std::min(dt_c, dt_a);
}

void SoilStep::advance(double dt) {
  if (model_.settings.integration == TimeIntegration::verlet)
    advance_verlet(dt);
  else
    advance_predictor_corrector(dt);
}

// Kick-drift-kick: v_h = v + dt/2 a; x += dt v_h; rates of density and stress at (x, v_h); rho += dt drho,
// sigma = R(sigma + dt dsigma); forces at the new state; v = v_h + dt/2 a. Symplectic for the elastic waves: stable
// without dissipation up to omega dt = 2 (docs/sph.md), where the predictor-corrector needs the artificial viscosity.
void SoilStep::advance_verlet(double dt) {
  ParticleSet& p = model_.particles;
  auto& w = *impl_;
  const double half = 0.5 * dt;
  w.step_dt = dt;
  {
    const SoilArrays sa = model_.soil();
    const Index ns = static_cast<Index>(w.soil.size());
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < ns; ++k) {
      const std::size_t i = w.soil[static_cast<std::size_t>(k)];
      p.vx[i] += half * sa.ax[i];
      p.vy[i] += half * sa.ay[i];
      p.x[i] += dt * p.vx[i];
      p.y[i] += dt * p.vy[i];
    }
  }
  w.eval.kinematics(*this, model_, w);  // sorts; density and stress rates at the half-step velocity
  {
    const SoilArrays sa = model_.soil();  // the sort may have swapped the arrays' buffers
    const int substeps = model_.settings.stress_substeps;
    const Index ns = static_cast<Index>(w.soil.size());
#pragma omp parallel for schedule(dynamic, 64)  // the yielding particles take sub-steps: uneven work
    for (Index k = 0; k < ns; ++k) {
      const std::size_t i = w.soil[static_cast<std::size_t>(k)];
      p.rho[i] += dt * sa.drho[i];
      // With sub-steps, a particle that yields in the step (plastic flow at its start, or a trial stress the return
      // corrects) takes them; one that stays elastic keeps the one update below.
      if (substeps > 1 && sa.dplastic_strain[i] > 0.0) {
        update_stress_in_substeps(sa, i, dt, substeps);
        continue;
      }
      const Stress start{sa.sxx[i], sa.syy[i], sa.szz[i], sa.sxy[i]};
      Stress s{sa.sxx[i] + dt * sa.dsxx[i], sa.syy[i] + dt * sa.dsyy[i], sa.szz[i] + dt * sa.dszz[i],
               sa.sxy[i] + dt * sa.dsxy[i]};
      const ReturnResult rr = return_to_yield_surface(mc_[p.material[i]], s, &start);
      if (substeps > 1 && (rr.scaled || rr.tension_cracked)) {
        update_stress_in_substeps(sa, i, dt, substeps);
        continue;
      }
      sa.sxx[i] = s.xx; sa.syy[i] = s.yy; sa.szz[i] = s.zz; sa.sxy[i] = s.xy;
      sa.plastic_strain[i] += dt * sa.dplastic_strain[i] + rr.plastic_strain;
      sa.plastic_work[i] += dt * sa.dplastic_work[i] + rr.plastic_work / p.rho[i];
    }
  }
  const Settings& st = model_.settings;
  w.set_gravity(st, model_.state.time + dt);
  w.eval.forces(*this, model_, w);  // walls from the new stress; accelerations at the step's end
  {
    const SoilArrays sa = model_.soil();
    const bool xsph = st.xsph.enabled;
    const Index ns = static_cast<Index>(w.soil.size());
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < ns; ++k) {
      const std::size_t i = w.soil[static_cast<std::size_t>(k)];
      p.vx[i] += half * sa.ax[i];
      p.vy[i] += half * sa.ay[i];
      if (xsph) {
        p.x[i] += dt * w.xsph_dx[i];
        p.y[i] += dt * w.xsph_dy[i];
      }
    }
  }
  model_.state.time += dt;
  model_.state.step += 1;
}

// The stress update of particle i over dt in sub-steps: each takes the stress rate of its own start stress with
// the step's velocity gradient, then the return; the first sub-step's rate is the one the kinematic pass stored.
// Plastic strain and work add up over the sub-steps. Only a particle that yields in the step comes here (the Verlet
// step keeps the one update of an elastic particle, which sub-steps would change only by the Jaumann rotation's
// second-order term); it takes as many as stress_substep_count asks for its strain increment. In SPHinXsys's
// granular collapse at cfl 0.8, 48 % of the particle-steps of the first 0.3 s came here, with 12.3 sub-steps on
// average (docs/sph.md, "Time step"): this loop took 26-41 % of the run on one thread (perf).
void SoilStep::update_stress_in_substeps(const SoilArrays& sa, std::size_t i, double dt, int n_max) const {
  const ParticleSet& p = model_.particles;
  const auto& w = *impl_;
  // Local copies: the loop's values stay in registers (no write through the arrays can alias them); the operations
  // and their order are those of one update per sub-step written to the arrays.
  const MaterialConstants mc = mc_[p.material[i]];
  const double exx = w.lxx[i], eyy = w.lyy[i], exy = w.lexy[i], wxy = w.lwxy[i], rho = p.rho[i];
  const Stress s0{sa.sxx[i], sa.syy[i], sa.szz[i], sa.sxy[i]};
  const int n = stress_substep_count(mc, s0, exx, eyy, exy, dt, n_max);
  const double h = dt / n;
  double plastic_strain = sa.plastic_strain[i], plastic_work = sa.plastic_work[i];
  Stress s = s0;
  for (int q = 0; q < n; ++q) {
    const Stress start = s;
    StressRate sr;
    if (q == 0) {  // the kinematic pass's rate at the step's start stress
      sr.rate = {sa.dsxx[i], sa.dsyy[i], sa.dszz[i], sa.dsxy[i]};
      sr.plastic_strain_rate = sa.dplastic_strain[i];
      sr.plastic_work_rate = sa.dplastic_work[i] * rho;
    } else {
      sr = stress_rate(mc, s, exx, eyy, exy, wxy);
    }
    s.xx += h * sr.rate.xx;
    s.yy += h * sr.rate.yy;
    s.zz += h * sr.rate.zz;
    s.xy += h * sr.rate.xy;
    const ReturnResult rr = return_to_yield_surface(mc, s, &start);
    plastic_strain += h * sr.plastic_strain_rate + rr.plastic_strain;
    plastic_work += (h * sr.plastic_work_rate + rr.plastic_work) / rho;
  }
  sa.plastic_strain[i] = plastic_strain;
  sa.plastic_work[i] = plastic_work;
  sa.sxx[i] = s.xx;
  sa.syy[i] = s.yy;
  sa.szz[i] = s.zz;
  sa.sxy[i] = s.xy;
}

void SoilStep::advance_predictor_corrector(double dt) {
  ParticleSet& p = model_.particles;
  auto& w = *impl_;
  const double half = 0.5 * dt;
  w.step_dt = dt;
  {
    const SoilArrays sa = model_.soil();
    const HalfStep hs(p, w);
    const Index ns = static_cast<Index>(w.soil.size());
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < ns; ++k) {
      const std::size_t i = w.soil[static_cast<std::size_t>(k)];
      const double vxh = p.vx[i] + half * sa.ax[i];
      const double vyh = p.vy[i] + half * sa.ay[i];
      hs.vxh[i] = vxh;
      hs.vyh[i] = vyh;
      p.x[i] += dt * vxh;
      p.y[i] += dt * vyh;
      p.vx[i] += dt * sa.ax[i];
      p.vy[i] += dt * sa.ay[i];
      hs.rhoh[i] = p.rho[i] + half * sa.drho[i];
      p.rho[i] += dt * sa.drho[i];
      hs.sxx0[i] = sa.sxx[i];
      hs.syy0[i] = sa.syy[i];
      hs.szz0[i] = sa.szz[i];
      hs.sxy0[i] = sa.sxy[i];
      hs.sxxh[i] = sa.sxx[i] + half * sa.dsxx[i];
      hs.syyh[i] = sa.syy[i] + half * sa.dsyy[i];
      hs.szzh[i] = sa.szz[i] + half * sa.dszz[i];
      hs.sxyh[i] = sa.sxy[i] + half * sa.dsxy[i];
      Stress s{sa.sxx[i] + dt * sa.dsxx[i], sa.syy[i] + dt * sa.dsyy[i], sa.szz[i] + dt * sa.dszz[i],
               sa.sxy[i] + dt * sa.dsxy[i]};
      return_to_yield_surface(mc_[p.material[i]], s);
      sa.sxx[i] = s.xx; sa.syy[i] = s.yy; sa.szz[i] = s.zz; sa.sxy[i] = s.xy;
      sa.plastic_strain[i] += half * sa.dplastic_strain[i];
      sa.plastic_work[i] += half * sa.dplastic_work[i];
    }
  }
  // sorts (index lists change), extrapolates walls, computes rates at the predicted state, at the step's end time
  evaluate_at(model_.state.time + dt);
  {
    const SoilArrays sa = model_.soil();  // the sort may have swapped the arrays' buffers
    const HalfStep hs(p, w);
    const bool xsph = model_.settings.xsph.enabled;
    const Index ns = static_cast<Index>(w.soil.size());
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < ns; ++k) {
      const std::size_t i = w.soil[static_cast<std::size_t>(k)];
      p.vx[i] = hs.vxh[i] + half * sa.ax[i];
      p.vy[i] = hs.vyh[i] + half * sa.ay[i];
      p.rho[i] = hs.rhoh[i] + half * sa.drho[i];
      const Stress start{hs.sxx0[i], hs.syy0[i], hs.szz0[i], hs.sxy0[i]};
      Stress s{hs.sxxh[i] + half * sa.dsxx[i], hs.syyh[i] + half * sa.dsyy[i], hs.szzh[i] + half * sa.dszz[i],
               hs.sxyh[i] + half * sa.dsxy[i]};
      const ReturnResult rr = return_to_yield_surface(mc_[p.material[i]], s, &start);
      sa.sxx[i] = s.xx; sa.syy[i] = s.yy; sa.szz[i] = s.zz; sa.sxy[i] = s.xy;
      sa.plastic_strain[i] += half * sa.dplastic_strain[i] + rr.plastic_strain;
      sa.plastic_work[i] += half * sa.dplastic_work[i] + rr.plastic_work / p.rho[i];
      if (xsph) {
        p.x[i] += dt * w.xsph_dx[i];
        p.y[i] += dt * w.xsph_dy[i];
      }
    }
  }
  model_.state.time += dt;
  model_.state.step += 1;
}

std::vector<DerivedField> SoilStep::derived_outputs() const {
  const SoilArrays sa = model_.soil();
  DerivedField pressure{"pressure", std::vector<double>(model_.particles.size())};
  for (std::size_t i = 0; i < model_.particles.size(); ++i) pressure.values[i] = -(sa.sxx[i] + sa.syy[i] + sa.szz[i]) / 3.0;
  if (!model_.loads.water) return {pressure};
  // With pore water the stress is effective: "pressure" is the mean effective pressure; the pore pressure beside it.
  const ParticleSet& p = model_.particles;
  DerivedField pore{"pore_pressure", std::vector<double>(p.size())};
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::material))
      pore.values[i] = model_.loads.water->pressure(p.x[i], p.y[i]);
  return {pressure, pore};
}

Energies SoilStep::energies() const {
  const ParticleSet& p = model_.particles;
  const SoilArrays sa = model_.soil();
  auto& w = *impl_;
  const double gx = model_.settings.gravity_x, gy = model_.settings.gravity_y;
  // The loads' potentials (sph/soil/loads.hpp): volume times pore pressure, -m kh |g| x, -m kv |g| y, -f.x of a
  // surface force.
  const SoilLoads& loads = model_.loads;
  const PiezometricLine* water = loads.water ? &*loads.water : nullptr;
  const double seismic_ax = loads.seismic_coefficient * std::hypot(gx, gy);
  const double seismic_ay = loads.vertical_seismic_coefficient * std::hypot(gx, gy);
  const double* fx = loads.surface_force_x ? p.field(*loads.surface_force_x).data() : nullptr;
  const double* fy = loads.surface_force_y ? p.field(*loads.surface_force_y).data() : nullptr;
  Energies e;
  block_sums(
      w.soil, w.block_a, w.block_b, w.block_c,
      [&](std::size_t i, double& ke, double& pe, double& pw) {
        ke += 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
        pe -= p.mass[i] * (gx * p.x[i] + gy * p.y[i]);
        pw += p.mass[i] * sa.plastic_work[i];
        if (water) pe += p.mass[i] / p.rho[i] * water->pressure(p.x[i], p.y[i]);
        if (seismic_ax != 0.0) pe -= p.mass[i] * seismic_ax * p.x[i];
        if (seismic_ay != 0.0) pe -= p.mass[i] * seismic_ay * p.y[i];
        if (fx) pe -= fx[i] * p.x[i] + fy[i] * p.y[i];
      },
      e.kinetic, e.potential, e.plastic_dissipation);
  double v2 = 0;
  const Index ns = static_cast<Index>(w.soil.size());
#pragma omp parallel for schedule(static) reduction(max : v2)
  for (Index k = 0; k < ns; ++k) {
    const std::size_t i = w.soil[static_cast<std::size_t>(k)];
    v2 = std::max(v2, p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
  }
  e.max_speed = std::sqrt(v2);
  return e;
}

Health SoilStep::check_health() const {
  const ParticleSet& p = model_.particles;
  const SoilArrays sa = model_.soil();
  const auto& soil = impl_->soil;
  const Index ns = static_cast<Index>(soil.size());
  const double vlimit = model_.settings.blow_up_speed_factor * c_max_;
  const double v2lim = vlimit * vlimit;
  Index first_bad = std::numeric_limits<Index>::max();
#pragma omp parallel for schedule(static) reduction(min : first_bad)
  for (Index k = 0; k < ns; ++k) {
    const std::size_t i = soil[static_cast<std::size_t>(k)];
    const double sum = p.x[i] + p.y[i] + p.vx[i] + p.vy[i] + p.rho[i] + sa.sxx[i] + sa.syy[i] + sa.szz[i] + sa.sxy[i] +
                       sa.plastic_strain[i];
    const double v2 = p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i];
    if (!std::isfinite(sum) || !(v2 <= v2lim) || !(p.rho[i] > 0)) first_bad = std::min(first_bad, k);
  }
  Health h;
  if (first_bad == std::numeric_limits<Index>::max()) return h;
  h.ok = false;
  const std::size_t i = soil[static_cast<std::size_t>(first_bad)];
  std::ostringstream os;
  os.precision(6);
  os << "blow-up at step " << model_.state.step << " (t = " << model_.state.time << " s): particle " << p.id[i]
     << " (at x = " << p.x[i] << ", y = " << p.y[i] << ") ";
  struct Field { const char* name; double v; };
  const Field fields[] = {{"x", p.x[i]}, {"y", p.y[i]}, {"vx", p.vx[i]}, {"vy", p.vy[i]}, {"density", p.rho[i]},
                          {"stress_xx", sa.sxx[i]}, {"stress_yy", sa.syy[i]}, {"stress_zz", sa.szz[i]},
                          {"stress_xy", sa.sxy[i]}, {"plastic_strain", sa.plastic_strain[i]}};
  bool named = false;
  for (const auto& f : fields)
    if (!std::isfinite(f.v)) {
      os << "has non-finite " << f.name;
      named = true;
      break;
    }
  if (!named) {
    if (!(p.rho[i] > 0))
      os << "has non-positive density " << p.rho[i];
    else
      os << "has speed " << std::sqrt(p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]) << " m/s in field velocity, above "
         << vlimit << " m/s (blow_up_speed_factor x sound speed): the explicit scheme is not valid for soil moving "
            "faster than its P-wave speed (a very soft material, or a diverging run: raise the Young's modulus or "
            "lower the time-step factor)";
  }
  h.diagnostic = os.str();
  return h;
}

}  // namespace sph::soil
