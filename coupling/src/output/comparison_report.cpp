#include "coupling/output/comparison_report.hpp"

#include <string>

#include "coupling/output/json_values.hpp"
#include "coupling/scene/analysis_options.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

nlohmann::json sph_surface_json(const ComparisonResult& c) {
  const SphFailure& sph = c.sph;
  nlohmann::json surface;
  surface["plastic_strain_threshold"] = sph.band.plastic_strain_threshold;
  surface["bin_width_m"] = sph.band.bin_width;
  surface["configuration"] = sphslope::name_of(band_configuration_names, c.initial_configuration);
  surface["band_particles"] = sph.band.band_particles;
  surface["points_m"] = polyline_json(sph.band.points);
  surface["entry_m"] = sph.entry ? point_json(*sph.entry) : nlohmann::json();
  surface["exit_m"] = sph.exit ? point_json(*sph.exit) : nlohmann::json();
  if (sph.fitted_circle) {
    surface["fitted_circle"] = {{"center_m", {sph.fitted_circle->circle.xc, sph.fitted_circle->circle.yc}},
                                {"radius_m", sph.fitted_circle->circle.radius},
                                {"rms_residual_m", sph.fitted_circle->rms_residual},
                                {"max_residual_m", sph.fitted_circle->max_residual}};
  } else {
    surface["fitted_circle"] = nullptr;
  }
  surface["circle_raised_for_lem_m"] = c.circle_raised_for_lem_m;
  nlohmann::json for_lem;
  if (c.sph_surface_mass) {
    const slope::SlipMass& mass = *c.sph_surface_mass;
    for_lem = {{"points_m", polyline_json(mass.surface)},
               {"entry_m", point_json(mass.entry)},
               {"exit_m", point_json(mass.exit)},
               {"tension_crack_depth_m", mass.crack_depth},
               {"scarp_angle_deg", sphslope::degrees(c.sph_scarp_angle)},
               {"largest_convex_kink_deg", sphslope::degrees(c.sph_largest_convex_kink)},
               {"band_vertices_dropped", c.sph_surface_dropped_vertices},
               {"moment_point_m", point_json(mass.moment_point)},
               {"slices", mass.slices.size()}};
  } else {
    for_lem = {{"error", c.sph_surface_for_lem_error}};
  }
  surface["as_lem_surface"] = std::move(for_lem);
  return surface;
}

void geometry_json(const SurfaceGeometry& m, nlohmann::json& out) {
  if (m.entry_offset_m) out["entry_offset_m"] = point_json(*m.entry_offset_m);
  if (m.exit_offset_m) out["exit_offset_m"] = point_json(*m.exit_offset_m);
  out["common_span_x_m"] = {m.common_from_x_m, m.common_to_x_m};
  out["mean_normal_distance_m"] = m.mean_normal_distance_m;
  out["max_normal_distance_m"] = m.max_normal_distance_m;
  out["area_between_m2"] = m.area_between_m2;
  out["sph_sliding_mass_area_m2"] = m.sph_sliding_mass_area_m2;
  out["lem_sliding_mass_area_m2"] = m.lem_sliding_mass_area_m2;
  out["intersection_area_m2"] = m.intersection_area_m2;
  out["intersection_over_union"] = m.intersection_over_union;
}

nlohmann::json method_json(const MethodComparison& m) {
  nlohmann::json out;
  out["lem_factor_of_safety"] = optional_number(m.lem_factor_of_safety);
  out["factor_of_safety_on_sph_circle"] = optional_number(m.factor_of_safety_on_sph_circle);
  if (m.on_sph_circle_error) out["factor_of_safety_on_sph_circle_error"] = *m.on_sph_circle_error;
  out["factor_of_safety_on_sph_surface"] = optional_number(m.factor_of_safety_on_sph_surface);
  if (m.on_sph_surface_error) out["factor_of_safety_on_sph_surface_error"] = *m.on_sph_surface_error;
  if (!m.has_geometry) return out;
  geometry_json(m, out);
  if (m.noncircular) {
    nlohmann::json n = {{"factor_of_safety", m.noncircular->factor_of_safety},
                        {"from_circle", m.noncircular->from_circle}};
    geometry_json(*m.noncircular, n);
    out["noncircular"] = std::move(n);
  }
  return out;
}

}  // namespace

nlohmann::json comparison_report(const ComparisonResult& c) {
  const SphFailure& sph = c.sph;
  nlohmann::json report;
  report["sph_surface"] = sph_surface_json(c);
  report["displacement_check"] = {{"displacement_threshold_m", sph.displacement_threshold},
                                  {"displaced_particles", sph.displaced_particles},
                                  {"base_points_m", polyline_json(sph.displaced_mass_base)},
                                  {"mean_distance_to_band_m", sph.band_vs_displacement.mean_normal_distance},
                                  {"max_distance_to_band_m", sph.band_vs_displacement.max_normal_distance}};
  report["deformed_ground"] = {{"points_m", polyline_json(sph.final_ground)},
                               {"initial_toe_x_m", sph.initial_toe_x},
                               {"farthest_toe_advance_m", sph.farthest_toe_advance}};
  nlohmann::json methods = nlohmann::json::object();
  for (const MethodComparison& m : c.methods) methods[m.method] = method_json(m);
  report["methods"] = methods;
  report["verdict"] = c.verdict;
  if (c.acceptance) report["acceptance"] = acceptance_json(*c.acceptance);
  return report;
}

nlohmann::json comparison_error_report(const std::string& message) { return {{"error", message}}; }

nlohmann::json acceptance_json(const AcceptanceResult& result) {
  nlohmann::json criteria = nlohmann::json::array();
  for (const CriterionResult& c : result.criteria) {
    nlohmann::json row = {{"method", c.method},
                          {"criterion", c.criterion},
                          {"limit", c.limit},
                          {"measured", c.measured ? nlohmann::json(*c.measured) : nlohmann::json()},
                          {"passed", c.passed}};
    if (!c.note.empty()) row["note"] = c.note;
    criteria.push_back(row);
  }
  return {{"accepted", result.accepted}, {"criteria", criteria}};
}

}  // namespace coupling
