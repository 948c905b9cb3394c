#pragma once
// An ISPH fluid model: the particle set (fluid particles of kind 0, fixed wall particles of kind 1), its run state,
// the settings and the fluid's registered state block; and the builders that fill it.
#include <cstddef>

#include "sph/engine/fill.hpp"
#include "sph/engine/particle_set.hpp"
#include "sph/engine/stepper.hpp"
#include "sph/fluid/fields.hpp"
#include "sph/fluid/settings.hpp"

namespace sph::fluid {

struct Model {
  explicit Model(const Settings& s);
  Settings settings;
  ParticleSet particles;
  RunState state;
  Fields fields;

  Arrays arrays() { return Arrays(particles, fields); }
  ConstArrays arrays() const { return ConstArrays(particles, fields); }
};

// Fluid particles on the lattice (cell-centred, anchor at the origin) inside [x_min, x_max] x [y_min, y_max], at
// rest, mass rho0 dx^2. Returns the count.
std::size_t add_fluid_block(Model& model, double x_min, double y_min, double x_max, double y_max);

// Fixed wall particles around a box (settings.wall_layers rows, at least ceil(2h/dx)). Returns the count.
std::size_t add_tank_walls(Model& model, double x_min, double x_max, double y_min, double height);

// P = rho0 |g| (surface_y - y) for every fluid and wall particle below surface_y (0 above): a hydrostatic start.
void set_hydrostatic_pressure(Model& model, double surface_y);

}  // namespace sph::fluid
