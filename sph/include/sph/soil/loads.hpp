#pragma once
// The loads on the soil besides its weight (docs/sph.md, "Loads"), the same as limit equilibrium carries:
//  - pore water below a piezometric line fixed in space: u = gamma_w (line height - y) below the line, 0 above (no
//    suction), as in limit equilibrium. The soil's stress is then the effective stress (yield on it); the momentum
//    balance of the total stress, div(sigma' - u I) + rho g, is computed as div(sigma') + rho g - grad u with the
//    gradient of the known field u in closed form. Ponded water is the same field above the ground: the effective
//    traction at a submerged surface is zero, which the SPH free surface already gives.
//  - a horizontal pseudo-static body force kh |g| per unit mass (seismic coefficient kh, signed: + toward +x) and a
//    vertical one kv |g| (+ upward);
//  - surface forces on chosen particles (strip surcharges and line loads on the topmost particles of a lattice
//    column).
// All loads scale with the gravity factor of the run (ramped gravity ramps them too).
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "sph/engine/particle_set.hpp"

namespace sph::soil {

struct PiezometricLine {
  std::vector<double> x, y;     // m, vertices, x strictly increasing; the line is level beyond its ends
  double unit_weight = 9810.0;  // N/m^3, unit weight of water gamma_w

  double height(double px) const;  // m, the line's height at px
  // Pore pressure at (px, py), Pa: gamma_w (height(px) - py) below the line, 0 on and above it.
  double pressure(double px, double py) const;
  // Its gradient, Pa/m: gamma_w (dy_line/dx, -1) below the line, 0 above.
  void gradient(double px, double py, double& gx, double& gy) const;
  // Empty when usable; otherwise what is wrong (fewer than 2 vertices, x not increasing, gamma_w not > 0, ...).
  std::string error() const;
};

struct SoilLoads {
  std::optional<PiezometricLine> water;
  double seismic_coefficient = 0.0;  // kh, signed: the body force kh |g| acts toward +x when positive
  double vertical_seismic_coefficient = 0.0;  // kv, signed: the body force kv |g| acts upward when positive
  // Registered per-particle fields holding each particle's surface force, N/m (absent: no surface forces).
  std::optional<FieldId> surface_force_x, surface_force_y;

  bool any() const {
    return water || seismic_coefficient != 0.0 || vertical_seismic_coefficient != 0.0 || surface_force_x;
  }
};

// A vertical strip pressure `pressure` (Pa, acting downward) on the ground between from_x and to_x (m): each lattice
// column (width dx, centred on its soil particles' x) takes the pressure times its overlap with the strip, as a
// force shared by its three topmost soil particles in the proportions 1/4, 1/2, 1/4. (On the top particle alone, or
// shared equally by two, it excites the odd-even mode of the SPH operators: sigma_yy alternated from row to row by
// about +-5 % of the closed form below a loaded column top; with 1/4, 1/2, 1/4 the rows lie within 2 %,
// tests/sph/test_loads.cpp.) Registers the surface-force fields in `particles` on first use and records
// them in `loads`. Returns the number of particles loaded. The force stays with those particles as they move.
// pressure_end (Pa): the pressure at to_x of a trapezoidal strip, linear from `pressure` at from_x (NaN: uniform).
std::size_t add_strip_load(ParticleSet& particles, SoilLoads& loads, double from_x, double to_x, double pressure,
                           double dx, double pressure_end = std::nan(""));

// A line load (N/m, force_x toward +x, force_y upward) on the ground at x: on the lattice column holding x and its two
// neighbours (1/4, 1/2, 1/4), each share spread over the column's three topmost soil particles as a strip's.
// Returns the number of particles loaded.
std::size_t add_line_load(ParticleSet& particles, SoilLoads& loads, double x, double force_x, double force_y,
                          double dx);

}  // namespace sph::soil
