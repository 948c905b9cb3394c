#pragma once
// The frictional walls' Coulomb friction on the soil (WallSlip::frictional; docs/sph.md, "Walls"): a part of the soil
// model's rate evaluation (step_passes.cpp), which records each soil particle's push by the walls in its pair loop
// and applies the friction after it.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "step_impl.hpp"
#include "sphslope/units.hpp"

namespace sph::soil::detail {

// Coulomb friction of the walls on the soil particles (WallSlip::frictional; docs/sph.md, "Walls"). The walls push
// soil particle i with the sum of its pairs with wall particles; its part along their mean inward normal n
// (sum_j W_ij n_j, normalised) is its push a_n (record(), from the pair loop). The bound of its friction is tan(delta)
// max(P, 0), P the push averaged over the particles in contact around it (Shepard, mass-weighted: single particles'
// pushes alternate in sign along a wall, the SPH operators' odd-even mode) and relaxed in time (dP/dt = (avg - P)/T,
// a checkpointed field). The friction takes a tangential acceleration of at most the bound against the particle's
// trial tangential motion, the tangential velocity it would have after dt without friction, over dt (v_t / dt + a_t,
// a_t the tangential part of every other acceleration): below the bound it stops that motion (sticking), at the bound
// it opposes it (sliding), the contact rule of MPM's frictional contact (Bardenhagen, Brackbill & Sulsky 2000).
// dt = 0 (the first evaluation, before any step): P = the average, and the bound against v_t, or against a_t at rest.
// Why P is averaged and relaxed: with the bound following each particle's push at once, a stiff block sliding down a
// 45 deg plane rocked on it, its pushes swinging by several times their mean, and took up to 1.5 times the friction
// (steady sliding with Coulomb friction on an elastic body is unstable: Adams 1995; the response to a change of normal
// stress is regularised in time: Prakash & Clifton 1993); docs/sph.md, "Walls", has the measurements.
constexpr double kFrictionRelaxation = 30.0;  // T = kFrictionRelaxation h / c_max (10 failed, 20-40 held)

struct WallFriction {
  double tan_delta = 0.0, dt = 0.0, relax = 1.0;  // relax: the fraction 1 - exp(-dt / T) of a step
  double* push = nullptr;                         // the relaxed push P of each particle [m/s^2]
  double* raw = nullptr;                          // this evaluation's push a_n of each particle [m/s^2]
  double *nx = nullptr, *ny = nullptr;            // ... and its contact normal (0, 0 without wall neighbours)

  // Inert (no work, no scratch) unless `active`: the evaluation computes forces and the walls are frictional.
  WallFriction(Model& model, SoilStep::Impl& w, double c_max, bool active) {
    if (!active) return;
    const Settings& st = model.settings;
    tan_delta = std::tan(st.wall_friction_angle_deg * sphslope::degree);
    dt = w.step_dt;
    const double relaxation_time = kFrictionRelaxation * st.smoothing_length() / c_max;
    relax = dt > 0.0 ? -std::expm1(-dt / relaxation_time) : 1.0;
    push = model.particles.field(w.wall_push).data();
    const std::size_t n = model.particles.size();
    w.contact_push.assign(n, 0.0);
    w.contact_nx.assign(n, 0.0);
    w.contact_ny.assign(n, 0.0);
    raw = w.contact_push.data();
    nx = w.contact_nx.data();
    ny = w.contact_ny.data();
  }

  // Particle i's push and contact normal from the walls' share of its acceleration (ax, ay) and sum_j W_ij n_j over
  // its wall neighbours (sx, sy).
  void record(std::size_t i, double ax, double ay, double sx, double sy) const {
    const double norm = std::hypot(sx, sy);
    if (!(norm > 0.0)) return;
    nx[i] = sx / norm;
    ny[i] = sy / norm;
    raw[i] = ax * nx[i] + ay * ny[i];
  }

  // Every soil particle's friction, once each has its push and its acceleration without friction.
  template <class Kernel>
  void apply(Model& model, const SoilStep::Impl& w, const Kernel& kernel) const {
    ParticleSet& p = model.particles;
    const SoilArrays sa = model.soil();
    const double support2 = kernel.support() * kernel.support();
    const auto ns = static_cast<std::int64_t>(w.soil.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t k = 0; k < ns; ++k) {
      const std::size_t i = w.soil[static_cast<std::size_t>(k)];
      if (nx[i] == 0.0 && ny[i] == 0.0) {
        push[i] = 0.0;
        continue;
      }
      double sw = 0.0, sp = 0.0;
      w.sorted.cells().for_each_candidate(i, [&](std::uint32_t j) {
        if (nx[j] == 0.0 && ny[j] == 0.0) return;  // walls and soil out of contact
        const double ddx = p.x[i] - p.x[j], ddy = p.y[i] - p.y[j];
        const double r2 = ddx * ddx + ddy * ddy;
        if (r2 >= support2) return;
        const double wm = kernel.value(std::sqrt(r2)) * p.mass[j];
        sw += wm;
        sp += wm * raw[j];
      });
      push[i] += relax * (sp / sw - push[i]);
      const double bound = tan_delta * std::max(push[i], 0.0);
      if (!(bound > 0.0)) continue;
      const double tx = -ny[i], ty = nx[i];
      const double vt = p.vx[i] * tx + p.vy[i] * ty, at = sa.ax[i] * tx + sa.ay[i] * ty;
      double trial = at;  // the tangential acceleration that stops the trial motion over dt
      if (dt > 0.0)
        trial = vt / dt + at;
      else if (vt != 0.0)
        trial = std::copysign(bound, vt);
      const double f = std::min(bound, std::fabs(trial));
      const double sign = trial > 0.0 ? 1.0 : (trial < 0.0 ? -1.0 : 0.0);
      sa.ax[i] -= sign * f * tx;
      sa.ay[i] -= sign * f * ty;
    }
  }
};

}  // namespace sph::soil::detail
