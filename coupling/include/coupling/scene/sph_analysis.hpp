#pragma once
// analyses.sph, "bodies" and "walls" read into typed settings, once, by the scene loader (load_scene); the SPH
// stage and the model builder (coupling/analyses/sph_model.hpp) use these structs. Every fault names its JSON path;
// see docs/scene-format.md for the keys.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/soil_material.hpp"
#include "slope/section.hpp"
#include "sph/engine/fill.hpp"
#include "sph/soil/model.hpp"

namespace coupling {

inline constexpr double gibibyte = 1024.0 * 1024.0 * 1024.0;

struct WallSides {
  bool left = true, right = true, bottom = true;
};
// The sides' names in scene files (walls.sides, analyses.sph.walls.sides).
enum class WallSide { left, right, bottom };
inline constexpr sphslope::NameTable<WallSide, 3> wall_side_names{
    {{"left", WallSide::left}, {"right", WallSide::right}, {"bottom", WallSide::bottom}}};

// The loads of a slope section that analyses.sph.ignore_loads may name (seismic: k_h and k_v), with their names.
enum class SectionLoadKind { water, surcharges, line_loads, seismic };
inline constexpr sphslope::NameTable<SectionLoadKind, 4> section_load_names{
    {{"water", SectionLoadKind::water},
     {"surcharges", SectionLoadKind::surcharges},
     {"line_loads", SectionLoadKind::line_loads},
     {"seismic", SectionLoadKind::seismic}}};

// How a body's polygon is filled with particles: on the lattice of the wall box (faces that are not along the
// lattice become staircases, and particles closer than dx/2 to a solid's face are cleared), or in rows parallel to
// its faces (sph::boundary_layer_points: every face smooth, its first row dx/2 inside it).
enum class BodyFill { lattice, rows };
// The fills' names in scene files (bodies[i].fill).
inline constexpr sphslope::NameTable<BodyFill, 2> body_fill_names{
    {{"lattice", BodyFill::lattice}, {"rows", BodyFill::rows}}};

// The most vertices a body filled in rows may have: every row point is tested against every edge.
inline constexpr std::size_t max_rows_fill_vertices = 1000;

// A body of a particle scene: a polygon of one material.
struct ParticleBody {
  std::string name;
  std::vector<slope::Point> polygon;  // m
  SoilMaterial material;
  BodyFill fill = BodyFill::lattice;
};

// The points a body's soil particles take at spacing dx: the lattice points strictly inside its polygon (the
// lattice anchored at `anchor`), or its rows (sph::boundary_layer_points, until the rows meet).
std::vector<sph::Point> body_fill_points(const ParticleBody& body, double dx, sph::Point anchor);

// A particle scene's wall box: the inner box [x_min, x_max] x [bottom_y, bottom_y + height], walls on `sides`.
struct WallBox {
  double x_min = 0.0, x_max = 0.0, bottom_y = 0.0, height = 0.0;  // m
  WallSides sides;
};

struct SphAnalysis {
  sph::soil::Settings settings;               // SI
  WallSides section_walls;              // slope scenes: which sides of the section box carry walls
  int wall_layers = 0;                  // wall thickness in particle layers (at least the kernel support 2h)
  double quasi_static_speed = 0.0;      // m/s; stop once every particle is slower (0: run to end_time_s)
  double quasi_static_min_time = 0.0;   // s; not before this simulated time
  double memory_limit_bytes = 0.0;      // refuse a case whose estimate exceeds it
  std::size_t max_particles = 0;        // refuse more soil + wall particles than this
  double max_steps = 0.0;               // refuse a run that needs more time steps than this
  std::vector<SectionLoadKind> ignored_loads;  // section loads SPH leaves out (analyses.sph.ignore_loads)
};

// Whether analyses.sph.ignore_loads lists `load` (the SPH model leaves it out).
inline bool ignores(const SphAnalysis& analysis, SectionLoadKind load) {
  return std::find(analysis.ignored_loads.begin(), analysis.ignored_loads.end(), load) != analysis.ignored_loads.end();
}

// Reads analyses.sph (errors at "analyses.sph.<key>").
std::optional<SphAnalysis> read_sph_analysis(const nlohmann::json& block, Diagnostics& diagnostics);

struct Scene;
// What depends on analyses.sph.particle_spacing_m, checked again at `spacing` (sphslope study): at least 4 particles
// across the section or each body, with the reader's messages. (The wall layers do not: 2h is h/dx spacings.)
void apply_sph_spacing(const Scene& scene, SphAnalysis& analysis, double spacing, Diagnostics& diagnostics);

// Reads "bodies" and "walls" of a particle scene.
std::optional<std::vector<ParticleBody>> read_particle_bodies(const nlohmann::json& bodies, Diagnostics& diagnostics);
std::optional<WallBox> read_wall_box(const nlohmann::json& walls, Diagnostics& diagnostics);

}  // namespace coupling
