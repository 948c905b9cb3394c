#pragma once
// Scene files ("format": "sphslope-scene/1"): loading, validation and conversion to SI.
//
// Every key, unit and default is documented in docs/scene-format.md.
// load_scene() either returns a fully validated Scene in SI units (m, N/m^3, Pa, rad) or throws SceneError
// holding every fault found, each naming its JSON path:
//
//   section.profile_lines[1].points_m[3]: x must increase (got 12.0 after 15.0)
//
// Units are converted here, once: kPa -> Pa, kN/m^3 -> N/m^3, deg -> rad, MPa -> Pa.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/analysis_options.hpp"
#include "coupling/scene/coupled_analysis.hpp"
#include "coupling/scene/isph_analysis.hpp"
#include "coupling/scene/mps_analysis.hpp"
#include "coupling/scene/probabilistic_analysis.hpp"
#include "coupling/scene/soil_material.hpp"
#include "coupling/scene/sph_analysis.hpp"
#include "slope/drawdown.hpp"
#include "slope/methods.hpp"
#include "slope/newmark.hpp"
#include "slope/search.hpp"
#include "slope/section.hpp"

namespace coupling {

inline constexpr std::string_view scene_format = "sphslope-scene/1";

struct SceneSection {
  slope::Section section;                // SI, ready for slope::search_critical
  std::vector<SoilMaterial> materials;   // same order as section.materials
};

// analyses.lem.surfaces[i]: a slip surface given by the user, analysed with every method besides the search.
struct GivenSurface {
  std::string name;              // "name", default "surface <i>"
  slope::SlipPolyline polyline;  // points, moment point, tension crack, convex tolerance (SI)
  // "circle" instead of "points_m": the circle, analysed as 256 inscribed chords (slope::circle_as_polyline) so
  // that it can carry a tension crack; polyline.points are then set from it.
  std::optional<slope::Circle> circle;
};

// analyses.lem.critical_seismic_coefficient.acceleration_record: a ground acceleration record, read from its CSV
// file when the scene is read, for Newmark's displacement at k_c (slope/newmark.hpp).
struct AccelerationRecordInput {
  std::string file;           // as the scene gives it (relative to the scene's folder)
  slope::AccelerationRecord record;
  double start_time = 0.0;    // s, the first sample's time in the file
  double scale = 1.0;         // the accelerations times this
};

// analyses.lem.rapid_drawdown: Duncan, Wright & Wong's three stages (slope/drawdown.hpp) on every given surface, the
// section's water before drawdown and this one after.
struct DrawdownAnalysis {
  slope::Method method = slope::Method::bishop;
  slope::Water water_after;
  // per material of the section: its K_c = 1 envelope (SI), empty: free-draining
  std::vector<std::optional<slope::ConsolidatedEnvelope>> envelopes;
};

// analyses.lem, with every default applied.
struct LemAnalysis {
  std::vector<GivenSurface> surfaces;   // analyses.lem.surfaces, checked admissible on the section
  std::vector<slope::Method> methods;   // default: slope::all_methods()
  slope::SearchOptions search;          // slicing.slices default 50, refine default true, limits optional
  bool has_search_limits = false;       // the scene gave analyses.lem.search limits (or a minimum depth)
  bool methods_given = false;           // the scene listed analyses.lem.methods (else the default list)
  // analyses.lem.noncircular_search: the non-circular search after the circular one (absent: not run)
  std::optional<slope::NonCircularOptions> noncircular;
  // analyses.lem.fs_map: the safety map's method goes to search.fs_map_method (default Bishop when it is analysed,
  // else the first method); the top of its colour scale (absent: 1.5 x the lowest factor on the map).
  std::optional<double> fs_map_scale_max;
  // analyses.lem.critical_seismic_coefficient: the method whose search finds k_c (absent: k_c is not sought)
  std::optional<slope::Method> critical_coefficient_method;
  std::optional<AccelerationRecordInput> acceleration_record;  // (only with critical_coefficient_method)
  std::optional<ProbabilisticAnalysis> probabilistic;          // analyses.lem.probabilistic (absent: not run)
  std::optional<SensitivityAnalysis> sensitivity;              // analyses.lem.sensitivity (absent: not run)
  std::optional<DrawdownAnalysis> rapid_drawdown;              // analyses.lem.rapid_drawdown (absent: not run)
};

// The analyses the scene asks for, each read once into its typed settings (defaults applied).
struct Analyses {
  std::optional<LemAnalysis> lem;
  std::optional<SphAnalysis> sph;
  std::optional<ComparisonOptions> compare;
  std::optional<SrmOptions> srm;
  std::optional<IsphAnalysis> isph;  // the ISPH fluid (docs/isph.md), independent of the others
  std::optional<MpsAnalysis> mps;  // the WC-MPS granular or water flow (docs/mps.md), independent of the others
  // sph and isph as one coupled run (docs/coupled.md): the "coupled" stage runs them, not their own stages
  std::optional<CoupledAnalysis> coupled;
  bool empty() const { return !lem && !sph && !compare && !srm && !isph && !mps && !coupled; }
};

struct Scene {
  std::string name;                       // "name", default: the file stem
  std::string source;                     // "source", may be empty
  std::filesystem::path file;             // where it was loaded from (empty for text)
  std::optional<SceneSection> section;    // slope scenes
  // Particle scenes: "bodies" and "walls", read with analyses.sph (the only analysis that uses them).
  std::optional<std::vector<ParticleBody>> bodies;
  std::optional<WallBox> walls;
  std::optional<std::size_t> body_count;  // entries of "bodies" as written (also when no analysis reads them)
  Analyses analyses;
};

// Every fault of a scene, each "<json path>: <what is wrong> (<what is allowed>)".
class SceneError : public std::runtime_error {
 public:
  explicit SceneError(std::vector<std::string> messages);
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  std::vector<std::string> messages_;
};

// Reads, parses and validates a scene file. Throws SceneError (unreadable file, JSON syntax error with line and
// column, or validation faults).
Scene load_scene(const std::filesystem::path& file);
// Same, from text; `file` is only recorded (and its stem used as the default name).
Scene parse_scene(std::string_view text, const std::filesystem::path& file = {});
// Same, from an already parsed document.
Scene scene_from_json(const nlohmann::json& document, const std::filesystem::path& file = {});

// The scene at another particle spacing, as the reader would have read it with that particle_spacing_m (in
// analyses.mps, else analyses.isph, else analyses.sph): the spacing set on the typed settings and every check that
// depends on it made again, with the reader's messages. Throws SceneError with them. Used by sphslope study.
Scene scene_with_spacing(const Scene& scene, double spacing);

// The LEM settings used when the scene has no analyses.lem block (sphslope lem on such a scene).
LemAnalysis default_lem_analysis();
// What "lem": {} reads to: default_lem_analysis() with the safety map's default method.
LemAnalysis lem_analysis_of_empty_block();

// Keys of the methods analyses.lem computes ("bishop", ...), in the scene's order; empty without analyses.lem.
std::vector<std::string> lem_method_keys(const Scene& scene);

// The loads of a slope section that the SPH model leaves out because analyses.sph.ignore_loads lists them, each with
// the JSON path that defines it: {"water", "section.water"}, {"surcharges", "section.surcharges"},
// {"seismic", "section.seismic"}. Empty without a section or an SPH analysis.
// What the section carries into limit equilibrium that the SPH model leaves out: the loads the user listed in
// analyses.sph.ignore_loads, and what the SPH soil model cannot represent (a material's pore-pressure ratio r_u).
struct SectionLoad {
  std::string name;  // e.g. "water", "the pore-pressure ratio r_u = 0.25 of material \"clay\""
  std::string path;  // its JSON path
  std::string why;   // why SPH leaves it out, e.g. "listed in analyses.sph.ignore_loads"
};
std::vector<SectionLoad> loads_sph_leaves_out(const Scene& scene);


// One line describing the scene, for "sphslope check": "section 0 to 60 m, 2 profile lines, ...".
std::string summarize(const Scene& scene);

}  // namespace coupling
