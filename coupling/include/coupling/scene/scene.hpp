#pragma once
// Scene files ("format": "sphslope-scene/1"): loading, validation and conversion to SI.
//
// The contract is /work/shared/SCENE.md; every key, unit and default is documented in docs/scene-format.md.
// load_scene() either returns a fully validated Scene in SI units (m, N/m^3, Pa, rad) or throws SceneError
// holding every fault found, each naming its JSON path:
//
//   section.profile_lines[1].points_m[3]: x must increase (got 12.0 after 15.0)
//
// Units are converted here, once: kPa -> Pa, kN/m^3 -> N/m^3, deg -> rad, MPa -> Pa.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "slope/methods.hpp"
#include "slope/search.hpp"
#include "slope/section.hpp"

namespace coupling {

inline constexpr std::string_view scene_format = "sphslope-scene/1";
inline constexpr double standard_gravity = 9.81;  // m/s^2, as in the source thesis; density = unit weight / g

// A soil of the section, SI units. Section::materials holds the strength and weight for limit equilibrium;
// this keeps everything the scene said, including what only SPH needs.
struct SoilMaterial {
  std::string name;
  double unit_weight = 0.0;                // N/m^3
  double cohesion = 0.0;                   // Pa
  double friction_angle = 0.0;             // rad
  std::optional<double> dilatancy_angle;   // rad; absent: SPH uses 0 (non-associated flow)
  std::optional<double> youngs_modulus;    // Pa; needed by SPH only
  std::optional<double> poisson_ratio;     // -; needed by SPH only
  bool elastic = false;                    // SPH: linear elastic, no yield (constitutive_model "elastic")

  double density() const { return unit_weight / standard_gravity; }  // kg/m^3
};

struct SceneSection {
  slope::Section section;                // SI, ready for slope::search_critical
  std::vector<SoilMaterial> materials;   // same order as section.materials
};

// analyses.lem, with every default applied.
struct LemAnalysis {
  std::vector<slope::Method> methods;   // default: slope::all_methods()
  slope::SearchOptions search;          // slicing.slices default 50, refine default true, limits optional
  bool has_search_limits = false;       // the scene gave analyses.lem.search limits (or a minimum depth)
};

struct Analyses {
  std::optional<LemAnalysis> lem;
  std::optional<nlohmann::json> sph;      // raw; validated by the SPH stage
  std::optional<nlohmann::json> compare;  // raw; validated by the comparison stage
  std::optional<nlohmann::json> srm;      // raw; validated by the strength-reduction stage
  bool empty() const { return !lem && !sph && !compare && !srm; }
};

struct Scene {
  std::string name;                       // "name", default: the file stem
  std::string source;                     // "source", may be empty
  std::filesystem::path file;             // where it was loaded from (empty for text)
  std::optional<SceneSection> section;    // slope scenes
  std::optional<nlohmann::json> bodies;   // particle scenes (raw; validated by the SPH stage)
  std::optional<nlohmann::json> walls;    // particle scenes (raw; validated by the SPH stage)
  Analyses analyses;
  nlohmann::json document;                // the whole parsed file, for later stages that read raw blocks
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

// The LEM settings used when the scene has no analyses.lem block (sphslope lem on such a scene).
LemAnalysis default_lem_analysis();

// Keys of the methods analyses.lem computes ("bishop", ...), in the scene's order; empty without analyses.lem.
std::vector<std::string> lem_method_keys(const Scene& scene);

// One line describing the scene, for "sphslope check": "section 0 to 60 m, 2 profile lines, ...".
std::string summarize(const Scene& scene);

}  // namespace coupling
