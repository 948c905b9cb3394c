// analyses.isph's geometry beyond the tank: bed_slope_percent, solids, bodies and the domain (docs/scene-format.md).
#include <cmath>
#include <limits>
#include <string>

#include "coupling/scene/input_limits.hpp"
#include "coupling/scene/isph_analysis.hpp"
#include "scene_internal.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

constexpr double kMaxBedSlopePercent = 20.0;  // a steeper bed is a slope: model it as a solid

// Every vertex inside the tank (its inner faces, up to its top).
void check_inside_tank(JsonReader& r, const char* key, const std::vector<sph::Point>& polygon, const Tank& tank) {
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const sph::Point& p = polygon[k];
    if (p.x < tank.x_min || p.x > tank.x_max || p.y < tank.y_min || p.y > tank.y_min + tank.height) {
      r.diagnostics().error(index_path(r.path_of(key), k),
                            "the point (" + format_number(p.x) + ", " + format_number(p.y) +
                                ") m is outside the tank (x in [" + format_number(tank.x_min) + ", " +
                                format_number(tank.x_max) + "] m, y in [" + format_number(tank.y_min) + ", " +
                                format_number(tank.y_min + tank.height) + "] m)");
      return;
    }
  }
}

bool read_polygon_in_tank(JsonReader& r, const Tank& tank, const char* what, std::vector<sph::Point>& out) {
  const auto polygon = read_simple_polygon(r, "polygon_m", what);
  if (!polygon) return false;
  for (const auto& [x, y] : *polygon) out.push_back({x, y});
  check_inside_tank(r, "polygon_m", out, tank);
  return true;
}

// bodies[i].motion: {law: "free"} | {law: "ln_cosh", initial_acceleration_m_s2, terminal_speed_m_s} |
// {law: "table", time_s: [...], travel_m: [...]}.
void read_motion(JsonReader& m, sph::fluid::RigidBody& body) {
  using Motion = sph::fluid::RigidBody::Motion;
  if (!m.has("law")) {
    m.string("law", Need::required);  // reports the missing key
    return;
  }
  const std::size_t errors = m.diagnostics().size();
  read_named(m, "law", sph::fluid::motion_law_names, body.motion);
  if (m.diagnostics().size() != errors) return;
  if (body.motion == Motion::free) {
    // gravity and the fluid's force: nothing more to read
  } else if (body.motion == Motion::ln_cosh) {
    body.initial_acceleration = m.number("initial_acceleration_m_s2", Need::required).value_or(0);
    body.terminal_speed = m.number("terminal_speed_m_s", Need::required).value_or(0);
  } else {  // Motion::table
    const nlohmann::json* t = m.array("time_s", Need::required, 2, limits::polyline_points);
    const nlohmann::json* s = m.array("travel_m", Need::required, 2, limits::polyline_points);
    if (!t || !s) return;
    if (t->size() != s->size()) {
      m.diagnostics().error(m.path_of("travel_m"), "expected as many travels as times (" +
                                                       std::to_string(t->size()) + "), got " +
                                                       std::to_string(s->size()));
      return;
    }
    for (std::size_t k = 0; k < t->size(); ++k) {
      const auto tk = read_number((*t)[k], index_path(m.path_of("time_s"), k), m.diagnostics());
      const auto sk = read_number((*s)[k], index_path(m.path_of("travel_m"), k), m.diagnostics());
      if (!tk || !sk) return;
      if (!body.table_time.empty() && !(*tk > body.table_time.back())) {
        m.diagnostics().error(index_path(m.path_of("time_s"), k), "the times must increase");
        return;
      }
      body.table_time.push_back(*tk);
      body.table_travel.push_back(*sk);
    }
  }
}

}  // namespace

void read_isph_geometry(JsonReader& isph, IsphAnalysis& a) {
  const double percent = isph.number_or("bed_slope_percent", 0.0);
  a.bed_slope = percent / 100.0;
  const double theta = std::atan(a.bed_slope);
  a.settings.gravity_x = sphslope::standard_gravity * std::sin(theta);
  a.settings.gravity_y = -sphslope::standard_gravity * std::cos(theta);
  if (const nlohmann::json* solids = isph.array("solids", Need::optional, 1, limits::solids,
                                                "an array of solids {\"name\", \"polygon_m\"}")) {
    for (std::size_t i = 0; i < solids->size(); ++i) {
      JsonReader s((*solids)[i], index_path(isph.path_of("solids"), i), isph.diagnostics());
      IsphSolid solid;
      solid.name = s.string("name", Need::optional).value_or("solid " + std::to_string(i));
      if (read_polygon_in_tank(s, a.tank, "a solid", solid.polygon)) a.solids.push_back(std::move(solid));
      s.finish();
    }
  }
  const nlohmann::json* bodies = isph.array("bodies", Need::optional, 1, limits::bodies,
                                            "an array of rigid bodies {\"name\", \"polygon_m\", \"motion\", ...}");
  if (!bodies) return;
  for (std::size_t i = 0; i < bodies->size(); ++i) {
    JsonReader b((*bodies)[i], index_path(isph.path_of("bodies"), i), isph.diagnostics());
    IsphBody body;
    body.name = b.string("name", Need::optional).value_or("body " + std::to_string(i));
    const bool polygon = read_polygon_in_tank(b, a.tank, "a body", body.polygon);
    body.body.density = b.number_or("density_kg_m3", body.body.density);
    const double direction = b.number("direction_deg", Need::required).value_or(0.0);
    body.body.direction_x = std::cos(direction * sphslope::degree);
    body.body.direction_y = std::sin(direction * sphslope::degree);
    body.body.stop_travel =
        b.number_or("stop_after_m", std::numeric_limits<double>::infinity());
    body.body.start_time = b.number_or("start_time_s", 0.0);
    if (auto m = b.object("motion", Need::required)) {
      read_motion(*m, body.body);
      m->finish();
    }
    b.finish();
    if (polygon) a.bodies.push_back(std::move(body));
  }
}

}  // namespace coupling
