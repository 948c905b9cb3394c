#pragma once
// The soil model's state block: the per-particle arrays it registers in the engine's particle set, and a view
// of raw pointers into them for the per-particle loops. Stress is the Cauchy stress, tension positive: the total
// stress of a dry model, the effective stress when the model has pore water (sph/soil/loads.hpp);
// sigma_zz is the out-of-plane normal stress (plane strain).
#include "sph/engine/particle_set.hpp"

namespace sph::soil {

struct SoilFields {
  FieldId sxx, syy, szz, sxy;           // stress [Pa]; walls: extrapolated from the soil
  FieldId plastic_strain;               // accumulated equivalent plastic strain [-]
  FieldId plastic_work;                 // accumulated plastic work per unit mass [J/kg]
  FieldId wall_nx, wall_ny;             // unit normal of a wall particle pointing into the domain (0 for soil)
  // rates at the current state (the integrator carries them from one step to the next; checkpointed)
  FieldId ax, ay, drho, dsxx, dsyy, dszz, dsxy, dplastic_strain, dplastic_work;

  // Registers the block (or finds it, if already registered) in `set`.
  static SoilFields register_in(ParticleSet& set);
};

// The frictional walls' state (WallSlip::frictional): each soil particle's wall push relaxed in time [m/s^2]
// (sph/src/soil/wall_friction.hpp), checkpointed. SoilStep and read_checkpoint register it when the walls
// are frictional; other models do not carry it. Returns its id (the same on a second call).
FieldId register_wall_friction_state(ParticleSet& set);

// Raw pointers into the soil arrays of one particle set; valid until particles are added.
struct SoilArrays {
  double *sxx, *syy, *szz, *sxy, *plastic_strain, *plastic_work, *wall_nx, *wall_ny;
  double *ax, *ay, *drho, *dsxx, *dsyy, *dszz, *dsxy, *dplastic_strain, *dplastic_work;

  SoilArrays(ParticleSet& set, const SoilFields& f);
};

// Read-only view for code outside the model (reports, figures).
struct ConstSoilArrays {
  const double *sxx, *syy, *szz, *sxy, *plastic_strain, *plastic_work, *wall_nx, *wall_ny;

  ConstSoilArrays(const ParticleSet& set, const SoilFields& f);
  ConstSoilArrays(const SoilArrays& a)  // NOLINT: a read-only view of a writable one
      : sxx(a.sxx), syy(a.syy), szz(a.szz), sxy(a.sxy), plastic_strain(a.plastic_strain),
        plastic_work(a.plastic_work), wall_nx(a.wall_nx), wall_ny(a.wall_ny) {}
};

}  // namespace sph::soil
