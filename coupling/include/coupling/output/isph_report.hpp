#pragma once
// The "isph" block of report.json and the run folder's monitors.csv, from the typed result of the isph stage.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/output/monitor_table.hpp"
#include "sph/engine/run_loop.hpp"

namespace coupling {

struct IsphStageResult {
  sph::RunSummary summary;
  std::string pressure_mode;  // "explicit" / "iterative"
  std::string kernel;  // "wendland_c2" / "cubic_spline"
  double particle_spacing = 0, smoothing_length = 0;  // [m]
  std::size_t fluid_particles = 0, wall_particles = 0;
  double fluid_mass_start = 0, fluid_mass_end = 0;  // [kg/m]
  double front_x = 0;  // [m] at the end
  double max_density_error = 0;  // largest max |rho* - rho0|/rho0 over the steps
  MonitorTable monitors;
};

nlohmann::json isph_report(const IsphStageResult& result);
nlohmann::json isph_error_report(const std::string& error);

}  // namespace coupling
