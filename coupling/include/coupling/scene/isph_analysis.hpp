#pragma once
// analyses.isph: the explicit three-step ISPH fluid (sph/fluid, docs/isph.md) on a rectangular tank with water
// blocks, and its monitors (surface gauges, the surge front). Every key, unit and default is in
// docs/scene-format.md; the defaults come from sph::fluid::Settings.
#include <vector>

#include "coupling/scene/isph_outputs.hpp"
#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/tank_scene.hpp"
#include "sph/fluid/settings.hpp"

namespace coupling {

struct IsphAnalysis {
  sph::fluid::Settings settings;  // particle_spacing_m, end_time_s, ... (SI)
  Tank tank;
  std::vector<TankRectangle> water;  // water at rest at t = 0, hydrostatic pressure
  TankMonitors monitors;  // gauges and the front (no wall height)
  IsphOutputs outputs;  // snapshots_s, front_reference (read by scene.cpp through isph_outputs.hpp)
};

// Reads analyses.isph; faults go to the reader's diagnostics with their JSON paths.
IsphAnalysis read_isph_analysis(JsonReader& isph);

}  // namespace coupling
