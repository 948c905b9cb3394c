#pragma once
// SoilStep's internals shared by its files: the workspace (Impl), the half-step view and the passes over the
// particles (sph/src/soil/step_passes.cpp: sort, wall extrapolation, per-particle preparation, the pair loop).
#include <cstdint>
#include <vector>

#include "sph/engine/cell_sort.hpp"
#include "sph/soil/soil_step.hpp"

namespace sph::soil {

namespace detail {
// One evaluation of the rates at the particles' current state (sort by cell, walls, pair loop): the combined
// evaluation writes every rate; the Verlet step splits it into the kinematic rates (density, stress, XSPH; with the
// sort) and the forces (acceleration).
using Evaluator = void (*)(SoilStep&, Model&, SoilStep::Impl&);
struct Evaluators {
  Evaluator all = nullptr, kinematics = nullptr, forces = nullptr;
};
}  // namespace detail

namespace detail {
// The pairs found by the Verlet step's kinematic pass, read back by its forces pass (no particle moves between the
// two passes): each soil particle's neighbours j with r_ij and F(r_ij) (grad_i W_ij = F x_ij), in the order of the
// candidate scan, so that the forces' sums are bitwise those of a new scan. Entries go to the buffer of the thread
// that gathered the particle; per soil particle (its position k in `soil`): that buffer, the first entry, the count.
struct PairCache {
  struct alignas(128) Buffer {  // a cache line (pair) of its own: the threads append to theirs concurrently
    std::vector<std::uint32_t> j;
    std::vector<double> r, f;
    void clear() {
      j.clear();
      r.clear();
      f.clear();
    }
  };
  std::vector<Buffer> buffers;
  std::vector<std::uint32_t> thread, first, count;
};
}  // namespace detail

struct SoilStep::Impl {
  CellSortedSet sorted;  // the particles sorted by cell, and the cell list
  // index lists (sorted positions), rebuilt after every sort
  std::vector<std::uint32_t> soil, walls;
  // half-step values: registered in the particle set (not checkpointed), so the sort reorders them
  FieldId vxh, vyh, rhoh, sxxh, syyh, szzh, sxyh;
  FieldId sxx0, syy0, szz0, sxy0;  // the stress at the step's start (the plastic work of the return)
  // per-evaluation scratch (recomputed after every sort)
  std::vector<double> pxx, pyy, pxy, volume, sound, is_soil;  // sigma/rho^2, m/rho, c, 0/1
  std::vector<double> rxx, ryy, rxy;                           // artificial stress R/rho^2 terms
  std::vector<double> xsph_dx, xsph_dy;                        // XSPH velocity corrections
  // the velocity gradient of the kinematic pass (strain rate xx, yy, xy and spin xy): kept only for a stress update
  // in sub-steps (Settings::stress_substeps > 1), empty otherwise
  std::vector<double> lxx, lyy, lexy, lwxy;
  std::vector<double> bxx, bxy, byy;  // corrected kernel gradient: B_i (symmetric)
  std::vector<double> block_a, block_b, block_c;
  detail::Evaluators eval;
  detail::PairCache pairs;  // the Verlet step's pairs, from its kinematic pass to its forces pass
  double w_dx = 1.0;  // kernel value at the particle spacing (artificial stress)
  double gravity_x = 0.0, gravity_y = 0.0;  // gravity of the current evaluation (ramped: at its time), m/s^2
  double load_factor = 0.0;                 // the fraction of the loads acting at that time (as of gravity)
  double step_dt = 0.0;  // the current step's size (the frictional walls' sticking bound); 0 before the first step
  std::vector<double> contact_push, contact_nx, contact_ny;  // frictional walls: per-evaluation scratch
  FieldId wall_push = 0;  // frictional walls: each soil particle's relaxed wall push (register_wall_friction_state)

  // Gravity and loads of an evaluation at simulated time `time` (full, or their ramped fraction).
  void set_gravity(const Settings& st, double time) {
    load_factor = st.gravity_factor(time);
    gravity_x = load_factor * st.gravity_x;
    gravity_y = load_factor * st.gravity_y;
  }
};

namespace detail {

Evaluators select_evaluators(KernelType kernel);

// Rebuilds the soil/wall index lists for the current particle order.
void index_kinds(const ParticleSet& p, SoilStep::Impl& w);

// Raw pointers to the half-step values (registered in the particle set); valid until the next sort.
struct HalfStep {
  double *vxh, *vyh, *rhoh, *sxxh, *syyh, *szzh, *sxyh, *sxx0, *syy0, *szz0, *sxy0;
  HalfStep(ParticleSet& p, const SoilStep::Impl& w)
      : vxh(p.field(w.vxh).data()),
        vyh(p.field(w.vyh).data()),
        rhoh(p.field(w.rhoh).data()),
        sxxh(p.field(w.sxxh).data()),
        syyh(p.field(w.syyh).data()),
        szzh(p.field(w.szzh).data()),
        sxyh(p.field(w.sxyh).data()),
        sxx0(p.field(w.sxx0).data()),
        syy0(p.field(w.syy0).data()),
        szz0(p.field(w.szz0).data()),
        sxy0(p.field(w.sxy0).data()) {}
};

}  // namespace detail
}  // namespace sph::soil
