// The seed paper's ISPH cases run from cases/ through the sphslope program at a coarse spacing: the dam break on a
// dry bed against Ritter's solution, and the waves of Heinrich's (1992) submarine and aerial landslides (a rigid
// block sliding down a 45-degree slope into the water). docs/isph.md section 8 gives the finer runs.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace test_isph_cases {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json case_scene(const std::string& name) { return read_json(fs::path(test_paths::source_dir()) / "cases" / name); }

// Runs the scene (written into the folder) and returns report.json's isph block, after the checks every run of
// these cases must pass: exit 0, to the end time, the fluid's mass kept (none left the tank).
json run_case(const TemporaryFolder& folder, const std::string& stem, const json& scene) {
  const fs::path file = folder.path / (stem + ".json");
  std::ofstream(file) << scene.dump(1);
  const fs::path out = folder.path / stem;
  const ProgramRun run = run_sphslope("run '" + file.string() + "' -o '" + out.string() + "'");
  INFO(run.output);
  REQUIRE(run.status == 0);
  const json isph = read_json(out / "report.json")["isph"];
  CHECK(isph["stopped_because"] == "end_time");
  CHECK(isph["fluid_removed"]["particles"] == 0);
  CHECK(isph["fluid_mass_kg_per_m"]["end"].get<double>() ==
        Approx(isph["fluid_mass_kg_per_m"]["start"].get<double>()).epsilon(1e-12));
  CHECK(isph["fluid_past_walls"]["most"] == 0);
  return isph;
}

}  // namespace

// The seed's dam break (cases/isph_dam_break_ritter.json) at dx = 12.5 mm (8 particles deep) to 0.6 s. Reference:
// Ritter's (1892) dry-bed solution, with these bounds: the
// front's mean speed over the later half of the run between 0.6 and 1.0 times Ritter's 2 sqrt(g h0) (friction at
// the bed and at the tip slow a real front; faster would be a defect), and the depth at the dam within 10 % of
// 4 h0/9 for T >= 2; the front's position follows X = 2T closely in shape (r > 0.99).
TEST_CASE("ISPH dam break of the seed paper against Ritter's solution (coarse)", "[cli][isph][validation]") {
  TemporaryFolder folder("isph-ritter");
  json scene = case_scene("isph_dam_break_ritter.json");
  json& isph = scene["analyses"]["isph"];
  isph["particle_spacing_m"] = 0.0125;
  isph["end_time_s"] = 0.6;
  isph["output_interval_s"] = 0.0;
  isph["snapshots_s"] = json::array({0.5});
  const json r = run_case(folder, "ritter", scene);
  const json& ritter = r["ritter"];
  INFO(ritter.dump(1));
  CHECK(ritter["front_speed_ratio"].get<double>() > 0.6);
  CHECK(ritter["front_speed_ratio"].get<double>() < 1.0);
  CHECK(ritter["dam_depth_ratio"].get<double>() == Approx(1.0).margin(0.10));
  CHECK(ritter["dam_depth_points"].get<int>() >= 10);
  CHECK(ritter["front_X_against_2T"]["r"].get<double>() > 0.99);
  CHECK(ritter["front_X_against_2T"]["points"].get<int>() >= 20);
}

namespace {

// Heinrich's flume shortened to 8 m at dx = 0.05 m, gauges at 2, 4 and 6 m from the shoreline, to `end` s.
json coarse_heinrich(const std::string& name, double end) {
  json scene = case_scene(name);
  json& isph = scene["analyses"]["isph"];
  isph["particle_spacing_m"] = 0.05;
  isph["end_time_s"] = end;
  isph["output_interval_s"] = 0.0;
  isph["snapshots_s"] = json::array({1.0});
  isph["tank"]["x_max_m"] = 8.0;
  isph["water"][0]["x_max_m"] = 8.0;
  isph["monitors"]["gauges"] = json::array({{{"name", "x2"}, {"x_m", 2.0}}, {{"name", "x4"}, {"x_m", 4.0}},
                                            {{"name", "x6"}, {"x_m", 6.0}}});
  return scene;
}

// What any landslide run must show: the block stopped where told (at the slope's foot), the water gained no more
// energy than the block's work on it and kept a good part of it (the rest dissipated by viscosity and the scheme),
// and the leading crest travelled between the gauges at the long-wave celerity sqrt(g d), within `celerity_band`.
void check_landslide(const json& r, double stop_travel, double lo, double hi) {
  INFO(r["bodies"].dump(1) << "\n" << r["energy_J_per_m"].dump(1) << "\n" << r["waves"].dump(1));
  const json& block = r["bodies"][0];
  CHECK(block["travel_m"].get<double>() == Approx(stop_travel).epsilon(1e-9));
  CHECK(block["stopped_at_s"].is_number());
  CHECK(block["speed_end_m_s"].get<double>() == 0.0);
  const double gain = r["energy_J_per_m"]["fluid_gain"].get<double>();
  const double work = r["energy_J_per_m"]["work_by_bodies_on_fluid"].get<double>();
  CHECK(work > 0);
  CHECK(gain <= work);
  CHECK(gain > 0.3 * work);
  const json& celerity = r["waves"]["leading_crest_celerity"];
  REQUIRE(celerity.size() >= 1);
  for (const json& c : celerity) {
    CHECK(c["ratio_to_sqrt_g_d"].get<double>() > lo);
    CHECK(c["ratio_to_sqrt_g_d"].get<double>() < hi);
  }
}

}  // namespace

// The submarine case (d = 1 m, block top 1 cm below the water). No measured series is openly available (seed A14,
// A16), so the test checks the physics that can be checked: the
// block's stop, the energy budget and the leading crest's celerity against sqrt(g d) = 3.13 m/s (linear long-wave
// theory: 10 % would be usual; the crest's height a adds about a/2d, 1-2 % here, and 15 % allows the coarse
// spacing's dispersion).
TEST_CASE("ISPH submarine landslide (Heinrich 1992 geometry, coarse): stop, energy budget, wave celerity",
          "[cli][isph][validation]") {
  TemporaryFolder folder("isph-heinrich-submarine");
  const json r = run_case(folder, "submarine", coarse_heinrich("isph_heinrich_submarine.json", 2.6));
  check_landslide(r, 0.692965, 0.85, 1.15);  // stop_after_m of the case (0.49 m √2: the block's toe at the slope's foot)
}

// The aerial case (d = 0.4 m, the block above the water). Its leading crest is high (a/d about 0.3): a solitary-like
// crest travels at about sqrt(g (d + a)), 14 % above sqrt(g d), hence the wider upper bound.
TEST_CASE("ISPH aerial landslide (Heinrich 1992 geometry, coarse): stop, energy budget, wave celerity",
          "[cli][isph][validation]") {
  TemporaryFolder folder("isph-heinrich-aerial");
  const json r = run_case(folder, "aerial", coarse_heinrich("isph_heinrich_aerial.json", 3.5));
  check_landslide(r, 0.565685, 0.85, 1.3);  // stop_after_m of the case (0.4 m √2)
}

}  // namespace test_isph_cases
