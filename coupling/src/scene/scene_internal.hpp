#pragma once
// Shared between the scene readers (scene.cpp, scene_section.cpp); not part of the public interface.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/scene.hpp"

namespace coupling {

// Reads and validates one material object (name, unit weight, strength, optional elastic and flow constants) and
// converts it to SI; reports its own unknown keys. Also used for the materials of particle bodies.
// Scene units to SI: kPa, kN/m^3 and kPa/m (kilo), MPa (mega).
inline constexpr double kilo = 1e3;
inline constexpr double mega = 1e6;

// Whose material it is: a section's may have a strength envelope (limit equilibrium) in place of cohesion_kPa and
// friction_angle_deg; a particle body's is the SPH model's Mohr-Coulomb.
enum class MaterialOf { section, body };
// The scene key of a strength envelope of this kind.
inline const char* envelope_key(slope::StrengthEnvelope::Kind kind) {
  switch (kind) {
    case slope::StrengthEnvelope::Kind::hoek_brown: return "hoek_brown";
    case slope::StrengthEnvelope::Kind::power_curve: return "power_curve";
    case slope::StrengthEnvelope::Kind::shear_normal: return "shear_normal_kPa";
  }
  return "";
}
std::optional<SoilMaterial> read_material(JsonReader& material, MaterialOf owner);

// What the readers of things placed on a section need of it: its x range (known only when its geometry is valid)
// and the way into the slope (-1: toward -x, the ground's left end being higher; +1 the other way; 0 level ends).
struct SectionExtent {
  bool known = false;
  double x_min = 0.0, x_max = 0.0;  // m
  int into_slope = 0;
};
// section.reinforcement (scene_reinforcement.cpp): each element with its type's defaults, in SI; `ok` false when one
// is invalid (reported at its path).
std::vector<slope::Reinforcement> read_reinforcement(const nlohmann::json& array, const std::string& path,
                                                     const SectionExtent& extent, Diagnostics& diagnostics, bool& ok);

// analyses.lem.critical_seismic_coefficient.acceleration_record {"file", "scale"} (scene_records.cpp): the CSV file
// (relative to the scene's folder `scene_file`'s) read and checked; nullopt when anything is wrong (reported).
std::optional<AccelerationRecordInput> read_acceleration_record(JsonReader& record,
                                                                 const std::filesystem::path& scene_file);

// analyses.lem.probabilistic (lem_probabilistic.cpp), with its method resolved (one of those analysed) and after
// analyses.lem.surfaces (a given surface is named); reports its own unknown keys. nullopt when anything is wrong.
std::optional<ProbabilisticAnalysis> read_probabilistic(JsonReader& block, const LemAnalysis& lem,
                                                        const slope::Section* section, slope::Method method);

// analyses.lem.sensitivity (lem_probabilistic.cpp), the same way.
std::optional<SensitivityAnalysis> read_sensitivity(JsonReader& block, const LemAnalysis& lem,
                                                    const slope::Section* section, slope::Method method);

// A second water of a valid section (analyses.lem.rapid_drawdown.water_after), checked as section.water is.
std::optional<slope::Water> read_other_water(JsonReader& water, const slope::Section& section);

// analyses.lem.rapid_drawdown (lem_drawdown.cpp), with its method resolved; nullopt when anything is wrong.
std::optional<DrawdownAnalysis> read_drawdown(JsonReader& block, const LemAnalysis& lem, const slope::Section* section,
                                              slope::Method method);

// Reads and validates "section"; nullopt when anything in it is invalid (the faults are in `diagnostics`).
std::optional<SceneSection> read_section(JsonReader& section, Diagnostics& diagnostics);

// Reads analyses.lem.search into `limits`; `section` (may be null) bounds the entry and exit ranges.
// Returns whether any limit was given.
bool read_search_limits(JsonReader& search, const slope::Section* section, slope::SearchLimits& limits);

// analyses.lem.search.minimum_depth_m (m), when given.
std::optional<double> read_minimum_depth(JsonReader& search);

// Reads analyses.lem.surfaces (slip surfaces given as polylines, with optional moment point and tension crack) into
// `surfaces`; each is checked admissible on `section` (when valid) and refused at its JSON path with the reason.
void read_given_surfaces(JsonReader& lem, const slope::Section* section, const slope::SliceOptions& slicing,
                         std::vector<GivenSurface>& surfaces);

// parent.<key>: a simple polygon of at least 3 [x, y] points [m] with an area; faults reported at its path (`what`
// names the thing in the message, e.g. "a body"). nullopt when invalid.
std::optional<std::vector<std::pair<double, double>>> read_simple_polygon(JsonReader& parent, std::string_view key,
                                                                       std::string_view what);

// The raw blocks of the scene that the SPH readers take (pointers into the parsed document; null when absent).
struct SphBlocks {
  const nlohmann::json* sph = nullptr;      // analyses.sph, when it is an object
  const nlohmann::json* compare = nullptr;  // analyses.compare, when it is an object
  const nlohmann::json* srm = nullptr;      // analyses.srm, when it is an object
  const nlohmann::json* bodies = nullptr;   // "bodies", when it is an array
  const nlohmann::json* walls = nullptr;    // "walls", whatever it is
  const nlohmann::json* coupled = nullptr;  // analyses.coupled, when it is an object
};

// Reads analyses.sph, and with it "bodies" and "walls", into the scene, and validates what SPH needs from the rest
// of the scene (bodies inside the wall box, enough particles across, loads SPH leaves out). Errors go to
// `diagnostics`, so that "sphslope check" reports SPH faults too.
void read_sph_scene(const SphBlocks& blocks, Scene& scene, Diagnostics& diagnostics);

// Reads analyses.srm into the scene and checks that strength reduction has a section and analyses.sph.
void read_srm_scene(const SphBlocks& blocks, Scene& scene, Diagnostics& diagnostics);

// The SPH soil model needs the elastic constants of every material of the section.
void check_materials_for_sph(const std::string& section_path, const SceneSection& section, Diagnostics& diagnostics);

}  // namespace coupling
