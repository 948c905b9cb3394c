#pragma once
// analyses.mps: the weakly compressible MPS for granular and water flows (sph/mps, docs/mps.md) on a rectangular
// tank with blocks of named materials, and its monitors (surface gauges, the front, the height at the left wall).
// Every key, unit and default is in docs/scene-format.md; the defaults come from sph::mps::Settings and
// sph::mps::HerschelBulkley. Single phase for now: every particle has the rest density rest_density_kg_m3.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/tank_scene.hpp"
#include "sph/mps/model.hpp"

namespace coupling {

struct MpsMaterial {
  std::string name;
  sph::mps::Material material;
};

struct MpsAnalysis {
  sph::mps::Settings settings;  // particle_spacing_m, end_time_s, ... (SI)
  std::vector<MpsMaterial> materials;
  Tank tank;
  std::vector<TankRectangle> blocks;  // material at rest at t = 0 (released at once: no gate)
  std::vector<std::uint16_t> block_material;  // index into materials, one per block
  std::optional<double> gate_x;  // the gate's face on the blocks' side [m] (absent: material released at once)
  TankMonitors monitors;
  // analyses.mps.profiles: the times at which the surface and bed profiles are taken [s] (ascending), and the dam's
  // x [m] for the dam-break figures (coupling/analyses/mps_profiles.hpp)
  std::vector<double> profile_times;
  std::optional<double> dam_x;
  double max_steps = 5.0e6;  // a run planned to need more time steps is refused before it starts
};

// The first time step of eq. 30 with everything at rest (|u| = 0; the largest viscosity of the blocks' materials
// at rest: the cap for a granular material, which the capped law reaches at |D| = 0 when N < 1 and never exceeds,
// a water's own viscosity) and the steps it plans for end_time_s.
struct MpsPlan {
  double time_step = 0;  // [s]
  double viscosity = 0;  // mu_max rho0 / rho_i at rest [Pa s] (the phase of the smallest kinematic viscosity)
  double planned_steps = 0;
  bool viscous_limit = false;  // the viscous bound rho0 dx^2 / (2 d mu) sets the step, not dx / c0
};
MpsPlan plan_mps(const MpsAnalysis& a);

// Reads analyses.mps; faults go to the reader's diagnostics with their JSON paths.
MpsAnalysis read_mps_analysis(JsonReader& mps);

// analyses.mps at another particle spacing (sphslope study), checked as the reader checks it: the gate (ceil(r_e/dx)
// spacings thick) inside the tank and clear of the blocks, the settings' and materials' own checks, and the step plan
// against max_steps.
void apply_mps_spacing(MpsAnalysis& analysis, double spacing, Diagnostics& diagnostics);

}  // namespace coupling
