#pragma once
// The figures of a run of the pipeline, written into its output folder.
#include <filesystem>
#include <optional>

#include <string>
#include <vector>

#include "coupling/analyses/run_results.hpp"
#include "coupling/scene/scene.hpp"

namespace coupling {

// figures/section.svg (the section, the LE critical circles, the SPH particles and failure surface) and
// figures/fs_map.svg (after a limit-equilibrium search of the scene's analyses.lem) in `dir`; returns their names
// relative to `dir` (none when there is nothing to draw: no section and no particles).
std::optional<std::vector<std::string>> write_figures(const Scene& scene, const RunResults& results,
                                                      const std::filesystem::path& dir);

}  // namespace coupling
