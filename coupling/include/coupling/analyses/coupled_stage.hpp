#pragma once
// What the coupled stage found (analyses.coupled: the soil of analyses.sph and the water of analyses.isph in one
// run, docs/coupled.md): its typed result, which coupling/output/coupled_report writes as the "coupled" block of
// report.json, with monitors.csv and the gauges' figure.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "coupling/analyses/coupled_impact.hpp"
#include "coupling/analyses/monitor_table.hpp"
#include "sph/engine/run_loop.hpp"

namespace coupling {

struct CoupledStageResult {
  sph::RunSummary summary;  // the run loop's, on the water's clock
  double particle_spacing = 0;  // [m]
  std::size_t soil_particles = 0, soil_wall_particles = 0, water_particles = 0;
  double soil_mass_start = 0, soil_mass_end = 0;  // [kg/m]
  double water_volume_start = 0, water_volume_end = 0;  // [m^2] (per metre): fluid mass / rho0
  std::size_t water_removed = 0;  // water particles that left the domain
  // over the steps since the run (or its resumption) started: the soil's sub-steps per water step, the pressure
  // solver's iterations per water step
  int most_substeps = 0;
  double mean_substeps = 0;
  int most_solver_iterations = 0;
  double mean_solver_iterations = 0;
  double soil_steps = 0;  // soil sub-steps taken since the run (or its resumption) started
  // at the end: water particles closer than dx/2 to a soil particle's centre (inside the soil), the soil's largest
  // displacement [m] and plastic strain, the water's largest speed [m/s]
  std::size_t water_inside_soil = 0;
  double soil_max_displacement = 0, soil_max_plastic_strain = 0, water_max_speed = 0;
  double soil_seconds = 0, water_seconds = 0;  // wall time in each physics' steps (the water's with the exchange)
  // each phase's particles x its steps over its own wall time
  double soil_particle_steps_per_second = 0, water_particle_steps_per_second = 0;
  MonitorTable monitors;  // the water's gauges (monitors.csv)
  MonitorTable slide;  // the soil's centroid and its speed (slide.csv), on the monitors' times
  std::optional<CoupledImpact> impact;  // with analyses.coupled.impact
  std::vector<std::string> warnings;  // each naming its scene key
  std::vector<std::string> figures;  // relative to the run folder
};

}  // namespace coupling
