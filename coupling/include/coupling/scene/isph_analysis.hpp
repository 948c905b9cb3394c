#pragma once
// analyses.isph: the explicit three-step ISPH fluid (sph/fluid, docs/isph.md) on a rectangular tank with water
// blocks, solid walls and rigid bodies inside it, and its monitors (surface gauges, the surge front). Every key,
// unit and default is in docs/scene-format.md; the defaults come from sph::fluid::Settings.
#include <string>
#include <vector>

#include "coupling/scene/isph_outputs.hpp"
#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/tank_scene.hpp"
#include "sph/engine/fill.hpp"
#include "sph/fluid/model.hpp"
#include "sph/fluid/settings.hpp"

namespace coupling {

// A fixed solid inside the tank (a slope, a beach, an obstacle): wall particles in rows along its faces.
struct IsphSolid {
  std::string name;
  std::vector<sph::Point> polygon;  // [m]
};

// A rigid body: its polygon, filled with wall particles, moving as `body` says.
struct IsphBody {
  std::string name;
  std::vector<sph::Point> polygon;  // [m]
  sph::fluid::RigidBody body;
};

struct IsphAnalysis {
  sph::fluid::Settings settings;  // particle_spacing_m, end_time_s, ... (SI); gravity tilted by bed_slope
  double bed_slope = 0;  // the tank floor falls by this per unit length in +x (gravity tilted by atan of it)
  Tank tank;
  std::vector<IsphSolid> solids;  // built before the water, which fills around them
  std::vector<IsphBody> bodies;
  std::vector<TankRectangle> water;  // water at rest at t = 0, hydrostatic pressure
  TankMonitors monitors;  // gauges and the front (no wall height)
  IsphOutputs outputs;  // snapshots_s, front_reference (read by scene.cpp through isph_outputs.hpp)
};

// Reads analyses.isph; faults go to the reader's diagnostics with their JSON paths.
IsphAnalysis read_isph_analysis(JsonReader& isph);

// analyses.isph at another particle spacing (sphslope study): the spacing, the domain beyond which water is removed
// (the walls' outer faces, wall layers x spacing) and the settings' own check, as the reader does them.
void apply_isph_spacing(IsphAnalysis& analysis, double spacing, Diagnostics& diagnostics);

// analyses.isph's bed_slope_percent (gravity tilted), solids and bodies, inside the tank read before.
void read_isph_geometry(JsonReader& isph, IsphAnalysis& analysis);

}  // namespace coupling
