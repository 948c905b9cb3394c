#pragma once
// The "isph" block of report.json and the run folder's monitors.csv, from the typed result of the isph stage.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sph/engine/run_loop.hpp"

namespace coupling {

// monitors.csv: time_s, then one column per gauge (<name>_m), then front_x_m when asked for.
struct IsphMonitorTable {
  std::vector<std::string> columns;  // without time_s
  std::vector<double> times;  // [s]
  std::vector<std::vector<double>> rows;  // one value per column, per time
};

struct IsphStageResult {
  sph::RunSummary summary;
  std::string pressure_mode;  // "explicit" / "iterative"
  std::string kernel;  // "wendland_c2" / "cubic_spline"
  double particle_spacing = 0, smoothing_length = 0;  // [m]
  std::size_t fluid_particles = 0, wall_particles = 0;
  double fluid_mass_start = 0, fluid_mass_end = 0;  // [kg/m]
  double front_x = 0;  // [m] at the end
  double max_density_error = 0;  // largest max |rho* - rho0|/rho0 over the steps
  IsphMonitorTable monitors;
};

nlohmann::json isph_report(const IsphStageResult& result);
nlohmann::json isph_error_report(const std::string& error);
std::string monitors_csv(const IsphMonitorTable& table);

}  // namespace coupling
