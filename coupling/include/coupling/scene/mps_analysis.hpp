#pragma once
// analyses.mps: the weakly compressible MPS for granular and water flows (sph/mps, docs/mps.md) on a rectangular
// tank with blocks of named materials, and its monitors (surface gauges, the front, the height at the left wall).
// Every key, unit and default is in docs/scene-format.md; the defaults come from sph::mps::Settings and
// sph::mps::HerschelBulkley. Single phase for now: every particle has the rest density rest_density_kg_m3.
#include <cstdint>
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
  TankMonitors monitors;
};

// Reads analyses.mps; faults go to the reader's diagnostics with their JSON paths.
MpsAnalysis read_mps_analysis(JsonReader& mps);

}  // namespace coupling
