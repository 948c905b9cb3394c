#pragma once
// What the isph stage found (analyses.isph, docs/isph.md): its typed result, which coupling/output/isph_report
// writes as the "isph" block of report.json, monitors.csv and the isph figures.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "coupling/analyses/isph_bodies.hpp"
#include "coupling/analyses/isph_front.hpp"
#include "coupling/analyses/isph_measures.hpp"
#include "coupling/analyses/isph_waves.hpp"
#include "coupling/analyses/monitor_table.hpp"
#include "coupling/scene/isph_analysis.hpp"
#include "sph/engine/run_loop.hpp"
#include "sph/fluid/model.hpp"

namespace coupling {

struct IsphStageResult {
  sph::RunSummary summary;
  std::string pressure_mode;  // "explicit" / "iterative"
  std::string kernel;  // its name (sph::kernel_names)
  double particle_spacing = 0, smoothing_length = 0;  // [m]
  std::size_t fluid_particles = 0, wall_particles = 0;
  double fluid_mass_start = 0, fluid_mass_end = 0;  // [kg/m]
  double front_x = 0;  // [m] at the end
  // over the steps (a resumed run: from t = 0): the largest max |rho* - rho0|/rho0 and the largest of its mean over
  // the fluid, and the largest time step taken [s]
  double max_density_error = 0, mean_density_error = 0, largest_time_step = 0;
  std::size_t wall_contacts = 0;  // fluid particle-steps put back at the wall clearance (docs/isph.md D23)
  // fluid particles past the walls' first row: at the end, the most at any step and the first time there was one
  std::size_t past_walls_end = 0, past_walls_most = 0;
  std::optional<double> past_walls_first_time;
  std::optional<StillTankCheck> still_tank;  // a still tank: against hydrostatics
  std::optional<FrontErrors> front_errors;  // front_reference with Martin & Moyce's table
  std::optional<RitterComparison> ritter;  // front_reference with Ritter's dam
  std::optional<GaugeWaves> waves;  // a run with rigid bodies and gauges: the waves they made
  std::vector<std::string> warnings;  // each naming its scene key
  std::vector<std::string> figures;  // relative to the run folder
  MonitorTable monitors;
  std::size_t fluid_removed = 0;  // fluid particles that left the domain (removed)
  double fluid_mass_removed = 0;  // [kg/m]
  std::vector<BodyRecord> bodies;  // the rigid bodies (none: no "bodies" block)
  double fluid_energy_start = 0, fluid_energy_end = 0;  // [J/m] kinetic + potential of the fluid
};

// The fluid model of analyses.isph: its solids and bodies, the water at rest in its rectangles with a hydrostatic
// pressure (zero at the top row's centres, docs/isph.md D6), and the tank. The water leaves empty the solids, the
// bodies and the `displacing` polygons (a coupled run's soil bodies), and dx/2 around their faces.
sph::fluid::Model build_isph_model(const IsphAnalysis& a, const std::vector<std::vector<sph::Point>>& displacing = {});

}  // namespace coupling
