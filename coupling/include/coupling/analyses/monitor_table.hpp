#pragma once
// monitors.csv of the particle-flow analyses (isph, mps): one row per sampled time.
#include <string>
#include <utility>
#include <vector>

namespace coupling {

// time_s, then one column per gauge (<name>_m), then front_x_m and wall_height_m when asked for.
struct MonitorTable {
  std::vector<std::string> columns;  // without time_s
  std::vector<double> times;  // [s]
  std::vector<std::vector<double>> rows;  // one value per column, per time
};

std::string monitors_csv(const MonitorTable& table);
// The table of a monitors.csv text: the columns of its header (without time_s) and its rows up to the first that
// does not have one number per column (an empty table when the text has no "time_s" header).
MonitorTable parse_monitors_csv(const std::string& csv);
// On --resume: the rows of `csv` (an earlier run's file) up to `time` [s] replace `table`, when the file has the
// table's columns and such rows; returns whether they did.
bool restore_rows(MonitorTable& table, const std::string& csv, double time);
// The values of one column [time, value] (empty when the table has no such column).
std::vector<std::pair<double, double>> monitor_column(const MonitorTable& table, const std::string& column);

}  // namespace coupling
