// bodies[i].fill (docs/scene-format.md, "Particle scenes"): a body filled in rows keeps a slanted face smooth (every
// particle next to it dx/2 inside it) and nearly its polygon's area, where the lattice fill makes a staircase of it;
// a fill the reader does not know, and a rows fill of too many vertices, are refused with the JSON path.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/analyses/sph_model.hpp"
#include "coupling/scene/scene.hpp"
#include "sph/engine/fill.hpp"

namespace test_body_fill {

namespace {

constexpr double dx = 0.02;

// Heinrich's block (a right triangle, legs 0.5 m, its hypotenuse at 45 deg) as the body of a particle scene.
nlohmann::json triangle_scene(const char* fill) {
  nlohmann::json scene = nlohmann::json::parse(R"({"format": "sphslope-scene/1", "name": "triangle",
      "bodies": [{"name": "block", "polygon_m": [[0.01, 0.99], [0.51, 0.99], [0.51, 0.49]],
                  "material": {"name": "stiff", "unit_weight_kN_m3": 19.62, "cohesion_kPa": 30,
                               "friction_angle_deg": 30, "youngs_modulus_MPa": 10, "poisson_ratio": 0.3}}],
      "analyses": {"sph": {"particle_spacing_m": 0.02, "end_time_s": 1}}})");
  if (fill) scene["bodies"][0]["fill"] = fill;
  return scene;
}

struct FillFigures {
  std::size_t particles = 0;
  double area_ratio = 0;                      // particles x dx^2 over the polygon's area
  double nearest_min = 0, nearest_max = 0;  // distances of the particles next to the hypotenuse from it [m]
};

FillFigures fill_figures(const char* fill) {
  const coupling::Scene scene = coupling::parse_scene(triangle_scene(fill).dump());
  const sph::soil::Model model = coupling::build_sph_model(scene);
  FillFigures f;
  f.nearest_min = 1e9;
  for (std::size_t i = 0; i < model.particles.size(); ++i) {
    ++f.particles;
    // the distance from the hypotenuse x + y = 1 (inside: x + y > 1), for the particles within dx of it and 4 dx
    // or more from its ends (where the rows of the other faces meet it)
    const double x = model.particles.x[i], d = (x + model.particles.y[i] - 1.0) / std::sqrt(2.0);
    if (d < dx && x > 0.01 + 4 * dx && x < 0.51 - 4 * dx) f.nearest_min = std::min(f.nearest_min, d), f.nearest_max = std::max(f.nearest_max, d);
  }
  f.area_ratio = static_cast<double>(f.particles) * dx * dx / 0.125;
  std::printf("%s fill: %zu particles, %.3f of the polygon's area; next to the 45 deg face at %.4f to %.4f m "
              "(dx/2 = %.4f)\n",
              fill ? fill : "lattice (default)", f.particles, f.area_ratio, f.nearest_min, f.nearest_max, 0.5 * dx);
  return f;
}

}  // namespace

TEST_CASE("scene: a body filled in rows keeps its slanted face dx/2 inside and nearly its area", "[scene][fill]") {
  const FillFigures rows = fill_figures("rows"), lattice = fill_figures(nullptr);
  // rows: the first row on the face, every particle there at dx/2
  CHECK(rows.nearest_min == Approx(0.5 * dx).margin(1e-9));
  CHECK(rows.nearest_max == Approx(0.5 * dx).margin(1e-9));
  // the lattice's staircase puts them anywhere from the face to dx from it
  CHECK(lattice.nearest_max - lattice.nearest_min > 0.25 * dx);
  // the rows lose a little where the rows of two faces meet (the lattice's staircase, not cleared from a solid
  // here, holds about the area)
  CHECK(rows.area_ratio > 0.95);
  CHECK(rows.area_ratio <= 1.0);
}

TEST_CASE("scene: an unknown fill, or rows over too many vertices, is refused with its path", "[scene][fill]") {
  CHECK_THROWS_WITH(coupling::parse_scene(triangle_scene("grid").dump()),
                    Catch::Contains("bodies[0].fill") && Catch::Contains("lattice") && Catch::Contains("rows"));
  nlohmann::json scene = triangle_scene("rows");
  nlohmann::json polygon = nlohmann::json::array();
  // a circle of 1001 vertices
  for (int k = 0; k < 1001; ++k) {
    const double a = 2.0 * 3.141592653589793 * k / 1001.0;
    polygon.push_back({0.5 + 0.2 * std::cos(a), 0.5 + 0.2 * std::sin(a)});
  }
  scene["bodies"][0]["polygon_m"] = polygon;
  CHECK_THROWS_WITH(coupling::parse_scene(scene.dump()),
                    Catch::Contains("bodies[0].fill") && Catch::Contains("at most 1000 vertices"));
  polygon.erase(polygon.begin());
  scene["bodies"][0]["polygon_m"] = polygon;
  CHECK_NOTHROW(coupling::parse_scene(scene.dump()));
}

}  // namespace test_body_fill
