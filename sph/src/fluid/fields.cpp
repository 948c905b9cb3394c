#include "sph/fluid/fields.hpp"

namespace sph::fluid {

Fields Fields::register_in(ParticleSet& set) {
  Fields f;
  f.pressure = set.add_field({"pressure", true, true});
  f.provisional_density = set.add_field({"provisional_density", false, true});
  f.kernel_density = set.add_field({"kernel_density", false, true});
  f.free_surface = set.add_field({"free_surface", false, true});
  f.body_travel = set.add_field({"body_travel", true, false});
  f.body_speed = set.add_field({"body_speed", true, false});
  f.body_acceleration = set.add_field({"body_acceleration", true, false});
  f.x_start = set.add_field({"step_start_x", false, false});
  f.y_start = set.add_field({"step_start_y", false, false});
  f.vx_start = set.add_field({"step_start_vx", false, false});
  f.vy_start = set.add_field({"step_start_vy", false, false});
  return f;
}

Arrays::Arrays(ParticleSet& s, const Fields& f)
    : pressure(s.field(f.pressure).data()),
      provisional_density(s.field(f.provisional_density).data()),
      kernel_density(s.field(f.kernel_density).data()),
      free_surface(s.field(f.free_surface).data()),
      x_start(s.field(f.x_start).data()),
      y_start(s.field(f.y_start).data()),
      vx_start(s.field(f.vx_start).data()),
      vy_start(s.field(f.vy_start).data()) {}

ConstArrays::ConstArrays(const ParticleSet& s, const Fields& f)
    : pressure(s.field(f.pressure).data()),
      provisional_density(s.field(f.provisional_density).data()),
      kernel_density(s.field(f.kernel_density).data()),
      free_surface(s.field(f.free_surface).data()) {}

}  // namespace sph::fluid
