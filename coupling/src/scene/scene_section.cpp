// The "section" block of a scene and the LEM search limits: validation and conversion to SI.
#include <algorithm>
#include <cmath>
#include <map>

#include "scene_internal.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

using Polyline = std::vector<slope::Point>;

std::string range_text(double a, double b) { return format_number(a) + " to " + format_number(b); }

// A polyline of [x, y] points with x strictly increasing.
std::optional<Polyline> read_polyline(const nlohmann::json& points, const std::string& path, Diagnostics& diagnostics) {
  Polyline line;
  bool ok = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string point_path = index_path(path, i);
    const auto point = read_pair(points[i], point_path, diagnostics, "a point [x_m, y_m]");
    if (!point) {
      ok = false;
      continue;
    }
    if (!line.empty() && ok && !(point->first > line.back().x)) {
      diagnostics.error(point_path, "x must increase (got " + points[i][0].dump() + " after " +
                                        points[i - 1][0].dump() + "; points run left to right, x strictly increasing)");
      ok = false;
    }
    line.push_back({point->first, point->second});
  }
  if (!ok) return std::nullopt;
  return line;
}

// Linear interpolation on a polyline, constant beyond its ends (same rule as slope::polyline_y).
double height_at(const Polyline& line, double x) {
  if (x <= line.front().x) return line.front().y;
  if (x >= line.back().x) return line.back().y;
  const auto upper =
      std::upper_bound(line.begin(), line.end(), x, [](double value, const slope::Point& p) { return value < p.x; });
  const slope::Point& b = *upper;
  const slope::Point& a = *(upper - 1);
  return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
}

// Every vertex x of both lines inside [lo, hi], sorted, plus the ends.
std::vector<double> common_abscissae(const Polyline& a, const Polyline& b, double lo, double hi) {
  std::vector<double> xs{lo, hi};
  for (const auto* line : {&a, &b}) {
    for (const slope::Point& p : *line) {
      if (p.x > lo && p.x < hi) xs.push_back(p.x);
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  return xs;
}

struct LineRead {
  std::optional<std::size_t> material;
  std::optional<Polyline> points;
  std::string path;
};

// Every profile line spans the ground surface's x range.
void check_line_spans(const std::vector<LineRead>& lines, double x_min, double x_max, double tolerance,
                      Diagnostics& diagnostics) {
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const Polyline& line = *lines[i].points;
    const std::string points_path = join_path(lines[i].path, "points_m");
    const bool left_ok = std::fabs(line.front().x - x_min) <= tolerance;
    const bool right_ok = std::fabs(line.back().x - x_max) <= tolerance;
    if (!left_ok || !right_ok) {
      diagnostics.error(index_path(points_path, left_ok ? line.size() - 1 : 0),
                        "every profile line must span the same x range as the ground surface (profile_lines[0]: x " +
                            range_text(x_min, x_max) + " m); this line spans x " +
                            range_text(line.front().x, line.back().x) + " m");
    }
  }
}

// The ground surface is on top of every other line.
void check_ground_on_top(const std::vector<LineRead>& lines, double x_min, double x_max, double tolerance,
                         Diagnostics& diagnostics) {
  const Polyline& ground = *lines[0].points;
  for (std::size_t j = 1; j < lines.size(); ++j) {
    const Polyline& line = *lines[j].points;
    for (double x : common_abscissae(ground, line, x_min, x_max)) {
      const double above = height_at(line, x) - height_at(ground, x);
      if (above > tolerance) {
        diagnostics.error(lines[j].path,
                          "rises above the ground surface (profile_lines[0]) at x = " + format_number(x) + " m (y = " +
                              format_number(height_at(line, x)) + " above " + format_number(height_at(ground, x)) +
                              "); the first profile line is the ground surface and must be on top (lines may touch "
                              "but not cross)");
        break;
      }
    }
  }
}

// Lines below the ground may touch but not cross each other.
void check_lines_do_not_cross(const std::vector<LineRead>& lines, double x_min, double x_max, double tolerance,
                              Diagnostics& diagnostics) {
  for (std::size_t i = 1; i < lines.size(); ++i) {
    for (std::size_t j = i + 1; j < lines.size(); ++j) {
      const Polyline& a = *lines[i].points;
      const Polyline& b = *lines[j].points;
      double previous_x = 0.0, previous_d = 0.0;
      bool have_previous = false;
      for (double x : common_abscissae(a, b, x_min, x_max)) {
        const double d = height_at(a, x) - height_at(b, x);
        if (std::fabs(d) <= tolerance) continue;  // touching
        if (have_previous && (d > 0) != (previous_d > 0)) {
          const double crossing = previous_x + (x - previous_x) * previous_d / (previous_d - d);
          diagnostics.error(lines[j].path, "crosses profile_lines[" + std::to_string(i) + "] near x = " +
                                               format_number(crossing) + " m (lines may touch but not cross)");
          break;
        }
        previous_x = x;
        previous_d = d;
        have_previous = true;
      }
    }
  }
}

// bottom_y_m is at or below every profile line, and below the ground somewhere (else there is no soil).
void check_bottom(const std::vector<LineRead>& lines, double bottom_y, double tolerance,
                  const std::string& section_path, Diagnostics& diagnostics) {
  const Polyline& ground = *lines[0].points;
  const std::string bottom_path = join_path(section_path, "bottom_y_m");
  bool reported = false;
  for (std::size_t i = 0; i < lines.size() && !reported; ++i) {
    const Polyline& line = *lines[i].points;
    for (std::size_t k = 0; k < line.size(); ++k) {
      if (line[k].y < bottom_y - tolerance) {
        diagnostics.error(bottom_path, "must be at or below every profile line (got " + format_number(bottom_y) +
                                           ", but " + index_path(join_path(lines[i].path, "points_m"), k) +
                                           " has y = " + format_number(line[k].y) + ")");
        reported = true;
        break;
      }
    }
  }
  const bool ground_above =
      std::any_of(ground.begin(), ground.end(), [&](const slope::Point& p) { return p.y > bottom_y + tolerance; });
  if (!reported && !ground_above) {
    diagnostics.error(bottom_path, "must be below the ground surface (got " + format_number(bottom_y) +
                                       "; the ground surface is nowhere above it, so the section holds no soil)");
  }
}

// Profile lines: same x span as the ground surface, at or below it, pairwise not crossing, not below the bottom.
bool check_profile_geometry(const std::vector<LineRead>& lines, std::optional<double> bottom_y,
                            const std::string& section_path, Diagnostics& diagnostics) {
  const std::size_t errors_before = diagnostics.size();
  const Polyline& ground = *lines[0].points;
  const double x_min = ground.front().x, x_max = ground.back().x;
  double scale = std::max(1.0, x_max - x_min);
  for (const LineRead& line : lines) {
    for (const slope::Point& p : *line.points) scale = std::max(scale, std::fabs(p.y));
  }
  const double tolerance = 1e-9 * scale;

  check_line_spans(lines, x_min, x_max, tolerance, diagnostics);
  if (diagnostics.size() != errors_before) return false;
  check_ground_on_top(lines, x_min, x_max, tolerance, diagnostics);
  check_lines_do_not_cross(lines, x_min, x_max, tolerance, diagnostics);
  if (bottom_y) check_bottom(lines, *bottom_y, tolerance, section_path, diagnostics);
  return diagnostics.size() == errors_before;
}

std::optional<slope::Water> read_water(JsonReader& water, double x_min, double x_max, std::optional<double> bottom_y,
                                       bool geometry_ok) {
  Diagnostics& diagnostics = water.diagnostics();
  slope::Water result;
  std::optional<Polyline> line;
  if (const nlohmann::json* points = water.array("piezometric_line_m", Need::required, 2, limits::polyline_points,
                                                 "an array of at least two points [x_m, y_m]")) {
    line = read_polyline(*points, water.path_of("piezometric_line_m"), diagnostics);
  }
  const auto unit_weight = water.number("unit_weight_kN_m3", Need::optional);
  water.finish();
  if (!line || (water.has("unit_weight_kN_m3") && !unit_weight)) return std::nullopt;
  result.piezometric_line = *line;
  result.unit_weight = unit_weight.value_or(9.81) * kilo;
  if (!geometry_ok) return result;

  const std::string path = water.path_of("piezometric_line_m");
  const double tolerance = 1e-9 * std::max(1.0, x_max - x_min);
  if (line->front().x > x_min + tolerance || line->back().x < x_max - tolerance) {
    diagnostics.error(path, "must span the section's x range (x " + range_text(x_min, x_max) +
                                " m; it may extend beyond it), got x " + range_text(line->front().x, line->back().x) +
                                " m");
    return std::nullopt;
  }
  if (bottom_y) {
    double highest = std::max(height_at(*line, x_min), height_at(*line, x_max));
    for (const slope::Point& p : *line) {
      if (p.x > x_min && p.x < x_max) highest = std::max(highest, p.y);
    }
    if (highest <= *bottom_y) {
      diagnostics.error(path, "lies at or below bottom_y_m = " + format_number(*bottom_y) +
                                  " over the whole section, so there is no water in it (heights are elevations in m, "
                                  "not depths; leave \"water\" out for a dry slope)");
      return std::nullopt;
    }
  }
  return result;
}

std::vector<slope::Surcharge> read_surcharges(const nlohmann::json& array, const std::string& path, double x_min,
                                              double x_max, bool geometry_ok, Diagnostics& diagnostics, bool& ok) {
  std::vector<slope::Surcharge> result;
  for (std::size_t i = 0; i < array.size(); ++i) {
    JsonReader s(array[i], index_path(path, i), diagnostics);
    const auto from = s.number("from_x_m", Need::required);
    const auto to = s.number("to_x_m", Need::required);
    const auto pressure = s.number("pressure_kPa", Need::required);
    const auto pressure_end = s.number("pressure_end_kPa", Need::optional);
    s.finish();
    if (!from || !to || !pressure) {
      ok = false;
      continue;
    }
    if (!(*from < *to)) {
      diagnostics.error(s.path_of("to_x_m"), "must be greater than from_x_m (got from " + format_number(*from) +
                                                 " to " + format_number(*to) + ")");
      ok = false;
      continue;
    }
    if (geometry_ok && (*from < x_min || *to > x_max)) {
      diagnostics.error(s.path(), "must lie on the section (x " + range_text(x_min, x_max) + " m), got x " +
                                      range_text(*from, *to) + " m");
      ok = false;
      continue;
    }
    result.push_back({*from, *to, *pressure * kilo,
                      pressure_end ? std::optional<double>(*pressure_end * kilo) : std::nullopt});
  }
  return result;
}

// section.line_loads[i]: a force per metre on the ground at x_m, force_kN_m at angle_deg from the downward
// vertical (+ toward +x).
std::vector<slope::LineLoad> read_line_loads(const nlohmann::json& array, const std::string& path,
                                             const SectionExtent& extent, Diagnostics& diagnostics, bool& ok) {
  std::vector<slope::LineLoad> result;
  for (std::size_t i = 0; i < array.size(); ++i) {
    JsonReader r(array[i], index_path(path, i), diagnostics);
    const auto x = r.number("x_m", Need::required);
    const auto force = r.number("force_kN_m", Need::required);
    const double angle = r.number_or("angle_deg", 0.0);
    r.finish();
    if (!x || !force) {
      ok = false;
      continue;
    }
    if (extent.known && (*x < extent.x_min || *x > extent.x_max)) {
      diagnostics.error(r.path_of("x_m"), "must lie on the section (x " + range_text(extent.x_min, extent.x_max) +
                                               " m), got " + format_number(*x));
      ok = false;
      continue;
    }
    const double a = sphslope::radians(angle);
    result.push_back({*x, *force * kilo * std::sin(a), -*force * kilo * std::cos(a)});
  }
  return result;
}

// [min, max] with min <= max (or min < max when `strict`).
std::optional<slope::Range> read_range(JsonReader& reader, std::string_view key, bool strict) {
  const nlohmann::json* value = reader.raw(key, Need::optional);
  if (value == nullptr) return std::nullopt;
  const std::string path = reader.path_of(key);
  Diagnostics& diagnostics = reader.diagnostics();
  const auto pair = read_pair(*value, path, diagnostics, "a range [min, max]");
  if (!pair) return std::nullopt;
  if (strict ? !(pair->first < pair->second) : !(pair->first <= pair->second)) {
    diagnostics.error(path, std::string("min must be ") + (strict ? "less than" : "at most") + " max (got [" +
                                format_number(pair->first) + ", " + format_number(pair->second) + "])");
    return std::nullopt;
  }
  return slope::Range{pair->first, pair->second};
}

}  // namespace

std::optional<slope::Water> read_other_water(JsonReader& water, const slope::Section& section) {
  return read_water(water, section.x_min(), section.x_max(), section.bottom_y, true);
}

bool read_search_limits(JsonReader& search, const slope::Section* section, slope::SearchLimits& limits) {
  Diagnostics& diagnostics = search.diagnostics();
  Bounds on_ground = Bounds::any();
  std::string ground_text;
  if (section != nullptr && !section->profile_lines.empty() && !section->profile_lines[0].points.empty()) {
    const auto& ground = section->profile_lines[0].points;
    on_ground = Bounds::closed(ground.front().x, ground.back().x);
    ground_text = " (the ground surface's x range)";
  }
  for (const char* key : {"entry_x_m", "exit_x_m"}) {
    auto range = read_range(search, key, false);
    if (range && (!on_ground.contains(range->min) || !on_ground.contains(range->max))) {
      diagnostics.error(search.path_of(key), "must lie " + on_ground.describe() + ground_text + ", got [" +
                                                 format_number(range->min) + ", " + format_number(range->max) + "]");
      range.reset();
    }
    if (std::string_view(key) == "entry_x_m") {
      limits.entry_x = range;
    } else {
      limits.exit_x = range;
    }
  }
  if (auto grid = search.object("centre_grid", Need::optional,
                                "an object {\"x_m\": [min, max], \"y_m\": [min, max], \"nx\": 10, \"ny\": 10}")) {
    const auto x = read_range(*grid, "x_m", true);  // both required: the schema reports one that is missing
    const auto y = read_range(*grid, "y_m", true);
    slope::CentreGrid centre_grid;
    centre_grid.nx = static_cast<int>(grid->integer_or("nx", centre_grid.nx));  // an invalid count is reported
    centre_grid.ny = static_cast<int>(grid->integer_or("ny", centre_grid.ny));  // already: the scene is refused
    grid->finish();
    if (x && y) {
      centre_grid.x = *x;
      centre_grid.y = *y;
      limits.centre_grid = centre_grid;
    }
  }
  limits.radius = read_range(search, "radius_m", false);
  return search.has("entry_x_m") || search.has("exit_x_m") || search.has("centre_grid") || search.has("radius_m");
}

std::optional<double> read_minimum_depth(JsonReader& search) {
  return search.number("minimum_depth_m", Need::optional);
}

namespace {

// The names of section.materials, for the profile lines that refer to them.
struct MaterialNames {
  std::map<std::string, std::size_t> index;
  std::vector<std::string> names;  // in the order defined, for messages
};

// Materials first: profile lines refer to them by name.
MaterialNames read_section_materials(JsonReader& section, std::vector<SoilMaterial>& materials_out,
                                     Diagnostics& diagnostics) {
  MaterialNames known;
  const nlohmann::json* materials =
      section.array("materials", Need::required, 1, limits::materials, "an array of materials");
  if (!materials) return known;
  std::map<std::string, std::string> first_path;
  for (std::size_t i = 0; i < materials->size(); ++i) {
    JsonReader m((*materials)[i], index_path(section.path_of("materials"), i), diagnostics);
    auto material = read_material(m, MaterialOf::section);
    if (!material) {
      // Keep the name (if readable) so profile lines naming it do not report a second, misleading error.
      if (m.is_object() && (*materials)[i].contains("name") && (*materials)[i]["name"].is_string()) {
        known.index.emplace((*materials)[i]["name"].get<std::string>(), materials_out.size());
        known.names.push_back((*materials)[i]["name"].get<std::string>());
        materials_out.emplace_back();
      }
      continue;
    }
    const auto [it, inserted] = first_path.emplace(material->name, m.path());
    if (!inserted) {
      diagnostics.error(m.path_of("name"), "duplicate material name \"" + material->name + "\" (already used by " +
                                               it->second + "; names must be unique)");
      continue;
    }
    known.index.emplace(material->name, materials_out.size());
    known.names.push_back(material->name);
    materials_out.push_back(std::move(*material));
  }
  return known;
}

LineRead read_profile_line(const nlohmann::json& entry, std::string path, JsonReader& section,
                           const MaterialNames& known, Diagnostics& diagnostics) {
  LineRead line;
  line.path = std::move(path);
  JsonReader l(entry, line.path, diagnostics);
  if (const auto name = l.string("material", Need::required)) {
    const auto it = known.index.find(*name);
    if (it != known.index.end()) {
      line.material = it->second;
    } else if (!known.index.empty() || section.has("materials")) {
      std::string defined;
      for (const std::string& n : known.names) defined += (defined.empty() ? "" : ", ") + n;
      const std::string suggestion = closest_match(*name, known.names);
      diagnostics.error(l.path_of("material"),
                        "unknown material \"" + *name + "\" (" +
                            (suggestion.empty() ? "" : "did you mean \"" + suggestion + "\"? ") +
                            "defined in section.materials: " + (defined.empty() ? "none" : defined) + ")");
    }
  }
  if (const nlohmann::json* points = l.array("points_m", Need::required, 2, limits::polyline_points,
                                             "an array of at least two points [x_m, y_m]")) {
    line.points = read_polyline(*points, l.path_of("points_m"), diagnostics);
  }
  l.finish();
  return line;
}

// section.profile_lines; returns whether every line has its material and points.
bool read_profile_lines(JsonReader& section, const MaterialNames& known, std::vector<LineRead>& lines,
                        Diagnostics& diagnostics) {
  const nlohmann::json* profile = section.array("profile_lines", Need::required, 1, limits::profile_lines,
                                                "an array of profile lines, the ground surface first");
  if (!profile) return false;
  bool lines_ok = true;
  for (std::size_t i = 0; i < profile->size(); ++i) {
    LineRead line =
        read_profile_line((*profile)[i], index_path(section.path_of("profile_lines"), i), section, known, diagnostics);
    if (!line.material || !line.points) lines_ok = false;
    lines.push_back(std::move(line));
  }
  return lines_ok;
}

// Water, surcharges, reinforcement and the seismic coefficient; their positions are checked against the section's
// x range only when the geometry is valid.
void read_section_loads(JsonReader& section, const SectionExtent& extent, std::optional<double> bottom_y,
                        slope::Section& out, Diagnostics& diagnostics) {
  const double x_min = extent.x_min, x_max = extent.x_max;
  const bool geometry_ok = extent.known;
  if (auto water = section.object("water", Need::optional,
                                  "an object {\"piezometric_line_m\": [[x, y], ...], \"unit_weight_kN_m3\": 9.81}")) {
    out.water = read_water(*water, x_min, x_max, bottom_y, geometry_ok);
  }
  bool surcharges_ok = true;
  if (const nlohmann::json* surcharges = section.array("surcharges", Need::optional, 0, limits::surcharges)) {
    out.surcharges = read_surcharges(*surcharges, section.path_of("surcharges"), x_min, x_max, geometry_ok, diagnostics,
                                     surcharges_ok);
  }
  if (const nlohmann::json* elements = section.array("reinforcement", Need::optional, 0, limits::reinforcement)) {
    bool reinforcement_ok = true;
    out.reinforcement = read_reinforcement(*elements, section.path_of("reinforcement"), extent, diagnostics,
                                           reinforcement_ok);
  }
  if (const nlohmann::json* loads = section.array("line_loads", Need::optional, 0, limits::line_loads)) {
    bool line_loads_ok = true;
    out.line_loads = read_line_loads(*loads, section.path_of("line_loads"), extent, diagnostics, line_loads_ok);
  }
  if (auto seismic = section.object("seismic", Need::optional, "an object {\"horizontal_coefficient\": 0.1}")) {
    const auto kh = seismic->number("horizontal_coefficient", Need::optional);
    const auto kv = seismic->number("vertical_coefficient", Need::optional);
    if (!kh && !kv && seismic->is_object())
      diagnostics.error(seismic->path(), "give horizontal_coefficient (0 <= kh < 1), vertical_coefficient "
                                         "(-1 < kv < 1, + upward) or both");
    out.seismic_coefficient = kh.value_or(0.0);
    out.vertical_seismic_coefficient = kv.value_or(0.0);
    seismic->finish();
  }
}

}  // namespace

std::optional<SceneSection> read_section(JsonReader& section, Diagnostics& diagnostics) {
  const std::size_t errors_before = diagnostics.size();
  SceneSection result;

  const auto bottom_y = section.number("bottom_y_m", Need::required);
  const MaterialNames known = read_section_materials(section, result.materials, diagnostics);
  std::vector<LineRead> lines;
  const bool lines_ok = read_profile_lines(section, known, lines, diagnostics);

  // Geometry checks need every line's points.
  bool geometry_ok = lines_ok && !lines.empty();
  if (geometry_ok) {
    for (const LineRead& line : lines) geometry_ok = geometry_ok && line.points.has_value();
  }
  if (geometry_ok) geometry_ok = check_profile_geometry(lines, bottom_y, section.path(), diagnostics) && bottom_y;

  double x_min = 0.0, x_max = 0.0;
  if (geometry_ok) {
    x_min = lines[0].points->front().x;
    x_max = lines[0].points->back().x;
  }
  SectionExtent extent{geometry_ok, x_min, x_max, 0};
  if (geometry_ok) {
    const double left = lines[0].points->front().y, right = lines[0].points->back().y;
    extent.into_slope = left > right ? -1 : (left < right ? 1 : 0);
  }
  read_section_loads(section, extent, bottom_y, result.section, diagnostics);
  if (diagnostics.size() != errors_before || !geometry_ok) return std::nullopt;

  result.section.bottom_y = *bottom_y;
  for (const SoilMaterial& m : result.materials) {
    result.section.materials.push_back(
        slope::Material{m.name, m.unit_weight, m.cohesion, m.friction_angle, m.pore_pressure_ratio, m.cohesion_rate,
                        m.cohesion_datum_y, m.cohesion_max, m.saturated_unit_weight, m.envelope});
  }
  for (const LineRead& line : lines) {
    result.section.profile_lines.push_back(slope::ProfileLine{*line.material, *line.points});
  }
  return result;
}

}  // namespace coupling
