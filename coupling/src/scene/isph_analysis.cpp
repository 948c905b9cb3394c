// analyses.isph: settings, tank, water blocks and monitors of the ISPH fluid (docs/scene-format.md).
#include "coupling/scene/isph_analysis.hpp"

#include <cmath>
#include <exception>
#include <set>

namespace coupling {

namespace {

constexpr SizeLimit water_blocks{100, "water blocks", "each block is filled with particles"};
constexpr SizeLimit gauges_limit{100, "gauges", "each gauge is one column of monitors.csv"};

void read_numerics(JsonReader& r, sph::fluid::Settings& s) {
  if (auto v = r.number("particle_spacing_m", Need::required, Bounds::positive())) s.particle_spacing = *v;
  if (auto v = r.number("end_time_s", Need::required, Bounds::positive())) s.end_time = *v;
  s.h_over_dx = r.number_or("h_over_dx", s.h_over_dx,
                            Bounds::closed(sph::EngineSettings::h_over_dx_min, sph::EngineSettings::h_over_dx_max));
  s.output_interval = r.number_or("output_interval_s", s.output_interval, Bounds::non_negative());
  s.rest_density = r.number_or("rest_density_kg_m3", s.rest_density, Bounds::positive());
  s.viscosity = r.number_or("viscosity_Pa_s", s.viscosity, Bounds::non_negative());
  s.surface_beta = r.number_or("surface_beta", s.surface_beta, Bounds::open(0.0, 1.0));
  s.cfl = r.number_or("cfl", s.cfl, Bounds{0.0, false, sph::fluid::Settings::max_cfl, true});
  s.max_time_step = r.number_or("max_time_step_s", s.max_time_step, Bounds::non_negative());
  s.solver_tolerance = r.number_or("solver_tolerance", s.solver_tolerance, Bounds::open(0.0, 1.0));
  if (auto mode = r.string("pressure", Need::optional)) {
    try {
      s.pressure_mode = sph::fluid::pressure_mode_from(*mode);
    } catch (const std::exception&) {
      r.diagnostics().error(r.path_of("pressure"), "expected \"explicit\" or \"iterative\", got \"" + *mode + "\"");
    }
  }
  if (auto solver = r.string("solver", Need::optional)) {
    try {
      s.solver = sph::fluid::linear_solver_from(*solver);
    } catch (const std::exception&) {
      r.diagnostics().error(r.path_of("solver"), "expected \"cg\" or \"bicgstab\", got \"" + *solver + "\"");
    }
  }
  s.wall_layers = static_cast<int>(std::ceil(2.0 * s.h_over_dx - 1e-9));
}

void read_tank(JsonReader& r, IsphTank& tank) {
  auto t = r.object("tank", Need::required, "an object {x_min_m, x_max_m, y_min_m, height_m}");
  if (!t) return;
  tank.x_min = t->number_or("x_min_m", 0.0);
  tank.y_min = t->number_or("y_min_m", 0.0);
  if (auto v = t->number("x_max_m", Need::required)) tank.x_max = *v;
  if (auto v = t->number("height_m", Need::required, Bounds::positive())) tank.height = *v;
  if (tank.x_max <= tank.x_min) t->diagnostics().error(t->path_of("x_max_m"), "must be larger than x_min_m");
  t->finish();
}

void read_water(JsonReader& r, const IsphTank& tank, std::vector<IsphRectangle>& water) {
  const nlohmann::json* blocks = r.array("water", Need::required, 1, water_blocks, "an array of rectangles");
  if (!blocks) return;
  for (std::size_t k = 0; k < blocks->size(); ++k) {
    JsonReader b((*blocks)[k], index_path(r.path_of("water"), k), r.diagnostics());
    IsphRectangle w;
    auto x0 = b.number("x_min_m", Need::required), y0 = b.number("y_min_m", Need::required);
    auto x1 = b.number("x_max_m", Need::required), y1 = b.number("y_max_m", Need::required);
    if (x0 && y0 && x1 && y1) {
      w = {*x0, *y0, *x1, *y1};
      if (w.x_max <= w.x_min || w.y_max <= w.y_min)
        b.diagnostics().error(b.path(), "an empty rectangle (x_max_m must exceed x_min_m, y_max_m y_min_m)");
      else if (w.x_min < tank.x_min || w.x_max > tank.x_max || w.y_min < tank.y_min ||
               w.y_max > tank.y_min + tank.height)
        b.diagnostics().error(b.path(), "the water must lie inside the tank");
      water.push_back(w);
    }
    b.finish();
  }
}

void read_monitors(JsonReader& r, IsphAnalysis& a) {
  auto m = r.object("monitors", Need::optional, "an object {gauges, front, still_water_m, interval_s}");
  if (!m) return;
  a.front = m->boolean("front", Need::optional).value_or(false);
  a.still_water = m->number_or("still_water_m", 0.0);
  a.monitor_interval = m->number_or("interval_s", a.monitor_interval, Bounds::positive());
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

}  // namespace

IsphAnalysis read_isph_analysis(JsonReader& isph) {
  IsphAnalysis a;
  read_numerics(isph, a.settings);
  read_tank(isph, a.tank);
  read_water(isph, a.tank, a.water);
  read_monitors(isph, a);
  isph.finish();
  try {
    a.settings.validate();
  } catch (const std::exception& error) {
    isph.diagnostics().error(isph.path(), error.what());
  }
  return a;
}

}  // namespace coupling
