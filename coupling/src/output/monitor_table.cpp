// monitors.csv (coupling/output/monitor_table.hpp).
#include "coupling/output/monitor_table.hpp"

#include <cstdio>

namespace coupling {

std::string monitors_csv(const MonitorTable& table) {
  std::string out = "time_s";
  for (const std::string& c : table.columns) out += "," + c;
  out += "\n";
  char cell[40];
  for (std::size_t k = 0; k < table.times.size(); ++k) {
    std::snprintf(cell, sizeof cell, "%.6g", table.times[k]);
    out += cell;
    for (double v : table.rows[k]) {
      std::snprintf(cell, sizeof cell, ",%.6g", v);
      out += cell;
    }
    out += "\n";
  }
  return out;
}

}  // namespace coupling
