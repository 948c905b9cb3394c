// monitors.csv (coupling/analyses/monitor_table.hpp).
#include "coupling/analyses/monitor_table.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>

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

MonitorTable parse_monitors_csv(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, cell;
  MonitorTable table;
  if (!std::getline(in, line) || line.rfind("time_s", 0) != 0) return table;
  std::istringstream header(line);
  std::getline(header, cell, ',');
  while (std::getline(header, cell, ',')) table.columns.push_back(cell);
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::vector<double> values;
    while (std::getline(cells, cell, ',')) values.push_back(std::strtod(cell.c_str(), nullptr));
    if (values.size() != table.columns.size() + 1) break;
    table.times.push_back(values[0]);
    table.rows.emplace_back(values.begin() + 1, values.end());
  }
  return table;
}

bool restore_rows(MonitorTable& table, const std::string& csv, double time) {
  MonitorTable restored = parse_monitors_csv(csv);
  if (restored.columns != table.columns) return false;
  std::size_t kept = 0;
  while (kept < restored.times.size() && restored.times[kept] <= time + 1e-12) ++kept;
  if (kept == 0) return false;
  restored.times.resize(kept);
  restored.rows.resize(kept);
  table = std::move(restored);
  return true;
}

std::vector<std::pair<double, double>> monitor_column(const MonitorTable& table, const std::string& column) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    if (table.columns[c] == column)
      for (std::size_t k = 0; k < table.times.size(); ++k) out.emplace_back(table.times[k], table.rows[k][c]);
  return out;
}

}  // namespace coupling
