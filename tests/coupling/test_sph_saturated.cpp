// The SPH soil model carries a material's saturated unit weight (section.materials[i].saturated_unit_weight_kN_m3):
// particles below the piezometric line get the saturated density, and the K0 geostatic state is the closed form of
// the effective vertical stress in a layer whose soil is heavier below the water table.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include <nlohmann/json.hpp>

#include "coupling/analyses/sph_model.hpp"
#include "coupling/scene/scene.hpp"
#include "sph/soil/run.hpp"
#include "sph/soil/soil_step.hpp"

namespace test_sph_saturated {

namespace {

constexpr double gamma = 18e3, gamma_sat = 21e3, gamma_w = 9810.0, g = 9.81;
constexpr double ground = 10.0, table = 6.0;  // m

// Level ground at y = 10 over a base at y = 0, the water table at y = 6, one material heavier below it.
nlohmann::json level_scene(bool ignore_water) {
  nlohmann::json scene = {
      {"format", "sphslope-scene/1"},
      {"name", "level layer with a saturated unit weight below the water table"},
      {"section",
       {{"bottom_y_m", 0},
        {"profile_lines", {{{"material", "soil"}, {"points_m", {{0, ground}, {20, ground}}}}}},
        {"materials",
         {{{"name", "soil"},
           {"unit_weight_kN_m3", gamma / 1e3},
           {"saturated_unit_weight_kN_m3", gamma_sat / 1e3},
           {"cohesion_kPa", 10},
           {"friction_angle_deg", 30},
           {"youngs_modulus_MPa", 20},
           {"poisson_ratio", 0.3}}}},
        {"water", {{"piezometric_line_m", {{0, table}, {20, table}}}}}}},
      {"analyses",
       {{"sph", {{"particle_spacing_m", 0.5}, {"end_time_s", 0.5}, {"gravity", "geostatic_k0"}}}}}};
  if (ignore_water) scene["analyses"]["sph"]["ignore_loads"] = {"water"};
  return scene;
}

// The largest displacement of a soil particle from its start (m).
double largest_displacement(const sph::soil::Model& m) {
  double largest = 0.0;
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if (m.particles.kind[i] == static_cast<std::uint8_t>(sph::ParticleKind::material))
      largest = std::max(largest, std::hypot(m.particles.x[i] - m.particles.x0[i], m.particles.y[i] - m.particles.y0[i]));
  return largest;
}

}  // namespace

TEST_CASE("SPH: particles below the water table weigh the saturated unit weight, the K0 state is the closed form "
          "and at rest", "[sph][loads][water]") {
  const coupling::Scene scene = coupling::parse_scene(level_scene(false).dump());
  CHECK(coupling::loads_sph_leaves_out(scene).empty());
  sph::soil::Model model = coupling::build_sph_model(scene);
  const sph::ParticleSet& p = model.particles;
  int below = 0, above = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != static_cast<std::uint8_t>(sph::ParticleKind::material)) continue;
    const bool wet = p.y[i] < table;
    CHECK(p.rho[i] == (wet ? gamma_sat : gamma) / g);
    (wet ? below : above) += 1;
  }
  CHECK(below == 40 * 12);
  CHECK(above == 40 * 8);

  // sigma'_yy at a particle's depth: gamma (10 - y) above the table; gamma 4 + (gamma_sat - gamma_w) (6 - y) below
  // it (the lattice's cells end on the table: the column sums are exact).
  {
    sph::soil::SoilStep step(model);
    step.initialise();
  }
  const auto soil = model.soil();
  double worst = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != static_cast<std::uint8_t>(sph::ParticleKind::material)) continue;
    const double y = p.y[i];
    const double exact = y >= table ? -gamma * (ground - y)
                                    : -(gamma * (ground - table) + (gamma_sat - gamma_w) * (table - y));
    worst = std::max(worst, std::fabs(soil.syy[i] - exact) / (gamma * ground));
  }
  INFO("largest difference from the closed form: " << worst << " of gamma H");
  CHECK(worst < 1e-9);

  // Over 0.5 s the layer behaves as the same layer drawn as two materials of those unit weights, the lower one
  // below the table: the same largest displacement within 10 % (the lattice's settling from its K0 state where the
  // density steps: 2.3 mm, against 1.0 mm with one unit weight) and the same sigma'_yy within 1 % of gamma H.
  nlohmann::json layered = level_scene(false);
  nlohmann::json upper = layered["section"]["materials"][0];
  upper.erase("saturated_unit_weight_kN_m3");
  nlohmann::json lower = upper;
  lower["name"] = "lower";
  lower["unit_weight_kN_m3"] = gamma_sat / 1e3;
  layered["section"]["materials"] = {upper, lower};
  layered["section"]["profile_lines"].push_back({{"material", "lower"}, {"points_m", {{0, table}, {20, table}}}});
  sph::soil::Model reference = coupling::build_sph_model(coupling::parse_scene(layered.dump()));
  REQUIRE(sph::soil::run(model, {}).stopped_because == "end_time");
  REQUIRE(sph::soil::run(reference, {}).stopped_because == "end_time");
  const double moved = largest_displacement(model), moved_layered = largest_displacement(reference);
  INFO("largest displacement " << moved << " m, drawn as two layers " << moved_layered << " m");
  CHECK(std::fabs(moved - moved_layered) < 0.1 * moved_layered);
  const auto layered_soil = reference.soil();
  REQUIRE(reference.particles.size() == p.size());
  std::map<std::uint32_t, std::size_t> index_of;
  for (std::size_t j = 0; j < reference.particles.size(); ++j) index_of[reference.particles.id[j]] = j;
  double stress_difference = 0.0;
  int compared = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != static_cast<std::uint8_t>(sph::ParticleKind::material)) continue;
    stress_difference = std::max(stress_difference, std::fabs(soil.syy[i] - layered_soil.syy[index_of.at(p.id[i])]));
    ++compared;
  }
  INFO("largest difference of sigma'_yy " << stress_difference << " Pa over " << compared << " particles");
  CHECK(compared == 800);
  CHECK(stress_difference < 0.01 * gamma * ground);

  // Without the water the SPH run has one density, and says so.
  const coupling::Scene dry = coupling::parse_scene(level_scene(true).dump());
  const sph::soil::Model dry_model = coupling::build_sph_model(dry);
  for (std::size_t i = 0; i < dry_model.particles.size(); ++i)
    if (dry_model.particles.kind[i] == static_cast<std::uint8_t>(sph::ParticleKind::material))
      CHECK(dry_model.particles.rho[i] == gamma / g);
  const auto left_out = coupling::loads_sph_leaves_out(dry);
  REQUIRE(left_out.size() == 2);
  CHECK(left_out[1].path == "section.materials[0].saturated_unit_weight_kN_m3");
}

}  // namespace test_sph_saturated
