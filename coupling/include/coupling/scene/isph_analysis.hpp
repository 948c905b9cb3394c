#pragma once
// analyses.isph: the explicit three-step ISPH fluid (sph/fluid, docs/isph.md) on a rectangular tank with water
// blocks, and its monitors (surface gauges, the surge front). Every key, unit and default is in
// docs/scene-format.md; the defaults come from sph::fluid::Settings.
#include <string>
#include <vector>

#include "coupling/scene/json_reader.hpp"
#include "sph/fluid/settings.hpp"

namespace coupling {

struct IsphRectangle {
  double x_min = 0, y_min = 0, x_max = 0, y_max = 0;  // [m]
};

struct IsphTank {
  double x_min = 0, x_max = 0, y_min = 0, height = 0;  // inner faces of the walls [m]
};

struct IsphGauge {
  std::string name;  // the monitors.csv column is <name>_m
  double x = 0;  // [m]
};

struct IsphAnalysis {
  sph::fluid::Settings settings;  // particle_spacing_m, end_time_s, ... (SI)
  IsphTank tank;
  std::vector<IsphRectangle> water;  // water at rest at t = 0, hydrostatic pressure
  std::vector<IsphGauge> gauges;  // free-surface elevation relative to still_water_m at x
  bool front = false;  // the front column front_x_m (the largest x of the water + dx/2)
  double still_water = 0;  // [m] the level the gauges are relative to
  double monitor_interval = 0.01;  // [s] simulated time between rows of monitors.csv
};

// Reads analyses.isph; faults go to the reader's diagnostics with their JSON paths.
IsphAnalysis read_isph_analysis(JsonReader& isph);

}  // namespace coupling
