#pragma once
// analyses.coupled: the soil of analyses.sph (the top-level bodies) and the water of analyses.isph in one run and one
// domain (sph/coupled, docs/coupled.md). Its one key, `impact`, asks for the slide's impact parameters and the
// impulse wave Heller & Hager (2010) predict from them (coupling/analyses/impulse_waves.hpp); what it asks of the two others is
// checked here: the same particle spacing and end time, the tank as the walls of both, the bodies inside it, the
// water not all inside the soil, and none of what the coupled run does not carry yet (docs/scene-format.md).
#include <optional>

#include <nlohmann/json.hpp>

#include "coupling/scene/json_reader.hpp"

namespace coupling {

struct Scene;

// analyses.coupled.impact: the slide's ramp and the shoreline, for the impact parameters (docs/coupled.md).
struct SlideImpactSetup {
  double ramp_angle_deg = 0;  // alpha: the ramp the slide enters the water on, to the horizontal, descending to +x
  double shoreline_x = 0;     // [m] where the still water meets the ramp: the origin of the wave's distances
};

struct CoupledAnalysis {
  std::optional<SlideImpactSetup> impact;
};

// Reads analyses.coupled (`block`, an object) into the scene once analyses.sph, analyses.isph, "bodies" and "walls"
// have been read, and checks the scene against it; `sph` is the raw analyses.sph block (null when absent), `walls`
// the raw top-level "walls" (null when absent). Sets scene.walls to the tank (every side).
void read_coupled_scene(const nlohmann::json& block, const nlohmann::json* sph, const nlohmann::json* walls,
                        Scene& scene, Diagnostics& diagnostics);

}  // namespace coupling
