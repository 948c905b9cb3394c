#pragma once
// An ISPH fluid model: the particle set (fluid particles of kind 0, fixed wall particles of kind 1), its run state,
// the settings and the fluid's registered state block; and the builders that fill it.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "sph/engine/fill.hpp"
#include "sph/engine/particle_set.hpp"
#include "sph/engine/stepper.hpp"
#include "sph/fluid/fields.hpp"
#include "sph/fluid/settings.hpp"

namespace sph::fluid {

// A rigid body made of wall particles (kind wall, material = its index in Model::bodies + 1; the fixed walls have
// material 0) that translates along a straight line, e.g. a block sliding down an incline. Its particles take part
// in the fluid's equations as walls that move: their velocity in the viscous and continuity sums, their pressure
// extrapolated from the fluid with the body's acceleration (docs/isph.md D17-D19).
struct RigidBody {
  enum class Motion {
    table,     // travel s(t) from a table, linear between its points, constant after the last
    ln_cosh,   // s(t) = (u_t^2 / a0) ln cosh(a0 t / u_t): from rest at a0, tending to the terminal speed u_t
    free,      // gravity and the integrated fluid pressure force along the direction (frictionless)
  };
  Motion motion = Motion::free;
  double direction_x = 1.0, direction_y = 0.0;  // unit vector of travel
  double density = 2000.0;  // [kg/m^3] (the free motion's mass: density x area)
  double area = 0.0;  // [m^2] the polygon's (set by add_rigid_body)
  double centroid_x = 0.0, centroid_y = 0.0;  // [m] the polygon's at zero travel (set by add_rigid_body)
  double stop_travel = std::numeric_limits<double>::infinity();  // [m] it stops for good at this travel
  double start_time = 0.0;  // [s] at rest before
  std::vector<double> table_time, table_travel;  // [s], [m] (Motion::table)
  double initial_acceleration = 0.0, terminal_speed = 0.0;  // [m/s^2], [m/s] (Motion::ln_cosh)

  double mass() const { return density * area; }  // [kg/m]
  // The prescribed travel and speed at time t (table and ln_cosh; stop_travel not applied) [m], [m/s].
  void prescribed(double t, double& travel, double& speed) const;
};
// The motion laws' names in scene files (bodies[i].motion.law).
inline constexpr sphslope::NameTable<RigidBody::Motion, 3> motion_law_names{{{"free", RigidBody::Motion::free},
                                                                            {"ln_cosh", RigidBody::Motion::ln_cosh},
                                                                            {"table", RigidBody::Motion::table}}};

// Wall particles of another physics in a coupled run (the soil's, sph/coupled/exchange.hpp): kind wall with this
// material. The fluid treats them as walls whose positions and velocities the coupling sets before each step; it
// keeps those through the step (its fixed walls it sets at rest, its bodies' particles it moves itself).
inline constexpr std::uint16_t coupled_wall_material = 0xffff;
// Their acceleration [m/s^2], which the coupling sets with their positions and velocities (fields of the fluid's
// set; absent: at rest): the wall pressure's Neumann condition dP/dn = rho (g - a).n, as a rigid body's (D18).
inline constexpr const char* coupled_wall_acceleration_x = "coupled_wall_ax";
inline constexpr const char* coupled_wall_acceleration_y = "coupled_wall_ay";

struct Model {
  explicit Model(const Settings& s);
  Settings settings;
  ParticleSet particles;
  RunState state;
  Fields fields;
  std::vector<RigidBody> bodies;
  // the polygons of the solids (walls and bodies, as built), which fluid blocks leave empty
  std::vector<std::vector<Point>> solids;
  std::size_t fluid_particles_built = 0;  // before any left the domain
  double fluid_mass_built = 0.0;  // [kg/m]

  Arrays arrays() { return Arrays(particles, fields); }
  ConstArrays arrays() const { return ConstArrays(particles, fields); }
};

// Fluid particles on the lattice (cell-centred, anchor at the origin) inside [x_min, x_max] x [y_min, y_max], at
// rest, mass rho0 dx^2, except inside the solids built before or closer than dx/2 to their faces. Returns the count.
std::size_t add_fluid_block(Model& model, double x_min, double y_min, double x_max, double y_max);

// Fixed wall particles inside a polygon (a slope, a beach, an obstacle), in settings.wall_layers rows parallel to
// its edges (smooth on slanted faces). Returns the count.
std::size_t add_solid_wall(Model& model, const std::vector<Point>& polygon);

// A rigid body: its particles fill the polygon in rows parallel to its edges, at rest. Returns the count.
std::size_t add_rigid_body(Model& model, const std::vector<Point>& polygon, RigidBody body);

// Fixed wall particles around a box (settings.wall_layers rows, at least ceil(2h/dx)). Returns the count.
std::size_t add_tank_walls(Model& model, double x_min, double x_max, double y_min, double height);

// P = rho0 |g| (surface_y - y) for every fluid and wall particle below surface_y (0 above): a hydrostatic start.
void set_hydrostatic_pressure(Model& model, double surface_y);

}  // namespace sph::fluid
