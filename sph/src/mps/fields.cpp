#include "sph/mps/fields.hpp"

namespace sph::mps {

Fields Fields::register_in(ParticleSet& set) {
  Fields f;
  f.pressure = set.add_field({"pressure", true, true});
  f.x_listed = set.add_field({"mps_x_listed", true, false});
  f.y_listed = set.add_field({"mps_y_listed", true, false});
  f.number_density = set.add_field({"number_density", false, true});
  f.smoothed_pressure = set.add_field({"smoothed_pressure", false, true});
  f.viscosity = set.add_field({"viscosity", false, true});
  f.free_surface = set.add_field({"free_surface", false, true});
  f.mixture_density = set.add_field({"mixture_density", false, true});
  f.volume_fraction = set.add_field({"volume_fraction", false, true});
  return f;
}

Arrays::Arrays(ParticleSet& s, const Fields& f)
    : pressure(s.field(f.pressure).data()),
      number_density(s.field(f.number_density).data()),
      smoothed_pressure(s.field(f.smoothed_pressure).data()),
      viscosity(s.field(f.viscosity).data()),
      free_surface(s.field(f.free_surface).data()),
      mixture_density(s.field(f.mixture_density).data()),
      volume_fraction(s.field(f.volume_fraction).data()) {}

}  // namespace sph::mps
