// analyses.lem.surfaces: slip surfaces given as polylines, with an optional moment point and tension crack.
// Keys, units and defaults: docs/scene-format.md.
#include <cmath>
#include <string>

#include "scene_internal.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

// Chords of a circle given in the scene (slope::circle_as_polyline): its factor of safety within 5e-6 of the
// circle's (both finely sliced).
constexpr int circle_segments = 256;

// analyses.lem.surfaces[i].tension_crack: {"depth_m": z} or {"rankine": true}, and "water_filled".
std::optional<slope::TensionCrack> read_tension_crack(JsonReader& crack) {
  slope::TensionCrack out;
  const auto depth = crack.number("depth_m", Need::optional);
  const auto rankine = crack.boolean("rankine", Need::optional);
  out.water_filled = crack.boolean("water_filled", Need::optional).value_or(false);
  crack.finish();
  const bool asks_rankine = rankine.value_or(false);
  if (depth && asks_rankine) {
    crack.diagnostics().error(crack.path(), "give either depth_m or \"rankine\": true, not both");
    return std::nullopt;
  }
  if (!depth && !asks_rankine) {
    if (!crack.has("depth_m"))
      crack.diagnostics().error(crack.path(), "needs a depth: \"depth_m\": <m> or \"rankine\": true (the Rankine "
                                              "depth 2c'/(gamma sqrt(Ka)) of the soil at the upper end)");
    return std::nullopt;
  }
  out.depth = depth;
  return out;
}

// analyses.lem.surfaces[i].points_m into out.polyline.points; false when invalid.
bool read_points(JsonReader& surface, GivenSurface& out) {
  const nlohmann::json* points = surface.array("points_m", Need::required, 2, limits::slip_surface_points,
                                               "an array of at least two points [x_m, y_m] (or give \"circle\")");
  if (points == nullptr) return false;
  bool ok = true;
  for (std::size_t k = 0; k < points->size(); ++k) {
    const auto point = read_pair((*points)[k], index_path(surface.path_of("points_m"), k), surface.diagnostics(),
                                 "a point [x_m, y_m]");
    if (point) out.polyline.points.push_back(slope::Point{point->first, point->second});
    else ok = false;
  }
  return ok;
}

// analyses.lem.surfaces[i].circle: {"center_m": [x, y], "radius_m": r}; false when invalid.
bool read_circle(JsonReader& circle, GivenSurface& out) {
  const nlohmann::json* centre = circle.raw("center_m", Need::required, "a point [x_m, y_m]");
  const auto radius = circle.number("radius_m", Need::required);
  std::optional<std::pair<double, double>> c;
  if (centre) c = read_pair(*centre, circle.path_of("center_m"), circle.diagnostics(), "a point [x_m, y_m]");
  circle.finish();
  if (!c || !radius) return false;
  out.circle = slope::Circle{c->first, c->second, *radius};
  return true;
}

// One element of analyses.lem.surfaces; nullopt when anything in it is invalid.
std::optional<GivenSurface> read_one_surface(const nlohmann::json& value, const std::string& path, std::size_t index,
                                             Diagnostics& diagnostics) {
  const std::size_t faults_before = diagnostics.size();
  JsonReader surface(value, path, diagnostics);
  if (!surface.is_object()) return std::nullopt;
  GivenSurface out;
  out.name = surface.string("name", Need::optional).value_or("surface " + std::to_string(index));
  bool ok = true;
  if (surface.has("circle")) {
    if (surface.has("points_m")) {
      diagnostics.error(path, "give either points_m or circle, not both");
      ok = false;
    } else if (auto circle = surface.object("circle", Need::required)) {
      ok = read_circle(*circle, out);
    } else {
      ok = false;
    }
  } else if (!read_points(surface, out)) {
    ok = false;
  }
  if (const nlohmann::json* point = surface.raw("moment_point_m", Need::optional)) {
    const auto pair = read_pair(*point, surface.path_of("moment_point_m"), diagnostics, "a point [x_m, y_m]");
    if (pair) out.polyline.moment_point = slope::Point{pair->first, pair->second};
    else ok = false;
  }
  if (const auto tolerance = surface.number("convex_tolerance_deg", Need::optional))
    out.polyline.convex_tolerance = *tolerance * sphslope::degree;
  if (auto crack = surface.object("tension_crack", Need::optional)) {
    out.polyline.tension_crack = read_tension_crack(*crack);
    ok = ok && out.polyline.tension_crack.has_value();
  }
  surface.finish();
  if (!ok || diagnostics.size() != faults_before) return std::nullopt;
  return out;
}

}  // namespace

void read_given_surfaces(JsonReader& lem, const slope::Section* section, const slope::SliceOptions& slicing,
                         std::vector<GivenSurface>& surfaces) {
  Diagnostics& diagnostics = lem.diagnostics();
  const nlohmann::json* list = lem.array("surfaces", Need::optional, 1, limits::slip_surfaces,
                                         "an array of slip surfaces {\"points_m\": [[x, y], ...], ...}");
  if (list == nullptr) return;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string path = index_path(lem.path_of("surfaces"), i);
    auto surface = read_one_surface((*list)[i], path, i, diagnostics);
    if (!surface) continue;
    if (surface->circle && section != nullptr && slope::section_error(*section).empty()) {
      std::string reason;
      const auto polyline = slope::circle_as_polyline(*section, *surface->circle, circle_segments, &reason);
      if (!polyline) {
        diagnostics.error(join_path(path, "circle"), "not an admissible slip circle: " + reason);
        continue;
      }
      surface->polyline.points = polyline->points;
      if (!surface->polyline.moment_point) surface->polyline.moment_point = polyline->moment_point;
    }
    // Admissibility on the section: a surface that cannot be analysed is a fault of the input.
    if (section != nullptr && slope::section_error(*section).empty()) {
      std::string reason;
      if (!slope::slice_polyline(*section, surface->polyline, slicing, &reason)) {
        diagnostics.error(path, "not an admissible slip surface: " + reason);
        continue;
      }
    }
    surfaces.push_back(std::move(*surface));
  }
}

}  // namespace coupling
