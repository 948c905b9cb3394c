// analyses.coupled: the checks a coupled scene needs beyond those of analyses.sph and analyses.isph
// (docs/scene-format.md, "analyses.coupled").
#include "coupling/scene/coupled_analysis.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "coupling/scene/scene.hpp"
#include "sph/engine/fill.hpp"

namespace coupling {

namespace {

constexpr const char* kPath = "analyses.coupled";

// What the two blocks must agree on: one lattice (the soil's surface is the water's wall particle by particle) and
// one clock.
void check_agreement(const SphAnalysis& soil, const IsphAnalysis& water, Diagnostics& diagnostics) {
  const double dx_soil = soil.settings.particle_spacing, dx_water = water.settings.particle_spacing;
  if (dx_soil != dx_water)
    diagnostics.error("analyses.isph.particle_spacing_m",
                      format_number(dx_water) + " m must equal analyses.sph.particle_spacing_m = " +
                          format_number(dx_soil) + " m in a coupled run (each soil particle is a wall particle of "
                          "the water's, on one lattice)");
  if (soil.settings.end_time != water.settings.end_time)
    diagnostics.error("analyses.isph.end_time_s", format_number(water.settings.end_time) +
                                                      " s must equal analyses.sph.end_time_s = " +
                                                      format_number(soil.settings.end_time) +
                                                      " s in a coupled run (one clock for both)");
  if (soil.settings.gravity_mode == sph::GravityMode::ramped)
    diagnostics.error("analyses.sph.gravity", "\"ramped\" is not allowed in a coupled run: the water has full gravity "
                                              "from the start (use \"sudden\" or \"geostatic_k0\")");
  if (water.bed_slope != 0.0)
    diagnostics.error("analyses.isph.bed_slope_percent", "must be 0 in a coupled run (the soil's gravity is vertical)");
  if (!water.bodies.empty())
    diagnostics.error("analyses.isph.bodies", "not yet in a coupled run: the soil does not see rigid bodies");
}

// Keys of analyses.sph that the water's block governs in a coupled run, refused rather than left unused.
void check_soil_keys(const nlohmann::json& sph, Diagnostics& diagnostics) {
  const struct {
    const char* key;
    const char* why;
  } governed[] = {
      {"output_interval_s", "frames and energy rows of a coupled run come every analyses.isph.output_interval_s"},
      {"stop_below_speed_m_s", "a coupled run runs to its end time"},
      {"stop_below_speed_after_s", "a coupled run runs to its end time"},
  };
  for (const auto& g : governed)
    if (sph.contains(g.key)) diagnostics.error(join_path("analyses.sph", g.key), std::string("not used in a coupled run: ") + g.why);
}

void check_bodies_inside_tank(const std::vector<ParticleBody>& bodies, const Tank& tank, Diagnostics& diagnostics) {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (std::size_t k = 0; k < bodies[i].polygon.size(); ++k) {
      const auto& p = bodies[i].polygon[k];
      if (p.x < tank.x_min - 1e-9 || p.x > tank.x_max + 1e-9 || p.y < tank.y_min - 1e-9 ||
          p.y > tank.y_min + tank.height + 1e-9)
        diagnostics.error(index_path(join_path(index_path("bodies", i), "polygon_m"), k),
                          "point (" + format_number(p.x) + ", " + format_number(p.y) +
                              ") lies outside the tank analyses.isph.tank (x " + format_number(tank.x_min) + " to " +
                              format_number(tank.x_max) + " m, y " + format_number(tank.y_min) + " to " +
                              format_number(tank.y_min + tank.height) + " m), the walls of a coupled run");
    }
}

// The water's solids are the soil's walls too: a body whose lattice points fall inside one is a mistake (the soil
// is cleared from the solids' faces by dx/2, as the water is, but not from their insides).
void check_bodies_clear_of_solids(const std::vector<ParticleBody>& bodies, const IsphAnalysis& water,
                                  Diagnostics& diagnostics) {
  const double dx = water.settings.particle_spacing;
  // the bodies' lattice is anchored at the first body's lower-left corner (a coupled scene has no wall box)
  sph::Point anchor{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (const auto& p : bodies.front().polygon) anchor = {std::min(anchor.x, p.x), std::min(anchor.y, p.y)};
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const auto points = body_fill_points(bodies[i], dx, anchor);
    for (std::size_t k = 0; k < water.solids.size(); ++k) {
      const auto& solid = water.solids[k].polygon;
      const bool inside = std::any_of(points.begin(), points.end(), [&](const sph::Point& q) {
        return sph::point_in_polygon(solid, q.x, q.y) && sph::distance_to_polygon_edges(solid, q.x, q.y) > 0.5 * dx;
      });
      if (inside)
        diagnostics.error(index_path("bodies", i),
                          "\"" + bodies[i].name + "\" overlaps analyses.isph.solids[" + std::to_string(k) + "] (\"" +
                              water.solids[k].name + "\"), a wall of the soil and the water: a body may rest on a "
                              "solid's face, not reach into it");
    }
  }
}

// The water fills its rectangles around the soil (as around the water's solids); a rectangle with no lattice point
// outside the soil is a mistake.
void check_water_outside_soil(const std::vector<ParticleBody>& bodies, const IsphAnalysis& water,
                              Diagnostics& diagnostics) {
  const double dx = water.settings.particle_spacing;
  std::vector<std::vector<sph::Point>> polygons;
  for (const ParticleBody& b : bodies) {
    polygons.emplace_back();
    for (const auto& p : b.polygon) polygons.back().push_back({p.x, p.y});
  }
  for (std::size_t k = 0; k < water.water.size(); ++k) {
    const TankRectangle& r = water.water[k];
    const auto free = sph::lattice_points_in_region(r.x_min, r.y_min, r.x_max, r.y_max, dx, [&](double x, double y) {
      for (const auto& polygon : polygons)
        if (sph::point_in_polygon(polygon, x, y)) return false;
      return true;
    });
    if (free.empty())
      diagnostics.error(index_path("analyses.isph.water", k),
                        "lies entirely inside the soil bodies: the water fills its rectangles around the soil, and "
                        "this one keeps no water");
  }
}

}  // namespace

void read_coupled_scene(const nlohmann::json& block, const nlohmann::json* sph, const nlohmann::json* walls,
                        Scene& scene, Diagnostics& diagnostics) {
  JsonReader reader(block, kPath, diagnostics);
  CoupledAnalysis coupled;
  if (auto impact = reader.object("impact", Need::optional)) {
    SlideImpactSetup setup;
    setup.ramp_angle_deg = impact->number("ramp_angle_deg", Need::required, Bounds{0.0, false, 90.0, true}).value_or(0);
    setup.shoreline_x = impact->number("shoreline_x_m", Need::required).value_or(0);
    impact->finish();
    coupled.impact = setup;
    if (scene.analyses.isph && scene.analyses.isph->monitors.gauges.size() < 2)
      diagnostics.error(join_path(kPath, "impact"), "needs at least two gauges in analyses.isph.monitors.gauges (the "
                                                    "largest crest and the leading crest's celerity are read from them)");
  }
  reader.finish();
  scene.analyses.coupled = coupled;
  if (!sph) diagnostics.error(kPath, "needs analyses.sph, the soil's settings (the soil is the top-level \"bodies\")");
  if (!scene.analyses.isph) diagnostics.error(kPath, "needs analyses.isph, the water and its tank");
  if (scene.section)
    diagnostics.error("section", "a coupled run's soil is the top-level \"bodies\" (a slope section is not yet "
                                 "supported there)");
  else if (!scene.body_count)
    diagnostics.error(kPath, "needs the top-level \"bodies\", the soil");
  if (walls)
    diagnostics.error("walls", "a coupled run's walls are its tank, analyses.isph.tank (remove \"walls\")");
  if (sph) check_soil_keys(*sph, diagnostics);
  if (!scene.analyses.sph || !scene.analyses.isph) return;
  const IsphAnalysis& water = *scene.analyses.isph;
  check_agreement(*scene.analyses.sph, water, diagnostics);
  if (!scene.bodies) return;
  check_bodies_inside_tank(*scene.bodies, water.tank, diagnostics);
  check_water_outside_soil(*scene.bodies, water, diagnostics);
  check_bodies_clear_of_solids(*scene.bodies, water, diagnostics);
  if (!walls) scene.walls = WallBox{water.tank.x_min, water.tank.x_max, water.tank.y_min, water.tank.height, {}};
}

}  // namespace coupling
