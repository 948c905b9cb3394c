#pragma once
// The figures of a run of the pipeline, written into its output folder.
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/compare/comparison.hpp"
#include "coupling/compare/failure_surface.hpp"
#include "coupling/scene/scene.hpp"

namespace coupling {

// figures/section.svg (the section, the LE critical circles, the SPH particles and failure surface) and
// figures/fs_map.svg (after a limit-equilibrium search) in `dir`; their names go to report["figures"].
void write_figures(const Scene& scene, const WorkflowResult& out, const std::optional<ParticleSnapshot>& final_state,
                   const std::optional<SphFailure>& failure, const std::filesystem::path& dir,
                   nlohmann::json& report);

}  // namespace coupling
