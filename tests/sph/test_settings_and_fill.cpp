// Settings validation, memory estimate, lattice fill and wall construction.
#include <catch2/catch.hpp>

#include <cmath>

#include "sph/engine/fill.hpp"
#include "sph/soil/model.hpp"

namespace test_settings_and_fill {

TEST_CASE("invalid settings are refused with a message naming the setting", "[sph][settings]") {
  sph::soil::Settings s;
  s.particle_spacing = 0.01;
  CHECK_NOTHROW(s.validate());
  s.h_over_dx = 0;
  CHECK_THROWS_WITH(s.validate(), Catch::Contains("h_over_dx"));
  s.h_over_dx = 1.2;
  s.particle_spacing = -1;
  CHECK_THROWS_WITH(s.validate(), Catch::Contains("particle_spacing"));
  s.particle_spacing = 0.01;
  s.cfl = 2;
  CHECK_THROWS_WITH(s.validate(), Catch::Contains("cfl"));
  sph::soil::Material m;
  m.poisson_ratio = 0.5;
  CHECK_THROWS_WITH(m.validate(), Catch::Contains("poisson_ratio"));
}

TEST_CASE("memory estimate grows linearly and is sensible", "[sph][settings]") {
  const auto a = sph::soil::estimate_memory_bytes(100000), b = sph::soil::estimate_memory_bytes(200000);
  CHECK(b > a);
  CHECK(a > 100000 * 200);    // at least the state arrays
  CHECK(a < 100000 * 2000);   // and not absurd
}

TEST_CASE("polygon fill is cell-centred and walls cover the kernel support", "[sph][fill]") {
  // thesis slope 2 (seed-002 section 4.2): 20 m base, 10 m high, 45 deg face, 10 m crest at dx = 0.2 m -> 3725
  const std::vector<sph::Point> section{{0, 0}, {20, 0}, {10, 10}, {0, 10}};
  const auto pts = sph::lattice_points_in_polygon(section, 0.2);
  CHECK(pts.size() == 3725);
  sph::ParticleSet p;
  const double dx = 0.1, h = 0.13;
  sph::BoxWalls box;
  box.x_min = 0; box.x_max = 1; box.y_min = 0; box.height = 0.5;
  const auto n = sph::add_box_walls(p, box, dx, h, 0, 2000);
  const int layers = sph::wall_layers_for(dx, h);
  CHECK(layers == 3);
  // bottom: (10 + 2*3) * 3 ; sides: 5 rows * 3 layers * 2
  CHECK(n == static_cast<std::size_t>((10 + 2 * layers) * layers + 5 * layers * 2));
  const auto& normal_x = p.field(*p.find_field("wall_normal_x"));
  const auto& normal_y = p.field(*p.find_field("wall_normal_y"));
  for (std::size_t i = 0; i < p.size(); ++i) {
    CHECK(std::hypot(normal_x[i], normal_y[i]) == Approx(1.0));
    CHECK(p.mass[i] == Approx(2000 * dx * dx));
  }
}

TEST_CASE("time-step estimate equals the stepper's bound at rest", "[sph][settings]") {
  sph::soil::Model m;
  m.materials.push_back(sph::soil::Material{});
  m.settings.particle_spacing = 0.1;
  sph::add_soil(m.particles, sph::lattice_points_in_region(0, 0, 1, 1, 0.1, [](double, double) { return true; }), 0.1, 0,
                m.materials[0].density);
  const double c = sph::soil::MaterialConstants::from(m.materials[0]).sound_speed;
  // the default cfl 0.8 (Verlet), h = 1.2 dx, alpha = 0.1
  CHECK(sph::soil::time_step_estimate(m) == Approx(0.8 * 0.12 / (c * 1.12)).epsilon(1e-12));
  m.settings.use_integration(sph::soil::TimeIntegration::predictor_corrector);
  CHECK(sph::soil::time_step_estimate(m) == Approx(0.2 * 0.12 / (c * 1.12)).epsilon(1e-12));
}

}  // namespace test_settings_and_fill
