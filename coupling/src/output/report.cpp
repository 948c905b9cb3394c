#include "coupling/output/report.hpp"

#include <algorithm>
#include <cmath>

#include "coupling/scene/json_text.hpp"
#include "coupling/output/json_values.hpp"
#include "sphslope/units.hpp"

#ifndef SPHSLOPE_VERSION
#define SPHSLOPE_VERSION "0.1.0"
#endif

namespace coupling {

namespace {

constexpr double to_kilo = 1e-3;  // N -> kN, Pa -> kPa


// A finite number, or null (JSON has no NaN or infinity; never write a made-up number).
nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

// The base's c' (Pa) and tan(phi'): the material's, or for a base with a strength envelope the tangent to it at
// the base's effective normal stress of the solution (NaN without forces).
std::pair<double, double> base_strength(const slope::SlipMass& mass, const slope::Slice& slice,
                                        const slope::SliceForces* forces) {
  if (slice.envelope < 0 || static_cast<std::size_t>(slice.envelope) >= mass.envelopes.size())
    return {slice.cohesion, slice.tan_friction};
  if (forces == nullptr) return {std::nan(""), std::nan("")};
  const double sigma = (forces->normal - forces->pore_force) / slice.base_length;
  const slope::EnvelopePoint p = slope::envelope_at(mass.envelopes[static_cast<std::size_t>(slice.envelope)], sigma);
  return {p.shear - sigma * p.slope, p.slope};
}

nlohmann::json slice_report(const slope::Section& section, const slope::SlipMass& mass, const slope::Slice& slice,
                            const slope::SliceForces* forces) {
  nlohmann::json s;
  s["x_left_m"] = slice.x_left;
  s["x_right_m"] = slice.x_right;
  s["width_m"] = slice.width;
  s["base_angle_deg"] = sphslope::degrees(slice.base_angle);
  s["base_length_m"] = slice.base_length;
  s["material"] = slice.base_material < section.materials.size() ? section.materials[slice.base_material].name : "";
  const auto [cohesion, tan_friction] = base_strength(mass, slice, forces);
  s["cohesion_kPa"] = number(cohesion * to_kilo);
  s["friction_angle_deg"] = number(sphslope::degrees(std::atan(tan_friction)));
  s["weight_kN_m"] = slice.weight * to_kilo;
  s["surcharge_kN_m"] = slice.surcharge_load * to_kilo;
  s["ponded_water_kN_m"] = slice.ponded_water_load * to_kilo;
  s["pore_pressure_kPa"] = slice.pore_pressure * to_kilo;
  if (slice.vertical_seismic_force != 0.0) s["vertical_seismic_kN_m"] = slice.vertical_seismic_force * to_kilo;
  if (forces != nullptr) {
    s["normal_force_kN_m"] = number(forces->normal * to_kilo);
    s["shear_force_kN_m"] = number(forces->shear * to_kilo);
    s["interslice_normal_right_kN_m"] = number(forces->interslice_normal_right * to_kilo);
    s["interslice_shear_right_kN_m"] = number(forces->interslice_shear_right * to_kilo);
  } else {
    for (const char* key : {"normal_force_kN_m", "shear_force_kN_m", "interslice_normal_right_kN_m",
                            "interslice_shear_right_kN_m"}) {
      s[key] = nullptr;
    }
  }
  return s;
}

// The slip surface of a mass: a circle, or a polyline with its moment point and tension crack.
nlohmann::json surface_report(const slope::SlipMass& mass) {
  nlohmann::json s;
  if (mass.surface.empty()) {
    s = {{"type", "circle"},
         {"center_m", nlohmann::json::array({mass.circle.xc, mass.circle.yc})},
         {"radius_m", mass.circle.radius}};
  } else {
    s = {{"type", "polyline"},
         {"points_m", polyline_json(mass.surface)},
         {"moment_point_m", point_json(mass.moment_point)}};
    if (mass.crack_depth > 0.0)
      s["tension_crack"] = {{"depth_m", mass.crack_depth},
                            {"water_force_kN_m", mass.crack_water_force * to_kilo},
                            {"water_force_y_m", mass.crack_water_force > 0.0 ? nlohmann::json(mass.crack_water_force_y)
                                                                             : nlohmann::json(nullptr)}};
  }
  s["entry_m"] = point_json(mass.entry);
  s["exit_m"] = point_json(mass.exit);
  s["slides_toward"] = mass.direction >= 0 ? "+x" : "-x";
  return s;
}

// The reinforcement elements the surface crosses, each with the force it puts on the mass at the solution (its
// capacity there, divided by F when passive).
nlohmann::json supports_report(const slope::Section& section, const slope::SlipMass& mass, double factor_of_safety) {
  nlohmann::json list = nlohmann::json::array();
  for (const slope::SupportForce& f : mass.supports) {
    const slope::Reinforcement& e = section.reinforcement.at(f.element);
    const double share = f.passive ? 1.0 / factor_of_safety : 1.0;
    list.push_back({{"element", f.element},
                    {"type", std::string(sphslope::name_of(slope::support_type_names, e.type))},
                    {"direction", std::string(sphslope::name_of(slope::support_direction_names, e.direction))},
                    {"application", std::string(sphslope::name_of(slope::support_application_names, e.application))},
                    {"crossing_m", point_json(f.at)},
                    {"distance_from_head_m", f.distance},
                    {"slice_from_left", f.slice + 1},
                    {"capacity_kN_m", f.capacity * to_kilo},
                    {"force_kN_m", f.capacity * share * to_kilo},
                    {"force_x_kN_m", f.force_x * share * to_kilo},
                    {"force_y_kN_m", f.force_y * share * to_kilo}});
  }
  return list;
}

}  // namespace

std::string_view program_version() { return SPHSLOPE_VERSION; }

nlohmann::json report_header(const Scene& scene) {
  nlohmann::json report;
  report["format"] = report_format;
  report["program"] = {{"name", "sphslope"}, {"version", program_version()}};
  report["scene"] = {{"name", scene.name}, {"file", scene.file.string()}};
  return report;
}

nlohmann::json method_report(const slope::Section& section, const slope::CriticalSurface& critical) {
  nlohmann::json m;
  const slope::FsResult& result = critical.result;
  const bool solved = critical.mass.has_value() && result.factor_of_safety.has_value() &&
                      std::isfinite(*result.factor_of_safety);
  if (!solved) {
    m["factor_of_safety"] = nullptr;
    m["error"] = !result.error.empty() ? result.error
                                       : std::string("no admissible slip surface converged for this method");
    return m;
  }
  m["factor_of_safety"] = *result.factor_of_safety;
  if (slope::has_interslice_lambda(critical.method)) m["lambda"] = result.lambda;
  m["iterations"] = result.iterations;

  const slope::SlipMass& mass = *critical.mass;
  m["surface"] = surface_report(mass);
  const bool with_forces = result.forces.size() == mass.slices.size();
  nlohmann::json slices = nlohmann::json::array();
  for (std::size_t i = 0; i < mass.slices.size(); ++i) {
    slices.push_back(slice_report(section, mass, mass.slices[i], with_forces ? &result.forces[i] : nullptr));
  }
  m["slices"] = std::move(slices);
  if (!section.reinforcement.empty()) m["reinforcement"] = supports_report(section, mass, *result.factor_of_safety);
  if (!section.line_loads.empty()) {
    nlohmann::json loads = nlohmann::json::array();
    for (const slope::AppliedLineLoad& q : mass.line_loads)
      loads.push_back({{"load", q.load},
                       {"at_m", point_json(q.at)},
                       {"slice_from_left", q.slice + 1},
                       {"force_x_kN_m", q.force_x * to_kilo},
                       {"force_y_kN_m", q.force_y * to_kilo}});
    m["line_loads"] = std::move(loads);
  }
  return m;
}

nlohmann::json lem_report(const slope::Section& section, const LemAnalysis& analysis,
                          const slope::SearchResult& result, const std::vector<GivenSurfaceResult>& surfaces) {
  nlohmann::json lem;
  nlohmann::json method_keys = nlohmann::json::array();
  for (slope::Method method : analysis.methods) method_keys.push_back(slope::method_key(method));
  lem["settings"] = {{"methods", method_keys},
                     {"slices", analysis.search.slicing.slices},
                     {"refine", analysis.search.refine},
                     {"minimum_depth_m", analysis.search.minimum_depth > 0 ? nlohmann::json(analysis.search.minimum_depth)
                                                                          : nlohmann::json(nullptr)},
                     {"search_limits_given", analysis.has_search_limits}};

  nlohmann::json methods = nlohmann::json::object();
  for (slope::Method method : analysis.methods) {
    const std::string key(slope::method_key(method));
    const slope::CriticalSurface* found = nullptr;
    for (const slope::CriticalSurface& critical : result.methods) {
      if (critical.method == method) found = &critical;
    }
    if (found != nullptr) {
      methods[key] = method_report(section, *found);
    } else {
      methods[key] = {{"factor_of_safety", nullptr},
                      {"error", result.error.empty() ? "the search returned no result for this method" : result.error}};
    }
  }
  lem["methods"] = std::move(methods);

  nlohmann::json map = nlohmann::json::array();
  for (const slope::FsMapEntry& entry : result.fs_map) {
    map.push_back({{"entry_m", point_json(entry.entry)},
                   {"exit_m", point_json(entry.exit)},
                   {"center_m", nlohmann::json::array({entry.circle.xc, entry.circle.yc})},
                   {"radius_m", entry.circle.radius},
                   {"factor_of_safety", number(entry.factor_of_safety)}});
  }
  lem["search"] = {{"trial_surfaces", result.trial_surfaces},
                   {"seconds", result.seconds},
                   {"fs_map_method", analysis.search.fs_map_method ? std::string(slope::method_key(*analysis.search.fs_map_method))
                                                                     : std::string()},
                   {"fs_map", std::move(map)}};
  if (!result.error.empty()) lem["search"]["error"] = result.error;
  if (!surfaces.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const GivenSurfaceResult& surface : surfaces) {
      nlohmann::json per_method = nlohmann::json::object();
      for (const slope::CriticalSurface& critical : surface.methods)
        per_method[std::string(slope::method_key(critical.method))] = method_report(section, critical);
      list.push_back({{"name", surface.name}, {"methods", std::move(per_method)}});
    }
    lem["surfaces"] = std::move(list);
  }
  return lem;
}

namespace {

nlohmann::json newmark_direction(const char* direction, const slope::NewmarkResult& r) {
  return {{"direction", direction},
          {"displacement_m", r.displacement},
          {"peak_velocity_m_s", r.peak_velocity},
          {"sliding_time_s", r.sliding_time},
          {"sliding_episodes", r.sliding_episodes}};
}

// lem.critical_seismic_coefficient.newmark: the record, and the displacement each way round (the larger governs).
nlohmann::json newmark_report(const AccelerationRecordInput& record, const slope::CriticalCoefficient& k,
                              const NewmarkOutcome* newmark) {
  const std::size_t n = record.record.acceleration.size();
  nlohmann::json out = {{"file", record.file},
                        {"samples", n},
                        {"time_step_s", record.record.time_step},
                        {"start_time_s", record.start_time},
                        {"duration_s", record.record.time_step * static_cast<double>(n - 1)},
                        {"scale", record.scale}};
  if (newmark == nullptr || !k.coefficient) {
    out["displacement_m"] = nullptr;
    out["displacement_m_error"] = "no yield coefficient k_c: " + k.why;
    return out;
  }
  out["yield_coefficient"] = *k.coefficient;
  out["peak_acceleration_g"] = newmark->peak_acceleration;
  out["displacement_m"] = std::max(newmark->as_given.displacement, newmark->reversed.displacement);
  out["directions"] = {newmark_direction("as given", newmark->as_given),
                       newmark_direction("reversed", newmark->reversed)};
  return out;
}

}  // namespace

nlohmann::json critical_coefficient_report(const slope::Section& section, slope::Method method,
                                           const slope::CriticalCoefficient& k, const AccelerationRecordInput* record,
                                           const NewmarkOutcome* newmark) {
  nlohmann::json out = {{"method", std::string(slope::method_key(method))},
                        {"k_c", optional_number(k.coefficient)},
                        {"vertical_coefficient", section.vertical_seismic_coefficient},
                        {"factor_of_safety_without", k.factor_of_safety_without},
                        {"searches", k.searches},
                        {"seconds", k.seconds}};
  if (!k.coefficient) out["why"] = k.why;
  if (k.surface && k.surface->mass) {
    out["factor_of_safety"] = optional_number(k.surface->result.factor_of_safety);
    out["surface"] = surface_report(*k.surface->mass);
  }
  if (record != nullptr) out["newmark"] = newmark_report(*record, k, newmark);
  return out;
}

nlohmann::json noncircular_report(const slope::Section& section, const slope::NonCircularOptions& options,
                                  const slope::NonCircularResult& result) {
  nlohmann::json methods = nlohmann::json::object();
  for (const slope::NonCircularSurface& surface : result.methods) {
    nlohmann::json m = method_report(section, slope::CriticalSurface{surface.method, surface.mass, surface.result});
    m["searched"] = surface.searched;
    m["from_circle"] = surface.from_circle;
    m["circle_factor_of_safety"] = optional_number(surface.circle_factor_of_safety);
    m["polyline_factor_of_safety"] = optional_number(surface.polyline_factor_of_safety);
    if (!surface.searched && surface.method == slope::Method::ordinary)
      m["note"] = "not searched: the Ordinary method is defined for circular surfaces; this is its critical circle";
    else if (surface.from_circle)
      m["note"] = "no polyline below the critical circle was found; this is the critical circle";
    m["trial_surfaces"] = surface.trial_surfaces;
    methods[std::string(slope::method_key(surface.method))] = std::move(m);
  }
  return {{"settings", {{"initial_segments", options.initial_segments},
                        {"segments", options.segments},
                        {"tolerance", options.tolerance}}},
          {"trial_surfaces", result.trial_surfaces},
          {"seconds", result.seconds},
          {"methods", std::move(methods)}};
}

nlohmann::json drawdown_report(const DrawdownAnalysis& analysis, const std::vector<DrawdownSurfaceResult>& surfaces) {
  nlohmann::json list = nlohmann::json::array();
  for (const DrawdownSurfaceResult& s : surfaces) {
    const slope::DrawdownResult& r = s.result;
    nlohmann::json one = {{"name", s.name},
                          {"factor_of_safety", optional_number(r.factor_of_safety)},
                          {"before_drawdown", optional_number(r.stage1)},
                          {"undrained", optional_number(r.stage2)},
                          {"drained_where_lower", optional_number(r.stage3)}};
    if (!r.error.empty()) one["factor_of_safety_error"] = one["before_drawdown_error"] = one["undrained_error"] = r.error;
    if (!r.stage3) one["drained_where_lower_error"] = r.error.empty() ? "no slice's drained strength is lower" : r.error;
    nlohmann::json slices = nlohmann::json::array();
    long drained = 0;
    for (const slope::DrawdownSlice& d : r.slices) {
      drained += d.drained_governs ? 1 : 0;
      slices.push_back({{"base_x_m", d.base_x},
                        {"undrained", d.undrained},
                        {"consolidation_normal_kPa", d.consolidation_normal / 1e3},
                        {"consolidation_shear_kPa", d.consolidation_shear / 1e3},
                        {"undrained_strength_kPa", d.undrained_strength / 1e3},
                        {"drained_strength_kPa", d.drained_strength / 1e3},
                        {"drained_governs", d.drained_governs}});
    }
    one["slices_drained"] = drained;
    one["slices"] = std::move(slices);
    list.push_back(std::move(one));
  }
  return {{"method", std::string(slope::method_key(analysis.method))},
          {"procedure", "duncan_wright_wong"},
          {"surfaces", std::move(list)}};
}

std::string report_text(const nlohmann::json& report) { return json_text(report); }

}  // namespace coupling
