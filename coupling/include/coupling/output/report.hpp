#pragma once
// report.json ("format": "sphslope-report/1"): every key is documented in docs/scene-format.md. Units are in every
// key; forces are per metre of slope width (plane strain), in kN/m.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/scene/scene.hpp"
#include "slope/search.hpp"

namespace coupling {

inline constexpr std::string_view report_format = "sphslope-report/1";

// The program's version ("0.1.0").
std::string_view program_version();

// {"format", "program", "scene": {"name", "file"}}; the workflow adds the analyses, status and timing.
nlohmann::json report_header(const Scene& scene);

// One critical surface: factor_of_safety (or null and "error"), lambda (Spencer, Morgenstern-Price), iterations,
// surface {type "circle", center_m, radius_m | type "polyline", points_m, moment_point_m, tension_crack; entry_m,
// exit_m, slides_toward}, slices [...].
nlohmann::json method_report(const slope::Section& section, const slope::CriticalSurface& critical);

// The "lem" block: settings, methods (keyed by method key, in the order asked for), search {trial_surfaces,
// seconds, fs_map_method, fs_map} and, when the scene gave slip surfaces, surfaces [{name, methods}].
nlohmann::json lem_report(const slope::Section& section, const LemAnalysis& analysis,
                          const slope::SearchResult& result, const std::vector<GivenSurfaceResult>& surfaces = {});

// lem.critical_seismic_coefficient: k_c (null with "why" when there is none), the factor of safety without k_h, the
// critical surface at k_c; with an acceleration record, "newmark" (Newmark's displacement at k_c, or why there is
// none).
nlohmann::json critical_coefficient_report(const slope::Section& section, slope::Method method,
                                           const slope::CriticalCoefficient& k,
                                           const AccelerationRecordInput* record = nullptr,
                                           const NewmarkOutcome* newmark = nullptr);

// The "lem.noncircular" block: settings {initial_segments, segments, tolerance}, trial_surfaces, seconds, and
// methods keyed by method key, each as method_report plus searched, from_circle, circle_factor_of_safety,
// polyline_factor_of_safety, trial_surfaces and a note when the result is the critical circle.
nlohmann::json noncircular_report(const slope::Section& section, const slope::NonCircularOptions& options,
                                  const slope::NonCircularResult& result);

// lem.rapid_drawdown: the method, the procedure and per given surface its factor of safety (the lower of stages 2 and
// 3; null with `factor_of_safety_error`), the three stages' factors, and its slices' consolidation stresses and
// strengths (kPa).
nlohmann::json drawdown_report(const DrawdownAnalysis& analysis, const std::vector<DrawdownSurfaceResult>& surfaces);

// Pretty-printed JSON text of a report, ending in a newline; throws NonFiniteNumber (coupling/scene/json_text.hpp),
// naming the keys, when a number in it is NaN or infinite.
std::string report_text(const nlohmann::json& report);

}  // namespace coupling
