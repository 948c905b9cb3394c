// The passes of one rate evaluation of the soil model (sort, wall extrapolation, preparation, the pair loop over
// the neighbours); the equations of each pair term are in terms.hpp.
#include "step_impl.hpp"
#include "terms.hpp"
#include "wall_friction.hpp"

#include <omp.h>

#include <cmath>

namespace sph::soil::detail {

namespace {
using namespace terms;
using Index = std::int64_t;
}  // namespace

void index_kinds(const ParticleSet& p, SoilStep::Impl& w) {
  w.soil.clear();
  w.walls.clear();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool soil = p.kind[i] == static_cast<std::uint8_t>(ParticleKind::material);
    w.is_soil[i] = soil ? 1.0 : 0.0;
    (soil ? w.soil : w.walls).push_back(static_cast<std::uint32_t>(i));
  }
}

namespace {

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
  const bool no_slip = model.settings.wall_slip == WallSlip::no_slip;  // frictional walls: free-slip ghosts
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

// The smallest eigenvalue of the moment matrix M_i for which the corrected gradient is used (model.hpp: 0.25, 0.5
// and 0.8 were tried; only 0.8 and above keep the granular collapse's front from blowing up).
constexpr double kMinMomentEigenvalue = 0.8;

// Corrected kernel gradient: B_i = M_i^-1, M_i = sum_j V_j (x_j - x_i) (x) grad_i W_ij = -sum_j V_j F_ij x_ij (x) x_ij
// (symmetric; the identity for a full, continuous support), for soil and wall particles alike (a wall's B_j enters
// the soil's momentum sum). A particle without a nearly full support keeps B = I.
template <class Kernel>
void correction_pass(const ParticleSet& p, SoilStep::Impl& w, const Kernel& kernel) {
  const double support2 = kernel.support() * kernel.support();
  const Index n = static_cast<Index>(p.size());
  const double *x = p.x.data(), *y = p.y.data(), *vol = w.volume.data();
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    double mxx = 0.0, mxy = 0.0, myy = 0.0;  // M_i over every neighbour, soil and wall
    w.sorted.cells().for_each_candidate(i, [&](std::uint32_t j) {
      const double dx = x[i] - x[j], dy = y[i] - y[j];
      const double r2 = dx * dx + dy * dy;
      if (r2 >= support2 || r2 == 0.0) return;
      const double f = -vol[j] * kernel.gradient_factor(std::sqrt(r2));
      mxx += f * dx * dx;
      mxy += f * dx * dy;
      myy += f * dy * dy;
    });
    const double mean = 0.5 * (mxx + myy);
    const double smallest = mean - std::sqrt(0.25 * (mxx - myy) * (mxx - myy) + mxy * mxy);
    if (!(smallest >= kMinMomentEigenvalue)) mxx = 1.0, mxy = 0.0, myy = 1.0;
    const double inv_det = 1.0 / (mxx * myy - mxy * mxy);
    w.bxx[i] = myy * inv_det;
    w.bxy[i] = -mxy * inv_det;
    w.byy[i] = mxx * inv_det;
  }
}

// The options of the pair terms, fixed for a run. They are run-time flags, not template parameters: the pair loop is
// compiled once per kernel and pass (6 copies, where one per combination of the options made 48), with no cost that
// side-by-side runs resolve (about 1 % on the collapse; docs/performance.md, "Soil pair loop").
struct PairOptions {
  bool artificial_stress = false;  // the artificial stress term (Model::uses_artificial_stress)
  bool xsph = false;               // the XSPH velocity correction (Settings::xsph)
  bool corrected = false;          // the corrected kernel gradient (Settings::kernel_gradient)
  bool frictional = false;         // the walls' forces gathered apart, for their friction (WallSlip::frictional)
};

// What the pair sums read, gathered once per evaluation (after the sort, the wall pass and the prepare pass).
struct PairInputs {
  const double *x, *y, *vx, *vy, *rho, *mass;
  const double *pxx, *pyy, *pxy, *vol, *snd, *rxx, *ryy, *rxy, *is_soil;  // prepare_pass
  const double *bxx, *bxy, *byy;                                           // correction_pass (corrected gradient)
  const double *wall_nx, *wall_ny;                                         // the walls' inward normals
  double h, support2, eta2, alpha, beta, inv_w_dx, as_n;
  PairOptions options;

  PairInputs(const ParticleSet& p, const ConstSoilArrays& sa, const SoilStep::Impl& w, const Settings& st, double h_,
             double support, const PairOptions& options_)
      : x(p.x.data()), y(p.y.data()), vx(p.vx.data()), vy(p.vy.data()), rho(p.rho.data()), mass(p.mass.data()),
        pxx(w.pxx.data()), pyy(w.pyy.data()), pxy(w.pxy.data()), vol(w.volume.data()), snd(w.sound.data()),
        rxx(w.rxx.data()), ryy(w.ryy.data()), rxy(w.rxy.data()), is_soil(w.is_soil.data()), bxx(w.bxx.data()),
        bxy(w.bxy.data()), byy(w.byy.data()), wall_nx(sa.wall_nx), wall_ny(sa.wall_ny), h(h_),
        support2(support * support), eta2(st.viscosity.eta_factor * h_ * h_), alpha(st.viscosity.alpha),
        beta(st.viscosity.beta), inv_w_dx(1.0 / w.w_dx), as_n(st.artificial_stress.exponent), options(options_) {}
};

// The sums over the neighbours of one particle.
struct PairSums {
  double drho = 0, ax = 0, ay = 0, xsph_x = 0, xsph_y = 0;
  VelocityGradient gradient;
  // With frictional walls: the walls' share of the acceleration (not in ax, ay) and sum_j W_ij n_j over the walls.
  double wall_ax = 0, wall_ay = 0, wall_nx = 0, wall_ny = 0;
};

// grad_i W_ij of a pair multiplied by a particle's symmetric correction B = [bxx bxy; bxy byy].
inline PairGeometry corrected(const PairGeometry& g, double bxx, double bxy, double byy) {
  return PairGeometry{g.dx, g.dy, g.r2, g.r, bxx * g.gwx + bxy * g.gwy, bxy * g.gwx + byy * g.gwy};
}

// The forces of a pair with the corrected gradient: m_j [(P_i - Pi/2 I + f^n R_i) B_i + (P_j - Pi/2 I + f^n R_j) B_j]
// grad_i W_ij, P = sigma/rho^2: antisymmetric in i and j, exact for a linear stress field in a regular interior.
inline void corrected_momentum(std::size_t i, std::uint32_t j, const PairInputs& in, double pi_ij, double fn,
                               const PairGeometry& gi, const PairGeometry& gj, double& ax, double& ay) {
  const double half = 0.5 * pi_ij;
  double ixx = in.pxx[i] - half, iyy = in.pyy[i] - half, ixy = in.pxy[i];
  double jxx = in.pxx[j] - half, jyy = in.pyy[j] - half, jxy = in.pxy[j];
  if (in.options.artificial_stress) {
    ixx += fn * in.rxx[i]; iyy += fn * in.ryy[i]; ixy += fn * in.rxy[i];
    jxx += fn * in.rxx[j]; jyy += fn * in.ryy[j]; jxy += fn * in.rxy[j];
  }
  momentum(in.mass[j], ixx, iyy, ixy, gi, ax, ay);
  momentum(in.mass[j], jxx, jyy, jxy, gj, ax, ay);
}

// The pair terms of particle i: the kinematic terms [C, L, X] when kRates, the forces [AV, AS, M] when kForces
// (both: the combined evaluation, in the order its results were pinned with); the options (artificial stress, XSPH,
// corrected kernel gradient) from the inputs. add() takes one neighbour within the support: x_ij, r_ij^2, r_ij and
// F(r_ij).
template <class Kernel, bool kRates, bool kForces>
struct PairTerms {
  const PairInputs& in;
  const Kernel& kernel;
  std::size_t i;
  double xi, yi, vxi, vyi, rhoi, ci, pxxi, pyyi, pxyi, rxxi = 0, ryyi = 0, rxyi = 0;

  PairTerms(std::size_t i_, const PairInputs& in_, const Kernel& kernel_)
      : in(in_), kernel(kernel_), i(i_), xi(in_.x[i_]), yi(in_.y[i_]), vxi(in_.vx[i_]), vyi(in_.vy[i_]),
        rhoi(in_.rho[i_]), ci(in_.snd[i_]), pxxi(in_.pxx[i_]), pyyi(in_.pyy[i_]), pxyi(in_.pxy[i_]) {
    if (in.options.artificial_stress) {
      rxxi = in.rxx[i]; ryyi = in.ryy[i]; rxyi = in.rxy[i];
    }
  }

  void add(std::uint32_t j, double dx, double dy, double r2, double r, double F, PairSums& sum) const {
    const PairGeometry g{dx, dy, r2, r, F * dx, F * dy};
    const double dvx = vxi - in.vx[j], dvy = vyi - in.vy[j];  // v_i - v_j (a wall: its ghost velocity)
    const double mj = in.mass[j];
    const double rho_bar = mean_density(rhoi, in.rho[j]);
    const bool artificial_stress = in.options.artificial_stress;
    if (in.options.corrected) {
      const PairGeometry gi = corrected(g, in.bxx[i], in.bxy[i], in.byy[i]);
      if constexpr (kRates) {
        sum.drho += continuity(mj, vxi - in.is_soil[j] * in.vx[j], vyi - in.is_soil[j] * in.vy[j], gi);
        sum.gradient.add(in.vol[j], dvx, dvy, gi);
      }
      if constexpr (kForces) {
        const double pi_ij = artificial_viscosity(in.h, in.eta2, in.alpha, in.beta, ci, in.snd[j], rho_bar, dvx, dvy, g);
        const double fn = artificial_stress ? artificial_stress_weight(kernel.value(r), in.inv_w_dx, in.as_n) : 0.0;
        const bool wall = wall_share(j, r, sum);
        corrected_momentum(i, j, in, pi_ij, fn, gi, corrected(g, in.bxx[j], in.bxy[j], in.byy[j]),
                           wall ? sum.wall_ax : sum.ax, wall ? sum.wall_ay : sum.ay);
      }
      if constexpr (kRates) add_xsph(mj, rho_bar, r, dvx, dvy, sum);
      return;
    }
    if constexpr (kRates) {
      // [C] with the walls' own velocity (at rest): with the no-slip ghost velocity -v_avg here, a particle sliding
      // down a wall next to the free surface, whose wall neighbours above see only it, lost density at a rate
      // ~ 2 v |grad W| until it went negative (docs/stability.md).
      sum.drho += continuity(mj, vxi - in.is_soil[j] * in.vx[j], vyi - in.is_soil[j] * in.vy[j], g);
      sum.gradient.add(in.vol[j], dvx, dvy, g);
    }
    if constexpr (kForces) {
      const double pi_ij = artificial_viscosity(in.h, in.eta2, in.alpha, in.beta, ci, in.snd[j], rho_bar, dvx, dvy, g);
      double txx = pxxi + in.pxx[j] - pi_ij;
      double tyy = pyyi + in.pyy[j] - pi_ij;
      double txy = pxyi + in.pxy[j];
      if (artificial_stress) {
        const double fn = artificial_stress_weight(kernel.value(r), in.inv_w_dx, in.as_n);
        txx += fn * (rxxi + in.rxx[j]);
        tyy += fn * (ryyi + in.ryy[j]);
        txy += fn * (rxyi + in.rxy[j]);
      }
      if (wall_share(j, r, sum))
        momentum(mj, txx, tyy, txy, g, sum.wall_ax, sum.wall_ay);
      else
        momentum(mj, txx, tyy, txy, g, sum.ax, sum.ay);
    }
    if constexpr (kRates) add_xsph(mj, rho_bar, r, dvx, dvy, sum);
  }

  // With frictional walls, whether j is a wall (its force then goes to the walls' share), adding W_ij n_j to the
  // walls' normal sum.
  bool wall_share(std::uint32_t j, double r, PairSums& sum) const {
    if (!in.options.frictional || in.is_soil[j] != 0.0) return false;
    const double wr = kernel.value(r);
    sum.wall_nx += wr * in.wall_nx[j];
    sum.wall_ny += wr * in.wall_ny[j];
    return true;
  }

  // [X] the XSPH sum, when the run has it.
  void add_xsph(double mj, double rho_bar, double r, double dvx, double dvy, PairSums& sum) const {
    if (!in.options.xsph) return;
    const double wv = xsph_weight(mj, rho_bar, kernel.value(r));
    sum.xsph_x -= wv * dvx;
    sum.xsph_y -= wv * dvy;
  }
};

// Gathers the pair terms of particle i over the candidates of its cell neighbourhood; with a buffer, records each
// pair within the support in it (the Verlet step's kinematic pass, for its forces pass).
template <class Kernel, bool kRates, bool kForces>
PairSums pair_sums(std::size_t i, const PairInputs& in, const Kernel& kernel, const CellList& cells,
                   PairCache::Buffer* record) {
  const PairTerms<Kernel, kRates, kForces> terms(i, in, kernel);
  PairSums sum;
  IndexRange ranges[3];
  const int nr = cells.candidate_ranges(i, ranges);
  for (int rr = 0; rr < nr; ++rr) {
    for (std::uint32_t j = ranges[rr].begin; j < ranges[rr].end; ++j) {
      const double dx = terms.xi - in.x[j], dy = terms.yi - in.y[j];
      const double r2 = dx * dx + dy * dy;
      if (r2 >= in.support2) continue;
      const double r = std::sqrt(r2);
      const double F = kernel.gradient_factor(r);
      if (record) {
        record->j.push_back(j);
        record->r.push_back(r);
        record->f.push_back(F);
      }
      terms.add(j, dx, dy, r2, r, F, sum);
    }
  }
  return sum;
}

// The same sums over the `count` pairs recorded from `first` in a buffer.
template <class Kernel, bool kRates, bool kForces>
PairSums recorded_pair_sums(std::size_t i, const PairInputs& in, const Kernel& kernel, const PairCache::Buffer& buffer,
                            std::size_t first, std::size_t count) {
  const PairTerms<Kernel, kRates, kForces> terms(i, in, kernel);
  PairSums sum;
  const std::uint32_t* js = buffer.j.data() + first;
  const double *rs = buffer.r.data() + first, *fs = buffer.f.data() + first;
  for (std::size_t m = 0; m < count; ++m) {
    const std::uint32_t j = js[m];
    const double dx = terms.xi - in.x[j], dy = terms.yi - in.y[j];
    terms.add(j, dx, dy, dx * dx + dy * dy, rs[m], fs[m], sum);
  }
  return sum;
}

// The accelerations of the loads besides gravity (sph/soil/loads.hpp), at the evaluation's load factor: the seismic
// body force, minus the pore-pressure gradient over the density, the surface forces over the mass.
struct LoadTerms {
  const PiezometricLine* water = nullptr;
  const double *fx = nullptr, *fy = nullptr;
  double factor = 0.0, seismic_ax = 0.0, seismic_ay = 0.0;
  bool active = false;

  LoadTerms(Model& model, double load_factor) : factor(load_factor) {
    const SoilLoads& l = model.loads;
    active = l.any();
    if (!active) return;
    if (l.water) water = &*l.water;
    if (l.surface_force_x) {
      fx = model.particles.field(*l.surface_force_x).data();
      fy = model.particles.field(*l.surface_force_y).data();
    }
    const double g = std::hypot(model.settings.gravity_x, model.settings.gravity_y);
    seismic_ax = factor * l.seismic_coefficient * g;
    seismic_ay = factor * l.vertical_seismic_coefficient * g;
  }

  void add(const ParticleSet& p, std::size_t i, double& ax, double& ay) const {
    ax += seismic_ax;
    if (seismic_ay != 0.0) ay += seismic_ay;
    if (water) {
      double ux = 0.0, uy = 0.0;
      water->gradient(p.x[i], p.y[i], ux, uy);
      ax -= factor * ux / p.rho[i];
      ay -= factor * uy / p.rho[i];
    }
    if (fx) {
      ax += factor * fx[i] / p.mass[i];
      ay += factor * fy[i] / p.mass[i];
    }
  }
};

// Particle i's density and stress rates (and the velocity gradient, for stress sub-steps) from its pair sums [C, L,
// E, P, J], and its XSPH correction when the run has it.
inline void write_kinematic_rates(const ParticleSet& p, const SoilArrays& sa, SoilStep::Impl& w,
                                  const MaterialConstants& mc, std::size_t i, const PairSums& sum, bool xsph,
                                  double chi) {
  sa.drho[i] = sum.drho;
  // [L] strain rate and spin, [E, P, J] the stress rate of the material
  const VelocityGradient& L = sum.gradient;
  const Stress s{sa.sxx[i], sa.syy[i], sa.szz[i], sa.sxy[i]};
  const StressRate sr = stress_rate(mc, s, L.xx, L.yy, 0.5 * (L.xy + L.yx), 0.5 * (L.xy - L.yx));
  if (!w.lxx.empty()) {
    w.lxx[i] = L.xx;
    w.lyy[i] = L.yy;
    w.lexy[i] = 0.5 * (L.xy + L.yx);
    w.lwxy[i] = 0.5 * (L.xy - L.yx);
  }
  sa.dsxx[i] = sr.rate.xx;
  sa.dsyy[i] = sr.rate.yy;
  sa.dszz[i] = sr.rate.zz;
  sa.dsxy[i] = sr.rate.xy;
  sa.dplastic_strain[i] = sr.plastic_strain_rate;
  sa.dplastic_work[i] = sr.plastic_work_rate / p.rho[i];
  if (xsph) {
    w.xsph_dx[i] = chi * sum.xsph_x;
    w.xsph_dy[i] = chi * sum.xsph_y;
  }
}

// The rates of every soil particle; pairs are gathered from the perspective of i (no write conflicts). kRates: sorts
// by cell first and writes the density and stress rates (and XSPH); kForces: writes the acceleration.
template <class Kernel, bool kRates, bool kForces>
void evaluate_rates(SoilStep& self, Model& model, SoilStep::Impl& w) {
  ParticleSet& p = model.particles;
  const Settings& st = model.settings;
  const PairOptions options{self.artificial_stress_enabled(), st.xsph.enabled,
                            st.kernel_gradient == KernelGradient::corrected, st.wall_slip == WallSlip::frictional};
  const Kernel kernel(self.smoothing_length());
  if constexpr (kRates) sort_and_index(model, w, kernel.support());
  wall_pass(model, w, kernel);
  prepare_pass(model, w, self.material_constants(), options.artificial_stress && kForces,
               st.artificial_stress.epsilon);
  if (options.corrected) correction_pass(p, w, kernel);
  const SoilArrays sa = model.soil();  // after the sort: it may have swapped the arrays' buffers
  const PairInputs in(p, ConstSoilArrays(sa), w, st, kernel.h(), kernel.support(), options);
  const double chi = st.xsph.chi;
  const double gx = w.gravity_x, gy = w.gravity_y, damping = st.damping;
  const LoadTerms loads(model, w.load_factor);
  const WallFriction friction(model, w, self.max_sound_speed(), kForces && options.frictional);  // else inert
  const auto& mc = self.material_constants();
  const CellList& cells = w.sorted.cells();

  const Index ns = static_cast<Index>(w.soil.size());
  // The Verlet step's kinematic pass records its pairs; its forces pass reads them (PairCache).
  constexpr bool kRecord = kRates && !kForces, kRecorded = kForces && !kRates;
  PairCache& cache = w.pairs;
  if constexpr (kRecord) {
    cache.buffers.resize(static_cast<std::size_t>(omp_get_max_threads()));
    for (auto& b : cache.buffers) b.clear();
    for (auto* v : {&cache.thread, &cache.first, &cache.count}) v->resize(w.soil.size());
  }
#pragma omp parallel for schedule(dynamic, 256)  // gather per particle: results do not depend on the schedule
  for (Index k = 0; k < ns; ++k) {
    const std::size_t i = w.soil[static_cast<std::size_t>(k)];
    const auto kk = static_cast<std::size_t>(k);
    PairSums sum;
    if constexpr (kRecorded) {
      sum = recorded_pair_sums<Kernel, kRates, kForces>(
          i, in, kernel, cache.buffers[cache.thread[kk]], cache.first[kk], cache.count[kk]);
    } else if constexpr (kRecord) {
      const auto t = static_cast<std::size_t>(omp_get_thread_num());
      PairCache::Buffer& buffer = cache.buffers[t];
      const std::size_t first = buffer.j.size();
      sum = pair_sums<Kernel, kRates, kForces>(i, in, kernel, cells, &buffer);
      cache.thread[kk] = static_cast<std::uint32_t>(t);
      cache.first[kk] = static_cast<std::uint32_t>(first);
      cache.count[kk] = static_cast<std::uint32_t>(buffer.j.size() - first);
    } else {
      sum = pair_sums<Kernel, kRates, kForces>(i, in, kernel, cells, nullptr);
    }
    if constexpr (kForces) {
      const double vxi = p.vx[i], vyi = p.vy[i];
      sa.ax[i] = sum.ax + gx - damping * vxi;
      sa.ay[i] = sum.ay + gy - damping * vyi;
      if (loads.active) loads.add(p, i, sa.ax[i], sa.ay[i]);
      if (options.frictional) {
        sa.ax[i] += sum.wall_ax;
        sa.ay[i] += sum.wall_ay;
        friction.record(i, sum.wall_ax, sum.wall_ay, sum.wall_nx, sum.wall_ny);
      }
    }
    if constexpr (kRates) write_kinematic_rates(p, sa, w, mc[p.material[i]], i, sum, options.xsph, chi);
  }
  if constexpr (kForces)
    if (options.frictional) friction.apply(model, w, kernel);
}

template <class Kernel>
Evaluators evaluators() {
  return {&evaluate_rates<Kernel, true, true>, &evaluate_rates<Kernel, true, false>,
          &evaluate_rates<Kernel, false, true>};
}

}  // namespace

Evaluators select_evaluators(KernelType kernel) {
  return kernel == KernelType::cubic_spline ? evaluators<CubicSplineKernel>() : evaluators<WendlandC2Kernel>();
}

}  // namespace sph::soil::detail
