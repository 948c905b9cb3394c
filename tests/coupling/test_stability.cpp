// The scene keys of the stability matrix's features (the gravity ramp, the wall layers, the particles across a body),
// read and validated with their JSON paths. The matrix's cases themselves (cases/stability) run through the program
// in the `stability: ...` tests of tests/CMakeLists.txt, whose verdicts are scripts/stability_matrix.py's, the one
// source of them (docs/stability.md).
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/analyses/sph_model.hpp"
#include "coupling/scene/scene.hpp"
#include "test_support.hpp"

namespace test_stability {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

fs::path case_file(const std::string& stem) { return fs::path(test_paths::source_dir()) / "cases/stability" / (stem + ".json"); }

}  // namespace

// ---- scene keys of the matrix's features ----

TEST_CASE("scene: the walls' friction angle comes with the frictional wall condition only", "[stability][scene]") {
  json scene = read_json(case_file("sph_gravity_ramped"));
  json& walls = scene["analyses"]["sph"]["walls"];
  walls["slip"] = "frictional";
  walls["friction_angle_deg"] = 25;
  const coupling::Scene read = coupling::parse_scene(scene.dump(), "scene.json");
  CHECK(read.analyses.sph->settings.wall_slip == sph::soil::WallSlip::frictional);
  CHECK(read.analyses.sph->settings.wall_friction_angle_deg == 25.0);
  walls.erase("friction_angle_deg");
  CHECK(scene_faults(scene).find("analyses.sph.walls.friction_angle_deg: is required with \"slip\": \"frictional\"") !=
        std::string::npos);
  walls["friction_angle_deg"] = 90;
  CHECK(scene_faults(scene).find("analyses.sph.walls.friction_angle_deg: must be in [0, 90) (got 90)") != std::string::npos);
  walls["friction_angle_deg"] = 20;
  walls["slip"] = "free_slip";
  CHECK(scene_faults(scene).find("analyses.sph.walls.friction_angle_deg: is used only with \"slip\": \"frictional\"") !=
        std::string::npos);
}

TEST_CASE("stability: gravity ramp and wall layers are read and validated with their JSON paths", "[stability][scene]") {
  json scene = read_json(case_file("sph_gravity_ramped"));
  auto errors_of = [](const json& document) {
    try {
      coupling::parse_scene(document.dump(), "scene.json");
    } catch (const coupling::SceneError& error) {
      std::string all;
      for (const auto& m : error.messages()) all += m + "\n";
      return all;
    }
    return std::string();
  };
  auto settings_of = [](const json& document) {
    const coupling::Scene s = coupling::parse_scene(document.dump(), "scene.json");
    return *s.analyses.sph;
  };
  CHECK(settings_of(scene).settings.gravity_mode == sph::GravityMode::ramped);
  CHECK(settings_of(scene).settings.gravity_ramp_time == 2.0);
  scene["analyses"]["sph"].erase("gravity_ramp_s");
  CHECK(settings_of(scene).settings.gravity_ramp_time == Approx(0.4));  // default: 10 % of end_time_s = 4 s
  scene["analyses"]["sph"]["gravity_ramp_s"] = 5;
  CHECK(errors_of(scene).find("analyses.sph.gravity_ramp_s: 5 s is longer than end_time_s") != std::string::npos);
  scene["analyses"]["sph"]["gravity"] = "sudden";
  scene["analyses"]["sph"]["gravity_ramp_s"] = 1;
  CHECK(errors_of(scene).find("analyses.sph.gravity_ramp_s: is only used with \"gravity\": \"ramped\"") !=
        std::string::npos);
  scene["analyses"]["sph"].erase("gravity_ramp_s");
  scene["analyses"]["sph"]["gravity"] = "gradual";
  CHECK(errors_of(scene).find("allowed: sudden, geostatic_k0, ramped") != std::string::npos);
  scene["analyses"]["sph"]["gravity"] = "sudden";
  CHECK(settings_of(scene).wall_layers == 3);  // h = 1.2 dx: ceil(2.4)
  scene["analyses"]["sph"]["walls"] = {{"layers", 4}};
  CHECK(settings_of(scene).wall_layers == 4);
  coupling::SphSize thick, normal;
  coupling::build_sph_model(coupling::parse_scene(scene.dump(), "scene.json"), &thick);
  scene["analyses"]["sph"]["walls"] = {{"layers", 3}};
  coupling::build_sph_model(coupling::parse_scene(scene.dump(), "scene.json"), &normal);
  CHECK(thick.wall_particles > normal.wall_particles);
  scene["analyses"]["sph"]["walls"] = {{"layers", 2.5}};
  CHECK(errors_of(scene).find("analyses.sph.walls.layers") != std::string::npos);
  scene["analyses"]["sph"]["walls"] = {{"layers", 3}};
  scene["analyses"]["sph"]["cfl"] = 1.7;  // the Verlet step accepts (0, 1.6]: refused at the scene, not at run time
  CHECK(errors_of(scene).find("analyses.sph.cfl") != std::string::npos);
  scene["analyses"]["sph"]["cfl"] = 0.8;  // the predictor-corrector accepts (0, 0.5]
  scene["analyses"]["sph"]["time_integration"] = "predictor_corrector";
  CHECK(errors_of(scene).find("analyses.sph.cfl") != std::string::npos);
}

TEST_CASE("stability: a particle body with fewer than 4 particles across is refused like a section",
          "[stability][scene]") {
  // The column of Bui et al. (2008) is 0.1 m high: 0.03 m leaves 3.3 particles across.
  json scene = read_json(fs::path(test_paths::source_dir()) / "cases/bui2008_column_collapse.json");
  scene["analyses"]["sph"]["particle_spacing_m"] = 0.03;
  std::string message;
  try {
    coupling::parse_scene(scene.dump(), "column.json");
  } catch (const coupling::SceneError& error) {
    message = error.messages().front();
  }
  CHECK(message.find("analyses.sph.particle_spacing_m: spacing 0.03 m leaves fewer than 4 particles across "
                     "bodies[0]") != std::string::npos);
  CHECK(message.find("at most 0.025 m") != std::string::npos);
  scene["analyses"]["sph"]["particle_spacing_m"] = 0.025;  // exactly 4 across: accepted
  CHECK_NOTHROW(coupling::parse_scene(scene.dump(), "column.json"));
}

}  // namespace test_stability
