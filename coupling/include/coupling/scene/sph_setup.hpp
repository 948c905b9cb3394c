#pragma once
// From a validated scene to an SPH particle model: the analyses.sph settings, the particle bodies (a slope
// section filled on a lattice, or the polygons of a particle scene) and the walls. Every fault names its JSON
// path; see docs/scene-format.md for the keys.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/scene.hpp"
#include "sph/soil/model.hpp"

namespace coupling {

struct WallSides {
  bool left = true, right = true, bottom = true;
};

// A body of a particle scene: a polygon of one material.
struct ParticleBody {
  std::string name;
  std::vector<slope::Point> polygon;  // m
  SoilMaterial material;
};

// A particle scene's wall box: the inner box [x_min, x_max] x [bottom_y, bottom_y + height], walls on `sides`.
struct WallBox {
  double x_min = 0.0, x_max = 0.0, bottom_y = 0.0, height = 0.0;  // m
  WallSides sides;
};

struct SphAnalysis {
  sph::Settings settings;               // SI
  WallSides section_walls;              // slope scenes: which sides of the section box carry walls
  int wall_layers = 0;                  // wall thickness in particle layers (at least the kernel support 2h)
  double quasi_static_speed = 0.0;      // m/s; stop once every particle is slower (0: run to end_time_s)
  double quasi_static_min_time = 0.0;   // s; not before this simulated time
  double memory_limit_bytes = 0.0;      // refuse a case whose estimate exceeds it
  std::size_t max_particles = 0;        // refuse more soil + wall particles than this
  double max_steps = 0.0;               // refuse a run that needs more time steps than this
  std::vector<std::string> ignored_loads;  // section loads SPH may leave out ("water", "surcharges", "seismic")
};

// The loads of a slope section that the SPH model does not carry yet, each with the JSON path that defines it:
// {"water", "section.water"}, {"surcharges", "section.surcharges"}, {"seismic", "section.seismic"}.
struct SectionLoad {
  std::string name;
  std::string path;
};
std::vector<SectionLoad> loads_sph_leaves_out(const Scene& scene);

// Reads analyses.sph (errors at "analyses.sph.<key>").
std::optional<SphAnalysis> read_sph_analysis(const nlohmann::json& block, Diagnostics& diagnostics);

// Reads "bodies" and "walls" of a particle scene.
std::optional<std::vector<ParticleBody>> read_particle_bodies(const nlohmann::json& bodies, Diagnostics& diagnostics);
std::optional<WallBox> read_wall_box(const nlohmann::json& walls, Diagnostics& diagnostics);

// Validates everything SPH needs from the scene (analysis block, bodies/walls or section materials). Called by
// the scene loader so that "sphslope check" reports SPH faults too.
void check_sph_scene(const Scene& scene, Diagnostics& diagnostics);

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

// Builds the particle model of a validated scene. Throws SceneError (path "analyses.sph.particle_spacing_m")
// when the case would exceed the memory limit or the particle limit, before allocating particles.
sph::Model build_sph_model(const Scene& scene, SphSize* size = nullptr);

// Soil particle positions of a slope section on the cell-centred lattice of spacing dx anchored at the
// section's lower-left corner, with the material of each (the profile line that is the top of its layer).
struct SectionFill {
  std::vector<slope::Point> points;
  std::vector<std::size_t> materials;
};
SectionFill fill_section(const slope::Section& section, double dx);

}  // namespace coupling
