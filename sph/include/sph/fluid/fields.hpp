#pragma once
// The ISPH fluid's state block in the engine's particle set: the arrays it registers by name, and a view of raw
// pointers for the per-particle loops (valid until the next sort or particle addition).
#include "sph/engine/particle_set.hpp"

namespace sph::fluid {

struct Fields {
  // state (checkpointed): the pressure of the last step starts the next solve (the explicit mode's Jacobi sweep
  // reads it, the iterative mode uses it as its first guess)
  FieldId pressure;  // [Pa]
  // written to frames, recomputed every step
  FieldId provisional_density;  // rho* from continuity based on rho0 (seed eq. 32) [kg/m^3]
  FieldId kernel_density;  // sum_j m_j W_ij, the free-surface indicator [kg/m^3]
  FieldId free_surface;  // 1 where kernel_density < beta rho0 (pressure 0), else 0
  // state of the rigid bodies (checkpointed), held by each particle of a body (0 elsewhere): its travel along the
  // body's direction [m], speed [m/s] and acceleration [m/s^2] (the wall-pressure extrapolation reads it)
  FieldId body_travel, body_speed, body_acceleration;
  // step workspace (not checkpointed): the state at the start of the step, carried across the mid-step sort
  FieldId x_start, y_start, vx_start, vy_start;

  // Registers the block (or finds it, if already registered) in `set`.
  static Fields register_in(ParticleSet& set);
};

struct Arrays {
  double *pressure, *provisional_density, *kernel_density, *free_surface;
  double *x_start, *y_start, *vx_start, *vy_start;
  Arrays(ParticleSet& set, const Fields& f);
};

struct ConstArrays {
  const double *pressure, *provisional_density, *kernel_density, *free_surface;
  ConstArrays(const ParticleSet& set, const Fields& f);
};

}  // namespace sph::fluid
