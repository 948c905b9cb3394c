#pragma once
// analyses.coupled: the soil of analyses.sph (the top-level bodies) and the water of analyses.isph in one run and one
// domain (sph/coupled, docs/coupled.md). The block has no keys of its own yet; what it asks of the two others is
// checked here: the same particle spacing and end time, the tank as the walls of both, the bodies inside it, the
// water not all inside the soil, and none of what the coupled run does not carry yet (docs/scene-format.md).
#include <nlohmann/json.hpp>

#include "coupling/scene/json_reader.hpp"

namespace coupling {

struct Scene;

struct CoupledAnalysis {};

// Reads analyses.coupled (`block`, an object) into the scene once analyses.sph, analyses.isph, "bodies" and "walls"
// have been read, and checks the scene against it; `sph` is the raw analyses.sph block (null when absent), `walls`
// the raw top-level "walls" (null when absent). Sets scene.walls to the tank (every side).
void read_coupled_scene(const nlohmann::json& block, const nlohmann::json* sph, const nlohmann::json* walls,
                        Scene& scene, Diagnostics& diagnostics);

}  // namespace coupling
