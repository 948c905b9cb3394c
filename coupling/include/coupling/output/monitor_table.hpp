#pragma once
// monitors.csv of the particle-flow analyses (isph, mps): one row per sampled time.
#include <string>
#include <vector>

namespace coupling {

// time_s, then one column per gauge (<name>_m), then front_x_m and wall_height_m when asked for.
struct MonitorTable {
  std::vector<std::string> columns;  // without time_s
  std::vector<double> times;  // [s]
  std::vector<std::vector<double>> rows;  // one value per column, per time
};

std::string monitors_csv(const MonitorTable& table);

}  // namespace coupling
