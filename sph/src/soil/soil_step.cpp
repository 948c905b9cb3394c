#include "sph/soil/soil_step.hpp"

#include "sph/engine/cell_sort.hpp"
#include "terms.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace sph {

namespace {
using namespace soil_terms;
constexpr std::size_t kBlock = 1024;  // fixed block size: reductions are independent of the thread count

using Index = std::int64_t;
}  // namespace

struct SoilStep::Impl {
  CellSortedSet sorted;  // the particles sorted by cell, and the cell list
  // index lists (sorted positions), rebuilt after every sort
  std::vector<std::uint32_t> soil, walls;
  // half-step values: registered in the particle set (not checkpointed), so the sort reorders them
  FieldId vxh, vyh, rhoh, sxxh, syyh, szzh, sxyh;
  // per-evaluation scratch (recomputed after every sort)
  std::vector<double> pxx, pyy, pxy, volume, sound, is_soil;  // sigma/rho^2, m/rho, c, 0/1
  std::vector<double> rxx, ryy, rxy;                           // artificial stress R/rho^2 terms
  std::vector<double> xsph_dx, xsph_dy;                        // XSPH velocity corrections
  std::vector<double> block_a, block_b, block_c;
  void (*eval)(SoilStep&, Model&, Impl&) = nullptr;
  double w_dx = 1.0;  // kernel value at the particle spacing (artificial stress)
  double gravity_x = 0.0, gravity_y = 0.0;  // gravity of the current evaluation (ramped: at its time), m/s^2
};

namespace {

// Raw pointers to the half-step values (registered in the particle set); valid until the next sort.
struct HalfStep {
  double *vxh, *vyh, *rhoh, *sxxh, *syyh, *szzh, *sxyh;
  HalfStep(ParticleSet& p, const SoilStep::Impl& w)
      : vxh(p.field(w.vxh).data()),
        vyh(p.field(w.vyh).data()),
        rhoh(p.field(w.rhoh).data()),
        sxxh(p.field(w.sxxh).data()),
        syyh(p.field(w.syyh).data()),
        szzh(p.field(w.szzh).data()),
        sxyh(p.field(w.sxyh).data()) {}
};

void index_kinds(const ParticleSet& p, SoilStep::Impl& w) {
  w.soil.clear();
  w.walls.clear();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool soil = p.kind[i] == static_cast<std::uint8_t>(ParticleKind::soil);
    w.is_soil[i] = soil ? 1.0 : 0.0;
    (soil ? w.soil : w.walls).push_back(static_cast<std::uint32_t>(i));
  }
}

// Sorts the particles by cell (every registered array follows) and keeps the soil/wall index lists current.
void sort_and_index(Model& model, SoilStep::Impl& w, double cell_size) {
  if (w.sorted.sort(model.particles, cell_size) == CellSortedSet::Change::kinds_moved) index_kinds(model.particles, w);
}

// Wall particles: Shepard-weighted soil stress with the Adami et al. (2012) hydrostatic correction on the
// normal components, and a ghost velocity (no-slip: -v_avg; free-slip: v_avg mirrored in the wall normal).
template <class Kernel>
void wall_pass(Model& model, SoilStep::Impl& w, const Kernel& kernel) {
  ParticleSet& p = model.particles;
  const SoilArrays sa = model.soil();
  const double support2 = kernel.support() * kernel.support();
  const double gx = w.gravity_x, gy = w.gravity_y;  // the soil's current load (ramped gravity included)
  const bool no_slip = model.settings.wall_slip == WallSlip::no_slip;
  const Index nw = static_cast<Index>(w.walls.size());
  const double* x = p.x.data();
  const double* y = p.y.data();
  const double* is_soil = w.is_soil.data();
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < nw; ++k) {
    const std::size_t i = w.walls[static_cast<std::size_t>(k)];
    const double xi = x[i], yi = y[i];
    double sw = 0, sxx = 0, syy = 0, szz = 0, sxy = 0, hydro = 0, svx = 0, svy = 0;
    w.sorted.cells().for_each_candidate(i, [&](std::uint32_t j) {
      const double dx = xi - x[j], dy = yi - y[j];
      const double r2 = dx * dx + dy * dy;
      if (r2 >= support2 || is_soil[j] == 0.0) return;  // walls never read other walls (no data race)
      const double wgt = kernel.value(std::sqrt(r2));
      sw += wgt;
      sxx += sa.sxx[j] * wgt;
      syy += sa.syy[j] * wgt;
      szz += sa.szz[j] * wgt;
      sxy += sa.sxy[j] * wgt;
      hydro += p.rho[j] * (gx * dx + gy * dy) * wgt;  // rho_f g.(x_w - x_f)
      svx += p.vx[j] * wgt;
      svy += p.vy[j] * wgt;
    });
    if (sw > 0) {
      const double inv = 1.0 / sw;
      const double axx = sxx * inv, ayy = syy * inv, axy = sxy * inv;
      const double ax = svx * inv, ay = svy * inv;
      if (no_slip) {
        // shear traction continuous across the wall; ghost velocity opposite to the soil's (2 v_wall - v, v_wall = 0)
        sa.sxx[i] = axx;
        sa.syy[i] = ayy;
        sa.sxy[i] = axy;
        p.vx[i] = -ax;
        p.vy[i] = -ay;
      } else {
        // free slip: mirror stress and velocity in the wall, Q = I - 2 n n: sigma_w = Q sigma Q (the
        // normal-tangential shear changes sign, so the wall transmits no shear traction), v_w = Q v
        const double nx = sa.wall_nx[i], ny = sa.wall_ny[i];
        const double q11 = 1.0 - 2.0 * nx * nx, q12 = -2.0 * nx * ny, q22 = 1.0 - 2.0 * ny * ny;
        // (Q S Q) for symmetric S = [axx axy; axy ayy]
        const double t11 = q11 * axx + q12 * axy, t12 = q11 * axy + q12 * ayy;
        const double t21 = q12 * axx + q22 * axy, t22 = q12 * axy + q22 * ayy;
        sa.sxx[i] = t11 * q11 + t12 * q12;
        sa.sxy[i] = t11 * q12 + t12 * q22;
        sa.syy[i] = t21 * q12 + t22 * q22;
        const double vn = ax * nx + ay * ny;
        p.vx[i] = ax - 2.0 * vn * nx;
        p.vy[i] = ay - 2.0 * vn * ny;
      }
      // Adami et al. (2012) hydrostatic correction of the normal stresses: sigma_w -= sum rho_f g.(x_w - x_f) W / sum W
      sa.sxx[i] -= hydro * inv;
      sa.syy[i] -= hydro * inv;
      sa.szz[i] = (szz - hydro) * inv;
    } else {
      sa.sxx[i] = sa.syy[i] = sa.szz[i] = sa.sxy[i] = 0.0;
      p.vx[i] = p.vy[i] = 0.0;
    }
  }
}

// Per-particle quantities used by the pair loop (all particles, soil and wall).
void prepare_pass(Model& model, SoilStep::Impl& w, const std::vector<MaterialConstants>& mc, bool artificial_stress,
                  double epsilon) {
  ParticleSet& p = model.particles;
  const SoilArrays sa = model.soil();
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double inv_rho = 1.0 / p.rho[i];
    const double inv_rho2 = inv_rho * inv_rho;
    w.pxx[i] = sa.sxx[i] * inv_rho2;
    w.pyy[i] = sa.syy[i] * inv_rho2;
    w.pxy[i] = sa.sxy[i] * inv_rho2;
    w.volume[i] = p.mass[i] * inv_rho;
    w.sound[i] = mc[p.material[i]].sound_speed;
    if (artificial_stress) {
      // Gray, Monaghan & Swift (2001): principal in-plane stresses; R' = -eps sigma'/rho^2 for tension.
      const double a = sa.sxx[i], b = sa.syy[i], c = sa.sxy[i];
      const double mean = 0.5 * (a + b);
      const double rad = std::sqrt(0.25 * (a - b) * (a - b) + c * c);
      const double s1 = mean + rad, s2 = mean - rad;
      const double theta = 0.5 * std::atan2(2.0 * c, a - b);
      const double cs = std::cos(theta), sn = std::sin(theta);
      const double r1 = s1 > 0 ? -epsilon * s1 * inv_rho2 : 0.0;
      const double r2 = s2 > 0 ? -epsilon * s2 * inv_rho2 : 0.0;
      w.rxx[i] = r1 * cs * cs + r2 * sn * sn;
      w.ryy[i] = r1 * sn * sn + r2 * cs * cs;
      w.rxy[i] = (r1 - r2) * sn * cs;
    }
  }
}

// What the pair sums read, gathered once per evaluation (after the sort, the wall pass and the prepare pass).
struct PairInputs {
  const double *x, *y, *vx, *vy, *rho, *mass;
  const double *pxx, *pyy, *pxy, *vol, *snd, *rxx, *ryy, *rxy, *is_soil;  // prepare_pass
  double h, support2, eta2, alpha, beta, inv_w_dx, as_n;

  PairInputs(const ParticleSet& p, const SoilStep::Impl& w, const Settings& st, double h_, double support)
      : x(p.x.data()), y(p.y.data()), vx(p.vx.data()), vy(p.vy.data()), rho(p.rho.data()), mass(p.mass.data()),
        pxx(w.pxx.data()), pyy(w.pyy.data()), pxy(w.pxy.data()), vol(w.volume.data()), snd(w.sound.data()),
        rxx(w.rxx.data()), ryy(w.ryy.data()), rxy(w.rxy.data()), is_soil(w.is_soil.data()), h(h_),
        support2(support * support), eta2(st.viscosity.eta_factor * h_ * h_), alpha(st.viscosity.alpha),
        beta(st.viscosity.beta), inv_w_dx(1.0 / w.w_dx), as_n(st.artificial_stress.exponent) {}
};

// The sums over the neighbours of one particle.
struct PairSums {
  double drho = 0, ax = 0, ay = 0, xsph_x = 0, xsph_y = 0;
  VelocityGradient gradient;
};

// Gathers the pair terms of particle i over its neighbours [C, L, AV, AS, M, X].
template <class Kernel, bool kArtificialStress, bool kXsph>
PairSums pair_sums(std::size_t i, const PairInputs& in, const Kernel& kernel, const CellList& cells) {
  const double xi = in.x[i], yi = in.y[i], vxi = in.vx[i], vyi = in.vy[i], rhoi = in.rho[i], ci = in.snd[i];
  const double pxxi = in.pxx[i], pyyi = in.pyy[i], pxyi = in.pxy[i];
  double rxxi = 0, ryyi = 0, rxyi = 0;
  if constexpr (kArtificialStress) {
    rxxi = in.rxx[i]; ryyi = in.ryy[i]; rxyi = in.rxy[i];
  }
  PairSums sum;
  IndexRange ranges[3];
  const int nr = cells.candidate_ranges(i, ranges);
  for (int rr = 0; rr < nr; ++rr) {
    for (std::uint32_t j = ranges[rr].begin; j < ranges[rr].end; ++j) {
      const double dx = xi - in.x[j], dy = yi - in.y[j];
      const double r2 = dx * dx + dy * dy;
      if (r2 >= in.support2) continue;
      const double r = std::sqrt(r2);
      const double F = kernel.gradient_factor(r);
      const PairGeometry g{dx, dy, r2, r, F * dx, F * dy};
      const double dvx = vxi - in.vx[j], dvy = vyi - in.vy[j];  // v_i - v_j (a wall: its ghost velocity)
      const double mj = in.mass[j];
      // [C] with the walls' own velocity (at rest): with the no-slip ghost velocity -v_avg here, a particle sliding
      // down a wall next to the free surface, whose wall neighbours above see only it, lost density at a rate
      // ~ 2 v |grad W| until it went negative (docs/stability.md).
      sum.drho += continuity(mj, vxi - in.is_soil[j] * in.vx[j], vyi - in.is_soil[j] * in.vy[j], g);
      sum.gradient.add(in.vol[j], dvx, dvy, g);
      const double rho_bar = mean_density(rhoi, in.rho[j]);
      const double pi_ij = artificial_viscosity(in.h, in.eta2, in.alpha, in.beta, ci, in.snd[j], rho_bar, dvx, dvy, g);
      double txx = pxxi + in.pxx[j] - pi_ij;
      double tyy = pyyi + in.pyy[j] - pi_ij;
      double txy = pxyi + in.pxy[j];
      if constexpr (kArtificialStress) {
        const double fn = artificial_stress_weight(kernel.value(r), in.inv_w_dx, in.as_n);
        txx += fn * (rxxi + in.rxx[j]);
        tyy += fn * (ryyi + in.ryy[j]);
        txy += fn * (rxyi + in.rxy[j]);
      }
      momentum(mj, txx, tyy, txy, g, sum.ax, sum.ay);
      if constexpr (kXsph) {
        const double wv = xsph_weight(mj, rho_bar, kernel.value(r));
        sum.xsph_x -= wv * dvx;
        sum.xsph_y -= wv * dvy;
      }
    }
  }
  return sum;
}

// Rates for every soil particle; pairs are gathered from the perspective of i (no write conflicts).
template <class Kernel, bool kArtificialStress, bool kXsph>
void evaluate_rates(SoilStep& self, Model& model, SoilStep::Impl& w) {
  ParticleSet& p = model.particles;
  const Settings& st = model.settings;
  const Kernel kernel(self.smoothing_length());
  sort_and_index(model, w, kernel.support());
  wall_pass(model, w, kernel);
  prepare_pass(model, w, self.material_constants(), kArtificialStress, st.artificial_stress.epsilon);
  const SoilArrays sa = model.soil();  // after the sort: it may have swapped the arrays' buffers
  const PairInputs in(p, w, st, kernel.h(), kernel.support());
  const double chi = st.xsph.chi;
  const double gx = w.gravity_x, gy = w.gravity_y, damping = st.damping;
  const auto& mc = self.material_constants();
  const CellList& cells = w.sorted.cells();

  const Index ns = static_cast<Index>(w.soil.size());
#pragma omp parallel for schedule(dynamic, 256)  // gather per particle: results do not depend on the schedule
  for (Index k = 0; k < ns; ++k) {
    const std::size_t i = w.soil[static_cast<std::size_t>(k)];
    const PairSums sum = pair_sums<Kernel, kArtificialStress, kXsph>(i, in, kernel, cells);
    const double vxi = p.vx[i], vyi = p.vy[i];
    sa.drho[i] = sum.drho;
    sa.ax[i] = sum.ax + gx - damping * vxi;
    sa.ay[i] = sum.ay + gy - damping * vyi;
    // [L] strain rate and spin, [E, P, J] the stress rate of the material
    const VelocityGradient& L = sum.gradient;
    const Stress s{sa.sxx[i], sa.syy[i], sa.szz[i], sa.sxy[i]};
    const StressRate sr = stress_rate(mc[p.material[i]], s, L.xx, L.yy, 0.5 * (L.xy + L.yx), 0.5 * (L.xy - L.yx));
    sa.dsxx[i] = sr.rate.xx;
    sa.dsyy[i] = sr.rate.yy;
    sa.dszz[i] = sr.rate.zz;
    sa.dsxy[i] = sr.rate.xy;
    sa.dplastic_strain[i] = sr.plastic_strain_rate;
    sa.dplastic_work[i] = sr.plastic_work_rate / p.rho[i];
    if constexpr (kXsph) {
      w.xsph_dx[i] = chi * sum.xsph_x;
      w.xsph_dy[i] = chi * sum.xsph_y;
    }
  }
}

template <class Kernel>
void (*pick_eval(bool as, bool xsph))(SoilStep&, Model&, SoilStep::Impl&) {
  if (as) return xsph ? &evaluate_rates<Kernel, true, true> : &evaluate_rates<Kernel, true, false>;
  return xsph ? &evaluate_rates<Kernel, false, true> : &evaluate_rates<Kernel, false, false>;
}

// Deterministic block reduction over soil particles: f(i) -> 3 sums.
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
  for (auto* a : {&w.pxx, &w.pyy, &w.pxy, &w.volume, &w.sound, &w.is_soil, &w.rxx, &w.ryy, &w.rxy, &w.xsph_dx,
                  &w.xsph_dy})
    a->assign(n, 0.0);
  w.sorted.reserve(model_.particles);
  index_kinds(model_.particles, w);  // valid for the current order; sorts keep them up to date
  w.soil.reserve(n);
  w.walls.reserve(n);
  const double dx = st.particle_spacing;
  if (st.kernel == KernelType::cubic_spline) {
    w.eval = pick_eval<CubicSplineKernel>(artificial_stress_, st.xsph.enabled);
    w.w_dx = CubicSplineKernel(h_).value(dx);
  } else {
    w.eval = pick_eval<WendlandC2Kernel>(artificial_stress_, st.xsph.enabled);
    w.w_dx = WendlandC2Kernel(h_).value(dx);
  }
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
                sxyh = workspace("half_step_stress_xy");
  if (impl) {
    impl->vxh = vxh;
    impl->vyh = vyh;
    impl->rhoh = rhoh;
    impl->sxxh = sxxh;
    impl->syyh = syyh;
    impl->szzh = szzh;
    impl->sxyh = sxyh;
  }
}

void SoilStep::apply_geostatic_stress() {
  ParticleSet& p = model_.particles;
  const SoilArrays sa = model_.soil();
  const double g = -model_.settings.gravity_y;
  const double dx = model_.settings.particle_spacing;
  std::vector<std::uint32_t> soil;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::soil)) soil.push_back(static_cast<std::uint32_t>(i));
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
  long long current = std::numeric_limits<long long>::min();
  double above = 0;  // sum rho dx g of the particles above in this column
  for (auto i : soil) {
    const long long c = column(i);
    if (c != current) {
      current = c;
      above = 0;
    }
    const double rho_g_dx = p.rho[i] * g * dx;
    const double syy = -(above + 0.5 * rho_g_dx);
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
  const Settings& st = model_.settings;
  const double factor = st.gravity_factor(time);
  impl_->gravity_x = factor * st.gravity_x;
  impl_->gravity_y = factor * st.gravity_y;
  impl_->eval(*this, model_, *impl_);
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
  const double dt_c =
      st.cfl * h_ / (c_max_ * (1.0 + 1.2 * st.viscosity.alpha) + vmax * (1.0 + 2.4 * st.viscosity.beta));
  const double amax = std::sqrt(a2max);
  const double dt_a = amax > 0 ? st.acceleration_safety * std::sqrt(h_ / amax) : std::numeric_limits<double>::infinity();
  return std::min(dt_c, dt_a);
}

void SoilStep::advance(double dt) {
  ParticleSet& p = model_.particles;
  auto& w = *impl_;
  const double half = 0.5 * dt;
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
      Stress s{hs.sxxh[i] + half * sa.dsxx[i], hs.syyh[i] + half * sa.dsyy[i], hs.szzh[i] + half * sa.dszz[i],
               hs.sxyh[i] + half * sa.dsxy[i]};
      const ReturnResult rr = return_to_yield_surface(mc_[p.material[i]], s);
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
  return {pressure};
}

Energies SoilStep::energies() const {
  const ParticleSet& p = model_.particles;
  const SoilArrays sa = model_.soil();
  auto& w = *impl_;
  const double gx = model_.settings.gravity_x, gy = model_.settings.gravity_y;
  Energies e;
  block_sums(
      w.soil, w.block_a, w.block_b, w.block_c,
      [&](std::size_t i, double& ke, double& pe, double& pw) {
        ke += 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
        pe -= p.mass[i] * (gx * p.x[i] + gy * p.y[i]);
        pw += p.mass[i] * sa.plastic_work[i];
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

}  // namespace sph
