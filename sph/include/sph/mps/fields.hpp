#pragma once
// The WC-MPS state block in the engine's particle set: the arrays it registers by name (seed 2.11, step b-f), and
// a view of raw pointers for the per-particle loops (valid until the next sort or particle addition).
#include "sph/engine/particle_set.hpp"

namespace sph::mps {

struct Fields {
  // state (checkpointed): p^m feeds the predictor's (1 - alpha) grad p^m of the next step (seed eq. 28)
  FieldId pressure;  // [Pa]
  // the positions at which the stepper last listed the candidate neighbours [m]: a resumed run lists the same ones
  // (sph/mps/stepper.hpp, "neighbour lists")
  FieldId x_listed, y_listed;
  // written to frames, recomputed every step
  FieldId number_density;  // n* at the predicted positions [-] (seed eq. 6, 13)
  FieldId smoothed_pressure;  // p' of the yield stress [Pa] (seed eq. 20, A4)
  FieldId viscosity;  // effective viscosity mu_i [Pa s] (seed eq. 16, capped)
  FieldId free_surface;  // 1 where n* <= beta n0 (pressure 0), else 0 (seed eq. 15)
  // two phases (seed 2.10), at r*: the mixture density <rho> = sum rho_j w / sum w over the moving particles, i
  // itself with w = 1 (the EOS prefactor) [kg/m^3], and the grains' volume fraction phi = sum phi0_j w / sum w [-]
  FieldId mixture_density, volume_fraction;

  // Registers the block (or finds it, if already registered) in `set`.
  static Fields register_in(ParticleSet& set);
};

struct Arrays {
  double *pressure, *number_density, *smoothed_pressure, *viscosity, *free_surface, *mixture_density, *volume_fraction;
  Arrays(ParticleSet& set, const Fields& f);
};

}  // namespace sph::mps
