#pragma once
// What the mps stage found (analyses.mps, docs/mps.md): its typed result, which coupling/output/mps_report writes as
// the "mps" block of report.json, monitors.csv, profiles.csv and the profile figures.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "coupling/analyses/monitor_table.hpp"
#include "coupling/analyses/mps_profiles.hpp"
#include "sph/engine/run_loop.hpp"

namespace coupling {

struct MpsStageResult {
  sph::RunSummary summary;
  std::string regularisation, interaction_viscosity, effective_pressure, stress_divergence;  // the settings' keys
  double particle_spacing = 0, effective_radius = 0;  // dx, r_e [m]
  double sound_speed = 0, viscosity_cap = 0;  // c0 [m/s], mu_cap [Pa s]
  bool gate = false;  // analyses.mps.gate given: its face [m], lifting speed [m/s] and travel [m]
  double gate_x = 0, gate_lift_speed = 0, gate_lift_distance = 0;
  std::size_t moving_particles = 0, wall_particles = 0;
  double mass_start = 0, mass_end = 0;  // [kg/m] of the moving particles
  // The deposit: its front (the farthest particle still within 1.5 dx of the next one, plus dx/2) and its height
  // at the tank's left wall, at the start and at the end [m]
  double front_start = 0, front_end = 0, wall_height_start = 0, wall_height_end = 0;
  double max_speed_end = 0;  // [m/s] the largest particle speed at the end (the deposit is at rest when small)
  double max_speed_run = 0;  // [m/s] over the whole run, for the sound-speed rule c0 >= 10 |u|max
  std::vector<std::string> warnings;  // the sound-speed rule broken, blocks too thin for r_e (report "warnings")
  MonitorTable monitors;
  std::string pore_pressure;  // the setting's key
  // Each material (phase): its name, reference density [kg/m^3] and the mass of its moving particles inside the
  // tank at the start and at the end [kg per m of depth] (a particle never changes phase: they differ only when
  // particles have left the tank)
  struct Phase {
    std::string name;
    double density = 0, mass_start = 0, mass_end = 0;
  };
  std::vector<Phase> phases;
  std::vector<Profile> profiles;  // analyses.mps.profiles (profiles.csv, profiles.svg)
  std::vector<DamBreakFigures> dam_break;  // with profiles.dam_x_m: one per profile
  std::optional<double> dam_x;
};

}  // namespace coupling
