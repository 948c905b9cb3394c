#pragma once
// The waves an isph run's gauges saw (monitors.csv's <gauge>_m columns, the free-surface elevation relative to the
// still water): each gauge's highest and lowest elevation and its leading crest, and the leading crest's celerity
// between consecutive gauges against the long-wave celerity sqrt(g d) (docs/isph.md section 8).
#include <optional>
#include <string>
#include <vector>

#include "coupling/analyses/monitor_table.hpp"
#include "coupling/scene/tank_scene.hpp"

namespace coupling {

struct GaugeWave {
  std::string name;
  double x = 0;  // [m]
  // The gauge's reading at t = 0: the discretised still surface (the top row's centres plus dx/2), which differs
  // from the scene's still water by up to dx/2 when the depth is not a whole number of spacings. The elevations
  // below are relative to it [m].
  double initial = 0;
  double highest = 0, highest_at = 0, lowest = 0;  // [m], [s], [m]
  // the first local maximum of the elevation (over +-window) that is at least crest_fraction d high [m], [s]
  std::optional<double> crest, crest_at;
};

struct WaveCelerity {
  std::string from, to;
  double speed = 0;  // [m/s] the gauges' distance over the leading crest's travel time
  double ratio = 0;  // speed / sqrt(g d)
};

struct GaugeWaves {
  double depth = 0;  // d: the still water above the tank floor [m]
  double long_wave_celerity = 0;  // sqrt(g d) [m/s]
  std::vector<GaugeWave> gauges;
  std::vector<WaveCelerity> celerity;
};

// A leading crest is at least this fraction of the depth high, and a maximum over this window either side [s].
inline constexpr double crest_fraction = 0.005;
inline constexpr double crest_window_s = 0.1;

GaugeWaves gauge_waves(const MonitorTable& monitors, const TankMonitors& setup, const Tank& tank, double g);

}  // namespace coupling
