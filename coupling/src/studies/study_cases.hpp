#pragma once
// The references of `sphslope study` (internal to coupling): which quantities a case monitors, their cited
// reference values, and how each is read out of a finished run.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/scene.hpp"
#include "coupling/compare/surface_comparison.hpp"
#include "coupling/analyses/pipeline.hpp"
#include "slope/search.hpp"

namespace coupling::study_detail {

enum class CaseKind { slope_failure_surface, elastic_column, column_collapse, mps_dry_collapse, isph_dam_break };

struct Quantity {
  std::string key;                 // e.g. "exit_x_m"
  std::string description;         // what it is, with its unit
  std::optional<double> reference; // reference value (none: the value is itself an error against a closed form)
  std::string reference_source;    // citation
  std::string reference_short;     // a few words for the figure's legend
  std::string error_definition;    // how the relative error is formed
  double error_scale = 1.0;        // error = |value - reference| / error_scale (value itself when no reference)
};

struct CaseSetup {
  CaseKind kind = CaseKind::slope_failure_surface;
  std::string kind_key;            // "slope_failure_surface", ...
  std::vector<Quantity> quantities;
  nlohmann::json parameters;       // what the references were computed from (a, H, density, ...)
  // slope sections
  Polyline ground;                                     // initial ground surface
  std::optional<slope::CriticalSurface> lem_reference;  // the LEM critical surface the SPH run is measured against
  // particle scenes
  std::vector<slope::Point> body_polygon;
  double density = 0.0, poisson_ratio = 0.0;  // kg/m^3, -
};

// Chooses the case from the scene and computes the references. Throws SceneError ("study: ...") when the scene
// fits none of the references (e.g. an elastic column without free-slip side walls).
CaseSetup setup_case(const Scene& scene);

// The scene at another particle spacing (scene_with_spacing: checked as the reader checks a scene file), for slopes
// with the lem and compare analyses added when absent and without the strength reduction.
Scene scene_at_spacing(const Scene& scene, double spacing);

// The monitored values of one finished run, in the order of setup.quantities (null where not available).
// `folder`: the run's folder (the ISPH dam break reads its front from the folder's monitors.csv).
std::vector<std::optional<double>> read_values(const CaseSetup& setup, const RunResults& run,
                                               const std::filesystem::path& folder);

// The ISPH dam break against Martin & Moyce's table (study_isph_case.cpp): the case, and its values from the run's
// monitors.csv (the front's RMS error without and with a time shift).
CaseSetup isph_dam_break_case(const Scene& scene);
std::vector<std::optional<double>> isph_dam_break_values(const CaseSetup& setup, const std::filesystem::path& folder);

// Relative error of a value, per its quantity's definition.
double relative_error(const Quantity& quantity, double value);

}  // namespace coupling::study_detail
