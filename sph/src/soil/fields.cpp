#include "sph/soil/fields.hpp"

namespace sph::soil {

SoilFields SoilFields::register_in(ParticleSet& set) {
  auto state = [&](const char* name, bool vtu) { return set.add_field({name, true, vtu}); };
  SoilFields f;
  f.sxx = state("stress_xx", true);
  f.syy = state("stress_yy", true);
  f.szz = state("stress_zz", true);
  f.sxy = state("stress_xy", true);
  f.plastic_strain = state("plastic_strain", true);
  f.plastic_work = state("plastic_work_J_kg", false);
  f.wall_nx = state("wall_normal_x", false);
  f.wall_ny = state("wall_normal_y", false);
  f.ax = state("rate_ax", false);
  f.ay = state("rate_ay", false);
  f.drho = state("rate_density", false);
  f.dsxx = state("rate_stress_xx", false);
  f.dsyy = state("rate_stress_yy", false);
  f.dszz = state("rate_stress_zz", false);
  f.dsxy = state("rate_stress_xy", false);
  f.dplastic_strain = state("rate_plastic_strain", false);
  f.dplastic_work = state("rate_plastic_work", false);
  return f;
}

FieldId register_wall_friction_state(ParticleSet& set) { return set.add_field({"wall_friction_push", true, false}); }

SoilArrays::SoilArrays(ParticleSet& s, const SoilFields& f)
    : sxx(s.field(f.sxx).data()),
      syy(s.field(f.syy).data()),
      szz(s.field(f.szz).data()),
      sxy(s.field(f.sxy).data()),
      plastic_strain(s.field(f.plastic_strain).data()),
      plastic_work(s.field(f.plastic_work).data()),
      wall_nx(s.field(f.wall_nx).data()),
      wall_ny(s.field(f.wall_ny).data()),
      ax(s.field(f.ax).data()),
      ay(s.field(f.ay).data()),
      drho(s.field(f.drho).data()),
      dsxx(s.field(f.dsxx).data()),
      dsyy(s.field(f.dsyy).data()),
      dszz(s.field(f.dszz).data()),
      dsxy(s.field(f.dsxy).data()),
      dplastic_strain(s.field(f.dplastic_strain).data()),
      dplastic_work(s.field(f.dplastic_work).data()) {}

// Read only: the pointers of the writable view, which only reads the set's array addresses.
ConstSoilArrays::ConstSoilArrays(const ParticleSet& s, const SoilFields& f)
    : ConstSoilArrays(SoilArrays(const_cast<ParticleSet&>(s), f)) {}

}  // namespace sph::soil
