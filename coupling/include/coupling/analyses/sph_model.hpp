#pragma once
// From a validated scene to an SPH particle model: the particle bodies (a slope section filled on a lattice, or the
// polygons of a particle scene) and the walls, with the size checks that refuse a case before it starts.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "coupling/scene/scene.hpp"
#include "sph/soil/model.hpp"

namespace coupling {

// The particle count and memory a scene's SPH model would need, without building it.
struct SphSize {
  std::size_t soil_particles = 0;
  std::size_t wall_particles = 0;
  std::size_t memory_bytes = 0;
};

// What a run would need, estimated from the scene without building particles: soil and wall particle counts
// (lattice area estimate), memory, the fastest P-wave speed, the time step at rest and the number of steps to
// end_time_s. Empty when the scene lacks what the estimate needs (e.g. elastic constants; reported elsewhere).
struct SphPlan {
  std::size_t soil_particles = 0;
  std::size_t wall_particles = 0;
  std::size_t memory_bytes = 0;
  double p_wave_speed = 0.0;   // m/s
  double time_step = 0.0;      // s
  double planned_steps = 0.0;  // end_time_s / time_step
};
std::optional<SphPlan> plan_sph(const Scene& scene, const SphAnalysis& analysis);

// Messages ("<json path>: <why>") for a case that must be refused before it starts: more particles than
// max_particles, more memory than max_memory_GiB, more steps than max_steps. Empty when it may run.
std::vector<std::string> sph_refusals(const SphAnalysis& analysis, const SphPlan& plan);

// Builds the particle model of a validated scene, with the section's loads (water, surcharges, seismic) except those
// listed in analyses.sph.ignore_loads. Throws SceneError (path "analyses.sph.particle_spacing_m")
// when the case would exceed the memory limit or the particle limit, before allocating particles.
sph::soil::Model build_sph_model(const Scene& scene, SphSize* size = nullptr);

// Soil particle positions of a slope section on the cell-centred lattice of spacing dx anchored at the
// section's lower-left corner, with the material of each (the profile line that is the top of its layer).
struct SectionFill {
  std::vector<slope::Point> points;
  std::vector<std::size_t> materials;
};
SectionFill fill_section(const slope::Section& section, double dx);

}  // namespace coupling
