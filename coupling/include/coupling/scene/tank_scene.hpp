#pragma once
// What the particle-flow analyses in a tank share in a scene file (analyses.isph, analyses.mps): the rectangular
// tank of fixed wall particles, rectangles of material filled on the lattice, and the monitors written to
// monitors.csv. Every key, unit and default is in docs/scene-format.md.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "coupling/scene/json_reader.hpp"

namespace coupling {

struct TankRectangle {
  double x_min = 0, y_min = 0, x_max = 0, y_max = 0;  // [m]
};

struct Tank {
  double x_min = 0, x_max = 0, y_min = 0, height = 0;  // inner faces of the walls [m]
};

struct Gauge {
  std::string name;  // the monitors.csv column is <name>_m
  double x = 0;  // [m]
};

struct TankMonitors {
  std::vector<Gauge> gauges;  // free-surface elevation relative to still_water at x
  bool front = false;  // the column front_x_m: the largest x of the moving material + dx/2
  bool wall_height = false;  // the column wall_height_m: the top of the material at the tank's left wall
  double still_water = 0;  // [m] the level the gauges are relative to
  double interval = 0.01;  // [s] simulated time between rows of monitors.csv
};

// parent.tank: {x_min_m (default 0), x_max_m, y_min_m (default 0), height_m}.
void read_tank(JsonReader& parent, Tank& tank);

// parent.<key>: 1 to 100 rectangles {x_min_m, y_min_m, x_max_m, y_max_m} inside the tank. For each good rectangle,
// `extra` (when given) reads the further keys of its object before the object is finished.
void read_tank_rectangles(JsonReader& parent, const char* key, const Tank& tank, std::vector<TankRectangle>& out,
                          const std::function<void(JsonReader&)>& extra = {});

// parent.<key>: an array of 1 to limit.max times [s], each > 0 and at most end_time when it is given, increasing
// (analyses.mps.profiles.times_s, analyses.isph.snapshots_s). Appends the good ones to `out`.
void read_times(JsonReader& parent, const char* key, Need need, std::optional<double> end_time,
                const SizeLimit& limit, std::vector<double>& out);

// parent.monitors: {gauges: [{name, x_m}], front, wall_height (only when allow_wall_height), still_water_m,
// interval_s}.
void read_tank_monitors(JsonReader& parent, TankMonitors& monitors, bool allow_wall_height);

}  // namespace coupling
