// The tank, rectangles and monitors of the particle-flow analyses (coupling/scene/tank_scene.hpp).
#include "coupling/scene/tank_scene.hpp"

#include <set>

namespace coupling {

namespace {

constexpr SizeLimit rectangles_limit{100, "rectangles", "each rectangle is filled with particles"};
constexpr SizeLimit gauges_limit{100, "gauges", "each gauge is one column of monitors.csv"};

}  // namespace

void read_tank(JsonReader& r, Tank& tank) {
  auto t = r.object("tank", Need::required, "an object {x_min_m, x_max_m, y_min_m, height_m}");
  if (!t) return;
  tank.x_min = t->number_or("x_min_m", 0.0);
  tank.y_min = t->number_or("y_min_m", 0.0);
  if (auto v = t->number("x_max_m", Need::required)) tank.x_max = *v;
  if (auto v = t->number("height_m", Need::required)) tank.height = *v;
  if (tank.x_max <= tank.x_min) t->diagnostics().error(t->path_of("x_max_m"), "must be larger than x_min_m");
  t->finish();
}

void read_tank_rectangles(JsonReader& r, const char* key, const Tank& tank, std::vector<TankRectangle>& out,
                          const std::function<void(JsonReader&)>& extra) {
  const nlohmann::json* blocks = r.array(key, Need::required, 1, rectangles_limit, "an array of rectangles");
  if (!blocks) return;
  for (std::size_t k = 0; k < blocks->size(); ++k) {
    JsonReader b((*blocks)[k], index_path(r.path_of(key), k), r.diagnostics());
    auto x0 = b.number("x_min_m", Need::required), y0 = b.number("y_min_m", Need::required);
    auto x1 = b.number("x_max_m", Need::required), y1 = b.number("y_max_m", Need::required);
    if (x0 && y0 && x1 && y1) {
      const TankRectangle w{*x0, *y0, *x1, *y1};
      if (w.x_max <= w.x_min || w.y_max <= w.y_min)
        b.diagnostics().error(b.path(), "an empty rectangle (x_max_m must exceed x_min_m, y_max_m y_min_m)");
      else if (w.x_min < tank.x_min || w.x_max > tank.x_max || w.y_min < tank.y_min ||
               w.y_max > tank.y_min + tank.height)
        b.diagnostics().error(b.path(), "the rectangle must lie inside the tank (x " + format_number(tank.x_min) +
                                            " to " + format_number(tank.x_max) + " m, y " +
                                            format_number(tank.y_min) + " to " +
                                            format_number(tank.y_min + tank.height) + " m)");
      out.push_back(w);
      if (extra) extra(b);
    }
    b.finish();
  }
}

void read_times(JsonReader& r, const char* key, Need need, std::optional<double> end_time, const SizeLimit& limit,
                std::vector<double>& out) {
  const nlohmann::json* times = r.array(key, need, 1, limit);
  if (!times) return;
  const Bounds bounds = end_time ? Bounds{0.0, false, *end_time, true} : Bounds::any();  // > 0: the schema's
  for (std::size_t k = 0; k < times->size(); ++k) {
    const std::string path = index_path(r.path_of(key), k);
    const auto t = read_number((*times)[k], path, r.diagnostics(), bounds);
    if (!t) continue;
    if (!out.empty() && *t <= out.back())
      r.diagnostics().error(path, "times must increase (got " + format_number(*t) + " after " +
                                      format_number(out.back()) + ")");
    out.push_back(*t);
  }
}

void read_tank_monitors(JsonReader& r, TankMonitors& a, bool allow_wall_height) {
  auto m = r.object("monitors", Need::optional,
                    allow_wall_height ? "an object {gauges, front, wall_height, still_water_m, interval_s}"
                                      : "an object {gauges, front, still_water_m, interval_s}");
  if (!m) return;
  a.front = m->boolean("front", Need::optional).value_or(false);
  if (allow_wall_height) a.wall_height = m->boolean("wall_height", Need::optional).value_or(false);
  a.still_water = m->number_or("still_water_m", 0.0);
  a.interval = m->number_or("interval_s", a.interval);
  std::set<std::string> names;
  if (const nlohmann::json* gauges = m->array("gauges", Need::optional, 0, gauges_limit)) {
    for (std::size_t k = 0; k < gauges->size(); ++k) {
      JsonReader g((*gauges)[k], index_path(m->path_of("gauges"), k), m->diagnostics());
      auto name = g.string("name", Need::required);
      auto x = g.number("x_m", Need::required);
      if (name && !names.insert(*name).second) g.diagnostics().error(g.path_of("name"), "used twice");
      if (name && x) a.gauges.push_back({*name, *x});
      g.finish();
    }
  }
  m->finish();
}

}  // namespace coupling
