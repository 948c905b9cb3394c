#pragma once
// The reference cases of the ISPH fluid, built from settings (the spacing and the numerics come from them):
// a still water tank and the Martin & Moyce (1952) dam break. Shared by the tests and the benchmark program.
#include "sph/fluid/model.hpp"

namespace sph::fluid {

// Water at rest, [0, width] x [0, depth], in a tank of walls up to 1.5 depth; hydrostatic initial pressure.
Model make_still_tank(const Settings& settings, double width, double depth);

// A column [0, a] x [0, n2 a] against the left wall of a tank [0, tank_length], walls up to 1.5 n2 a, released at
// t = 0 with a hydrostatic pressure (Martin & Moyce 1952: a = 2.25 in, n^2 = 2).
Model make_dam_break(const Settings& settings, double a, double n2, double tank_length);

// The surge front: the largest x of a fluid particle plus dx/2 (the edge of its lattice cell) [m].
double front_position(const Model& model);

}  // namespace sph::fluid
