// Scene loading in-process: SI conversion, defaults, what is accepted, errors collected with their JSON paths,
// the report builder.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "coupling/scene/json_reader.hpp"
#include "coupling/output/report.hpp"
#include "coupling/output/run_files.hpp"
#include "coupling/scene/scene.hpp"
#include "coupling/analyses/pipeline.hpp"
#include "coupling/analyses/sph_model.hpp"
#include "sph/fluid/model.hpp"
#include "sph/mps/settings.hpp"
#include "sph/soil/model.hpp"

namespace test_scene_loader {

namespace fs = std::filesystem;
using coupling::parse_scene;
using coupling::Scene;
using coupling::SceneError;
using nlohmann::json;

namespace {

constexpr double degree = std::numbers::pi / 180.0;

// The scene format's full example (docs/scene-format.md), complete.
json example_scene() {
  return json::parse(R"({
    "format": "sphslope-scene/1",
    "name": "Homogeneous 2:1 slope",
    "source": "the scene format's full example",
    "notes": {"anything": ["goes", 1, null]},
    "section": {
      "bottom_y_m": 0.0,
      "profile_lines": [
        { "material": "upper", "points_m": [[0, 20], [20, 20], [40, 10], [60, 10]] },
        { "material": "lower", "points_m": [[0, 15], [60, 15]] }
      ],
      "materials": [
        { "name": "upper", "unit_weight_kN_m3": 20, "cohesion_kPa": 10, "friction_angle_deg": 20,
          "dilatancy_angle_deg": 0, "youngs_modulus_MPa": 50, "poisson_ratio": 0.3 },
        { "name": "lower", "unit_weight_kN_m3": 18, "cohesion_kPa": 5, "friction_angle_deg": 10 }
      ],
      "water": { "piezometric_line_m": [[0, 18], [60, 9]], "unit_weight_kN_m3": 9.81 },
      "surcharges": [ { "from_x_m": 2, "to_x_m": 10, "pressure_kPa": 20 } ],
      "seismic": { "horizontal_coefficient": 0.0 }
    },
    "analyses": {
      "lem": { "methods": ["ordinary", "bishop", "janbu", "spencer", "morgenstern_price"] }
    }
  })");
}

// The lower line of the example crosses the ground surface between x = 20 and 40 (the ground goes down to 10),
// so the valid variant used here keeps it below: at 8 m.
json valid_example() {
  json scene = example_scene();
  scene["section"]["profile_lines"][1]["points_m"] = json::parse("[[0, 8], [60, 8]]");
  return scene;
}

Scene load(const json& document, const fs::path& file = "scenes/example.json") {
  return parse_scene(document.dump(), file);
}

std::vector<std::string> errors_of(const json& document) {
  try {
    load(document);
  } catch (const SceneError& error) {
    return error.messages();
  }
  return {};
}

bool mentions(const std::vector<std::string>& errors, const std::string& text) {
  for (const std::string& e : errors) {
    if (e.find(text) != std::string::npos) return true;
  }
  return false;
}

std::string all(const std::vector<std::string>& errors) {
  std::string out;
  for (const std::string& e : errors) out += e + "\n";
  return out;
}

}  // namespace

TEST_CASE("scene: units are converted to SI once", "[scene]") {
  const Scene scene = load(valid_example());
  REQUIRE(scene.section);
  const slope::Section& s = scene.section->section;
  CHECK(scene.name == "Homogeneous 2:1 slope");
  CHECK(scene.source == "the scene format's full example");
  CHECK(s.bottom_y == 0.0);
  REQUIRE(s.materials.size() == 2);
  CHECK(s.materials[0].name == "upper");
  CHECK(s.materials[0].unit_weight == Approx(20000.0));        // kN/m^3 -> N/m^3
  CHECK(s.materials[0].cohesion == Approx(10000.0));           // kPa -> Pa
  CHECK(s.materials[0].friction_angle == Approx(20 * degree)); // deg -> rad
  CHECK(s.materials[1].unit_weight == Approx(18000.0));
  CHECK(s.materials[1].cohesion == Approx(5000.0));
  CHECK(s.materials[1].friction_angle == Approx(10 * degree));

  const coupling::SoilMaterial& upper = scene.section->materials[0];
  REQUIRE(upper.youngs_modulus);
  CHECK(*upper.youngs_modulus == Approx(50e6));                // MPa -> Pa
  CHECK(*upper.poisson_ratio == Approx(0.3));
  CHECK(*upper.dilatancy_angle == Approx(0.0));
  CHECK(upper.density() == Approx(20000.0 / 9.81));            // kg/m^3
  CHECK_FALSE(scene.section->materials[1].youngs_modulus);

  REQUIRE(s.profile_lines.size() == 2);
  CHECK(s.profile_lines[0].material == 0);
  CHECK(s.profile_lines[1].material == 1);
  REQUIRE(s.profile_lines[0].points.size() == 4);
  CHECK(s.profile_lines[0].points[2].x == 40.0);
  CHECK(s.profile_lines[0].points[2].y == 10.0);

  REQUIRE(s.water);
  CHECK(s.water->unit_weight == Approx(9810.0));
  CHECK(s.water->piezometric_line.size() == 2);
  REQUIRE(s.surcharges.size() == 1);
  CHECK(s.surcharges[0].from_x == 2.0);
  CHECK(s.surcharges[0].to_x == 10.0);
  CHECK(s.surcharges[0].pressure == Approx(20000.0));
  CHECK(s.seismic_coefficient == 0.0);

  REQUIRE(scene.analyses.lem);
  const auto& methods = scene.analyses.lem->methods;
  REQUIRE(methods.size() == 5);
  CHECK(methods[0] == slope::Method::ordinary);
  CHECK(methods[4] == slope::Method::morgenstern_price);
  CHECK_FALSE(scene.analyses.sph);
}

TEST_CASE("scene: defaults are applied", "[scene]") {
  json document = valid_example();
  document.erase("name");
  document["section"]["water"].erase("unit_weight_kN_m3");
  document["section"].erase("seismic");
  document["section"].erase("surcharges");
  document["analyses"]["lem"] = json::object();
  const Scene scene = load(document, "somewhere/my_slope.json");
  CHECK(scene.name == "my_slope");  // the file stem
  CHECK(scene.file == fs::path("somewhere/my_slope.json"));
  const slope::Section& s = scene.section->section;
  CHECK(s.water->unit_weight == Approx(9810.0));
  CHECK(s.seismic_coefficient == 0.0);
  CHECK(s.surcharges.empty());
  REQUIRE(scene.analyses.lem);
  CHECK(scene.analyses.lem->methods == slope::all_methods());
  CHECK(scene.analyses.lem->methods.size() == 7);
  CHECK(scene.analyses.lem->search.slicing.slices == 50);
  CHECK(scene.analyses.lem->search.refine == true);
  CHECK_FALSE(scene.analyses.lem->has_search_limits);
  CHECK_FALSE(scene.analyses.lem->search.limits.entry_x);
  CHECK_FALSE(scene.analyses.lem->search.limits.exit_x);
  CHECK_FALSE(scene.analyses.lem->search.limits.centre_grid);
  CHECK_FALSE(scene.analyses.lem->search.limits.radius);
  CHECK(scene.analyses.lem->search.minimum_depth < 0.0);  // automatic
}

TEST_CASE("scene: LEM options and search limits are read", "[scene]") {
  json document = valid_example();
  document["section"]["seismic"]["horizontal_coefficient"] = 0.15;
  document["analyses"]["lem"] = json::parse(R"({
    "methods": ["spencer"], "slices": 30, "refine": false,
    "search": { "entry_x_m": [2, 18], "exit_x_m": [38, 50],
                "centre_grid": { "x_m": [25, 45], "y_m": [22, 40], "nx": 8 }, "radius_m": [10, 40],
                "minimum_depth_m": 0.5 } })");
  const Scene scene = load(document);
  const coupling::LemAnalysis& lem = *scene.analyses.lem;
  CHECK(scene.section->section.seismic_coefficient == Approx(0.15));
  CHECK(lem.methods == std::vector<slope::Method>{slope::Method::spencer});
  CHECK(lem.search.slicing.slices == 30);
  CHECK(lem.search.refine == false);
  CHECK(lem.has_search_limits);
  REQUIRE(lem.search.limits.entry_x);
  CHECK(lem.search.limits.entry_x->min == 2.0);
  CHECK(lem.search.limits.entry_x->max == 18.0);
  CHECK(lem.search.limits.exit_x->min == 38.0);
  REQUIRE(lem.search.limits.centre_grid);
  CHECK(lem.search.limits.centre_grid->x.max == 45.0);
  CHECK(lem.search.limits.centre_grid->y.min == 22.0);
  CHECK(lem.search.limits.centre_grid->nx == 8);
  CHECK(lem.search.limits.centre_grid->ny == 10);  // default
  CHECK(lem.search.limits.radius->max == 40.0);
  CHECK(lem.search.minimum_depth == 0.5);
}

TEST_CASE("scene: what is accepted", "[scene]") {
  SECTION("water above the ground surface (ponding)") {
    json document = valid_example();
    document["section"]["water"]["piezometric_line_m"] = json::parse("[[0, 18], [40, 14], [60, 14]]");
    CHECK_NOTHROW(load(document));
  }
  SECTION("a piezometric line extending beyond the section") {
    json document = valid_example();
    document["section"]["water"]["piezometric_line_m"] = json::parse("[[-10, 18], [70, 9]]");
    CHECK_NOTHROW(load(document));
  }
  SECTION("a piezometric line partly below the bottom") {
    json document = valid_example();
    document["section"]["water"]["piezometric_line_m"] = json::parse("[[0, 5], [60, -3]]");
    CHECK_NOTHROW(load(document));
  }
  SECTION("profile lines that touch each other and the bottom") {
    json document = valid_example();
    document["section"]["profile_lines"][1]["points_m"] = json::parse("[[0, 8], [40, 10], [50, 0], [60, 0]]");
    CHECK_NOTHROW(load(document));
  }
  SECTION("a particle scene: bodies and walls instead of a section") {
    json document = json::parse(R"({"format": "sphslope-scene/1", "name": "column",
        "bodies": [{"name": "column", "polygon_m": [[0, 0], [0.2, 0], [0.2, 0.1], [0, 0.1]],
                    "material": {"name": "bars", "unit_weight_kN_m3": 26, "cohesion_kPa": 0,
                                 "friction_angle_deg": 19.8, "youngs_modulus_MPa": 0.84, "poisson_ratio": 0.3}}],
        "walls": {"x_range_m": [0, 0.6], "bottom_y_m": 0, "height_m": 0.12, "sides": ["left", "bottom"]},
        "analyses": {"sph": {"particle_spacing_m": 0.005, "end_time_s": 1}}})");
    const Scene scene = load(document);
    CHECK_FALSE(scene.section);
    REQUIRE(scene.bodies);
    REQUIRE(scene.walls);
    REQUIRE(scene.analyses.sph);
    CHECK(scene.analyses.sph->settings.end_time == 1);
    // The SPH stage validates the bodies and walls at load time: a body kind it does not know is an error.
    document["bodies"][0]["kind"] = "water";
    CHECK_THROWS_AS(load(document), SceneError);
  }
  SECTION("an sph block with the elastic constants, and compare kept raw") {
    json document = valid_example();
    document["section"]["materials"][1]["youngs_modulus_MPa"] = 20;
    document["section"]["materials"][1]["poisson_ratio"] = 0.25;
    // the example section has water and a surcharge, which SPH may only leave out when told to
    document["analyses"]["sph"] =
        json::parse(R"({"particle_spacing_m": 0.5, "end_time_s": 2, "ignore_loads": ["water", "surcharges"]})");
    document["analyses"]["compare"] = json::parse(R"({"plastic_strain_threshold": 0.1})");
    const Scene scene = load(document);
    REQUIRE(scene.analyses.sph);
    CHECK(scene.analyses.sph->settings.particle_spacing == 0.5);
    REQUIRE(scene.analyses.compare);
    CHECK(*scene.section->materials[1].youngs_modulus == Approx(20e6));
  }
  SECTION("notes in any object") {
    json document = valid_example();
    document["section"]["notes"] = "about the section";
    document["section"]["materials"][0]["notes"] = {{"lab", "triaxial"}};
    CHECK_NOTHROW(load(document));
  }
  SECTION("whole numbers written as 10.0 for counts") {
    json document = valid_example();
    document["analyses"]["lem"]["slices"] = 40.0;
    CHECK(load(document).analyses.lem->search.slicing.slices == 40);
  }
}

TEST_CASE("scene: every fault is reported at once, each with its JSON path", "[scene]") {
  json document = valid_example();
  document["section"]["materials"][0]["unit_weight_kN_m3"] = -1;
  document["section"]["materials"][1]["friction_angle_deg"] = 95;
  document["section"]["surcharges"][0]["pressure_kPa"] = -3;
  document["analyses"]["lem"]["methods"] = json::parse(R"(["bishop", "fellenius"])");
  document["analyses"]["lem"]["refine"] = "yes";
  document["extra"] = 1;
  const auto errors = errors_of(document);
  INFO(all(errors));
  CHECK(errors.size() == 6);
  CHECK(mentions(errors, "section.materials[0].unit_weight_kN_m3: must be > 0 (got -1)"));
  CHECK(mentions(errors, "section.materials[1].friction_angle_deg: must be in [0, 90) (got 95)"));
  CHECK(mentions(errors, "section.surcharges[0].pressure_kPa: must be >= 0 (got -3)"));
  CHECK(mentions(errors, "analyses.lem.methods[1]: unknown method \"fellenius\""));
  CHECK(mentions(errors, "analyses.lem.refine: expected true or false, got a string \"yes\""));
  CHECK(mentions(errors, "extra: unknown key (allowed here: format, name, source, section, bodies, walls, analyses)"));
}

TEST_CASE("scene: geometry faults", "[scene]") {
  SECTION("the lower line of the format's full example, taken literally, rises above the ground surface") {
    const auto errors = errors_of(example_scene());
    INFO(all(errors));
    REQUIRE(errors.size() == 1);
    CHECK(mentions(errors, "section.profile_lines[1]: rises above the ground surface (profile_lines[0]) at x = 40"));
  }
  SECTION("a single line that doubles back is reported at the offending point") {
    json document = valid_example();
    document["section"]["profile_lines"][0]["points_m"] = json::parse("[[0, 20], [20, 20], [20, 10], [60, 10]]");
    const auto errors = errors_of(document);
    INFO(all(errors));
    CHECK(mentions(errors, "section.profile_lines[0].points_m[2]: x must increase (got 20 after 20"));
  }
  SECTION("a point that is not a pair") {
    json document = valid_example();
    document["section"]["profile_lines"][0]["points_m"][1] = json::parse("[20, 20, 5]");
    const auto errors = errors_of(document);
    INFO(all(errors));
    CHECK(mentions(errors, "section.profile_lines[0].points_m[1]: expected a point [x_m, y_m]"));
  }
  SECTION("no soil above the bottom") {
    json document = valid_example();
    document["section"]["profile_lines"] = json::parse(R"([{"material": "upper", "points_m": [[0, 0], [60, 0]]}])");
    const auto errors = errors_of(document);
    INFO(all(errors));
    CHECK(mentions(errors, "section.bottom_y_m: must be below the ground surface"));
  }
  SECTION("a surcharge reaching beyond the section") {
    json document = valid_example();
    document["section"]["surcharges"][0]["to_x_m"] = 61;
    CHECK(mentions(errors_of(document), "section.surcharges[0]: must lie on the section (x 0 to 60 m)"));
  }
}

TEST_CASE("scene: SPH carries the section loads, and ignore_loads leaves one out only if the section has it",
          "[scene][sph]") {
  // docs/scene-format.md, analyses.sph.ignore_loads: SPH carries water, surcharges and k_h like limit equilibrium;
  // the user may leave one out on purpose (the report then warns), never one the section does not have.
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases/two_layer_water.json"));
  scene["section"]["seismic"]["horizontal_coefficient"] = 0.1;
  scene["analyses"]["sph"] = {{"particle_spacing_m", 1.0}, {"end_time_s", 1.0}};
  CHECK(coupling::loads_sph_leaves_out(parse_scene(scene.dump())).empty());
  scene["analyses"]["sph"]["ignore_loads"] = {"water", "seismic"};
  const auto left_out = coupling::loads_sph_leaves_out(parse_scene(scene.dump()));
  REQUIRE(left_out.size() == 2);
  CHECK(left_out[0].path == "section.water");
  CHECK(left_out[1].path == "section.seismic");
  // a material's r_u has no SPH counterpart: always left out, named by its path, without being listed
  scene["section"]["materials"][1]["pore_pressure_ratio"] = 0.2;
  const auto with_ru = coupling::loads_sph_leaves_out(parse_scene(scene.dump()));
  REQUIRE(with_ru.size() == 3);
  CHECK(with_ru[2].path == "section.materials[1].pore_pressure_ratio");
  CHECK_THAT(with_ru[2].name, Catch::Contains("r_u = 0.2"));
  CHECK_THAT(with_ru[2].why, Catch::Contains("piezometric line only"));
  CHECK(parse_scene(scene.dump()).section->section.materials[1].pore_pressure_ratio == 0.2);
  scene["section"]["materials"][1].erase("pore_pressure_ratio");
  scene["analyses"]["sph"]["ignore_loads"] = {"water", "surcharge"};
  CHECK_THROWS_WITH(parse_scene(scene.dump()), Catch::Contains("analyses.sph.ignore_loads[1]"));
  scene["section"].erase("water");
  scene["analyses"]["sph"]["ignore_loads"] = {"water"};
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("analyses.sph.ignore_loads[0]: the section has no water to leave out"));
}

TEST_CASE("scene: cohesion rising with depth is read in kPa/m, checked against the cohesion, and left out of SPH",
          "[scene][undrained]") {
  // docs/scene-format.md, section.materials[i]: cohesion_increase_kPa_per_m, cohesion_datum_y_m, cohesion_max_kPa.
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases/two_layer_water.json"));
  nlohmann::json& lower = scene["section"]["materials"][1];
  lower["cohesion_increase_kPa_per_m"] = 2.5;
  lower["cohesion_datum_y_m"] = 7.0;
  lower["cohesion_max_kPa"] = 40.0;
  const slope::Material read = parse_scene(scene.dump()).section->section.materials[1];
  CHECK(read.cohesion_rate == 2500.0);
  REQUIRE(read.cohesion_datum_y);
  CHECK(*read.cohesion_datum_y == 7.0);
  CHECK(read.cohesion_max == 40e3);
  CHECK(parse_scene(scene.dump()).section->section.materials[0].cohesion_rate == 0.0);
  scene["analyses"]["sph"] = {{"particle_spacing_m", 1.0}, {"end_time_s", 1.0}};
  const auto left_out = coupling::loads_sph_leaves_out(parse_scene(scene.dump()));
  REQUIRE(left_out.size() == 1);
  CHECK(left_out[0].path == "section.materials[1].cohesion_increase_kPa_per_m");
  CHECK_THAT(left_out[0].name, Catch::Contains("2.5 kPa/m"));
  scene["analyses"].erase("sph");

  lower["cohesion_max_kPa"] = 14.0;
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("section.materials[1].cohesion_max_kPa: must be at least cohesion_kPa = 15 (got 14)"));
  lower.erase("cohesion_max_kPa");
  lower.erase("cohesion_increase_kPa_per_m");
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("section.materials[1].cohesion_datum_y_m: needs cohesion_increase_kPa_per_m"));
  lower.erase("cohesion_datum_y_m");
  lower["cohesion_increase_kPa_per_m"] = -1.0;
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("section.materials[1].cohesion_increase_kPa_per_m: must be >= 0 (got -1.0)"));
}

TEST_CASE("scene: strength envelopes (Hoek-Brown, power curve, shear-normal function) are read in MPa and kPa, one "
          "per material, and the SPH analysis needs a Mohr-Coulomb strength beside them", "[scene][strength]") {
  // docs/scene-format.md, section.materials[i]: hoek_brown, power_curve, shear_normal_kPa.
  const fs::path source = fs::path(test_paths::source_dir());
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(source / "cases/hammah_2005_hoek_brown.json"));
  nlohmann::json& rock = scene["section"]["materials"][0];
  {
    const slope::Material read = parse_scene(scene.dump()).section->section.materials[0];
    REQUIRE(read.envelope);
    CHECK(read.envelope->kind == slope::StrengthEnvelope::Kind::hoek_brown);
    const slope::HoekBrown expected = slope::hoek_brown_from_gsi(30e6, 5.0, 2.0, 0.0);
    CHECK(read.envelope->hoek_brown.intact_strength == 30e6);
    CHECK(read.envelope->hoek_brown.mb == expected.mb);
    CHECK(read.envelope->hoek_brown.s == expected.s);
    CHECK(read.envelope->hoek_brown.a == expected.a);
  }
  rock["hoek_brown"] = {{"intact_strength_MPa", 30}, {"mb", 0.067}, {"s", 2.5e-5}, {"a", 0.619}};
  CHECK(parse_scene(scene.dump()).section->section.materials[0].envelope->hoek_brown.mb == 0.067);
  rock["hoek_brown"]["gsi"] = 5;
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("section.materials[0].hoek_brown: give gsi and mi (and disturbance), or mb, s and "
                                    "a, not both"));
  rock["hoek_brown"] = {{"intact_strength_MPa", 30}, {"gsi", 5}};
  CHECK_THROWS_WITH(parse_scene(scene.dump()), Catch::Contains("section.materials[0].hoek_brown.mi: required"));

  // tau = 1.4 sigma'^0.8 in kPa: 1.4 x 1000^0.2 Pa^0.2 in SI, the same strength at 100 kPa.
  rock.erase("hoek_brown");
  rock["power_curve"] = {{"a", 1.4}, {"b", 0.8}};
  {
    const slope::Material read = parse_scene(scene.dump()).section->section.materials[0];
    REQUIRE(read.envelope);
    CHECK(slope::envelope_at(*read.envelope, 100e3).shear == Approx(1.4 * std::pow(100.0, 0.8) * 1e3).epsilon(1e-12));
  }
  rock["power_curve"]["b"] = 1.5;
  CHECK_THROWS_WITH(parse_scene(scene.dump()), Catch::Contains("section.materials[0].power_curve.b: must be in (0, 1]"));
  rock["power_curve"]["b"] = 0.8;
  rock["shear_normal_kPa"] = {{0, 5}, {100, 60}};
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("section.materials[0].shear_normal_kPa: a material has one strength envelope"));
  rock.erase("power_curve");
  CHECK(parse_scene(scene.dump()).section->section.materials[0].envelope->points[1].shear == 60e3);
  rock["shear_normal_kPa"] = {{0, 5}, {100, 60}, {200, 50}};
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("section.materials[0].shear_normal_kPa[2]: the shear strength must not decrease"));
  rock["shear_normal_kPa"] = {{0, 5}, {100, 60}};

  rock["cohesion_increase_kPa_per_m"] = 2.0;
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("section.materials[0].cohesion_increase_kPa_per_m: a material with a strength "
                                    "envelope takes its strength from the envelope alone"));
  rock.erase("cohesion_increase_kPa_per_m");
  rock["cohesion_kPa"] = 20.0;
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("section.materials[0].friction_angle_deg: give both cohesion_kPa and "
                                    "friction_angle_deg"));
  rock.erase("cohesion_kPa");

  // The SPH soil model is Mohr-Coulomb: without cohesion_kPa and friction_angle_deg it cannot run; with them it
  // runs on them and the envelope is listed as left out of it.
  rock["youngs_modulus_MPa"] = 100.0;
  rock["poisson_ratio"] = 0.3;
  scene["analyses"]["sph"] = {{"particle_spacing_m", 1.0}, {"end_time_s", 1.0}};
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("lacks cohesion_kPa and friction_angle_deg (beside its strength envelope)"));
  rock["cohesion_kPa"] = 20.0;
  rock["friction_angle_deg"] = 35.0;
  const auto left_out = coupling::loads_sph_leaves_out(parse_scene(scene.dump()));
  REQUIRE(left_out.size() == 1);
  CHECK(left_out[0].path == "section.materials[0].shear_normal_kPa");
  CHECK_THAT(left_out[0].name, Catch::Contains("shear-normal function"));
}

TEST_CASE("scene: a particle body's material has no strength envelope and no saturated unit weight",
          "[scene][strength]") {
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases/bui2008_column_collapse.json"));
  REQUIRE(scene.contains("bodies"));
  scene["bodies"][0]["material"]["hoek_brown"] = {{"intact_strength_MPa", 30}, {"gsi", 5}, {"mi", 2}};
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("bodies[0].material.hoek_brown: strength envelopes are for the section's materials"));
  scene["bodies"][0]["material"].erase("hoek_brown");
  scene["bodies"][0]["material"]["saturated_unit_weight_kN_m3"] = 21.0;
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("bodies[0].material.saturated_unit_weight_kN_m3: is for the section's materials"));
}

TEST_CASE("scene: a saturated unit weight is read in kN/m3, SPH leaves it out only without the water",
          "[scene][water]") {
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases/two_layer_water.json"));
  scene["section"]["materials"][1]["saturated_unit_weight_kN_m3"] = 21.5;
  CHECK(parse_scene(scene.dump()).section->section.materials[1].saturated_unit_weight == 21.5e3);
  CHECK_FALSE(parse_scene(scene.dump()).section->section.materials[0].saturated_unit_weight);
  scene["analyses"]["sph"] = {{"particle_spacing_m", 1.0}, {"end_time_s", 1.0}};
  CHECK(coupling::loads_sph_leaves_out(parse_scene(scene.dump())).empty());
  scene["analyses"]["sph"]["ignore_loads"] = {"water"};
  const auto left_out = coupling::loads_sph_leaves_out(parse_scene(scene.dump()));
  REQUIRE(left_out.size() == 2);
  CHECK(left_out[1].path == "section.materials[1].saturated_unit_weight_kN_m3");
  scene["section"]["materials"][1]["saturated_unit_weight_kN_m3"] = 0.0;
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("section.materials[1].saturated_unit_weight_kN_m3: must be > 0"));
}

namespace {

// The row of docs/scene-format.md's tables that documents `key` ("| `key` | ..."): the first one, or the first after
// the heading `section` (e.g. "### `analyses.mps`") when a key is documented in several sections.
std::string documented_row(const std::string& key, const std::string& section = {}) {
  std::ifstream docs(fs::path(test_paths::source_dir()) / "docs/scene-format.md");
  std::string line;
  bool in_section = section.empty();
  while (std::getline(docs, line)) {
    if (!in_section) in_section = line == section;
    if (in_section && line.rfind("| `" + key + "` |", 0) == 0) return line;
  }
  return {};
}

// Every name of the table reads back to its value and is listed in the key's row of the docs, as `name` or
// "name"; the scene reader and the report take their names from the same table.
template <class E, std::size_t N>
void check_names(const std::string& key, const sphslope::NameTable<E, N>& names, const std::string& section = {}) {
  INFO(key);
  const std::string row = documented_row(key, section);
  REQUIRE_FALSE(row.empty());
  for (const sphslope::Named<E>& entry : names) {
    const std::string name(entry.name);
    INFO(name);
    CHECK(sphslope::value_named(names, entry.name) == entry.value);
    CHECK(sphslope::name_of(names, entry.value) == entry.name);
    CHECK((row.find("`" + name + "`") != std::string::npos || row.find("\"" + name + "\"") != std::string::npos));
  }
}

}  // namespace

TEST_CASE("scene: each setting's names come from one table that the docs list", "[scene]") {
  check_names("kernel", sph::kernel_names);
  check_names("kernel_gradient", sph::soil::kernel_gradient_names);
  check_names("time_integration", sph::soil::time_integration_names);
  check_names("gravity", sph::gravity_mode_names);
  check_names("slip", sph::soil::wall_slip_names);
  check_names("sides", coupling::wall_side_names, "### `analyses.sph`");
  check_names("ignore_loads", coupling::section_load_names);
  check_names("configuration", coupling::band_configuration_names);
  check_names("constitutive_model", coupling::constitutive_model_names);
  check_names("mode", coupling::probabilistic_mode_names, "### `analyses.lem.probabilistic`");
  check_names("sampling", coupling::sampling_names, "### `analyses.lem.probabilistic`");
  check_names("distribution", coupling::distribution_names, "### `analyses.lem.probabilistic`");
  check_names("parameter", coupling::random_parameter_names, "### `analyses.lem.probabilistic`");
  check_names("regularisation", sph::mps::regularisation_names);
  check_names("interaction_viscosity", sph::mps::interaction_viscosity_names);
  check_names("effective_pressure", sph::mps::effective_pressure_names);
  check_names("pore_pressure", sph::mps::pore_pressure_names);
  check_names("stress_divergence", sph::mps::stress_divergence_names);
  check_names("mode", sph::soil::artificial_stress_mode_names, "### `analyses.sph`");
  check_names("pressure", sph::fluid::pressure_mode_names);
  check_names("solver", sph::fluid::linear_solver_names);
  check_names("preconditioner", sph::fluid::preconditioner_names);
  check_names("law", sph::fluid::motion_law_names);
  check_names("type", slope::support_type_names);
  check_names("direction", slope::support_direction_names);
  check_names("application", slope::support_application_names);
  check_names("type", sph::mps::material_type_names, "#### `analyses.mps.materials[i]`");
  // The reader's message lists the same names.
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases/two_layer_water_sph.json"));
  scene["analyses"]["sph"]["kernel"] = "gaussian";
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("analyses.sph.kernel: unknown kernel \"gaussian\" (allowed: " +
                                    sphslope::names_listed(sph::kernel_names) + ")"));
}

TEST_CASE("scene: reinforcement is read in kN and kN/m with its type's defaults, and left out of SPH",
          "[scene][reinforcement]") {
  // docs/scene-format.md, section.reinforcement[i].
  const fs::path file = fs::path(test_paths::source_dir()) / "cases/duncan_wright_2005_geogrids.json";
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(file));
  const slope::Section read = parse_scene(scene.dump()).section->section;
  REQUIRE(read.reinforcement.size() == 5);
  const slope::Reinforcement& grid = read.reinforcement[4];
  CHECK(grid.type == slope::SupportType::geosynthetic);
  CHECK(grid.tail.x == Approx(7.62 + 6.096).epsilon(1e-12));  // length_m and inclination 0, into the slope (+x)
  CHECK(grid.tail.y == Approx(6.096).epsilon(1e-12));
  CHECK(grid.tensile_capacity == Approx(11675.0).epsilon(1e-12));
  CHECK(grid.direction == slope::SupportDirection::along);
  CHECK(grid.application == slope::SupportApplication::active);
  // a nail with only its capacity: passive, along, the head as strong as the nail, no pull-out limit
  nlohmann::json& elements = scene["section"]["reinforcement"];
  elements[0] = {{"type", "soil_nail"}, {"head_m", {2.0, 1.6}}, {"length_m", 5.0}, {"inclination_deg", 15.0},
                 {"tensile_capacity_kN", 90.0}, {"spacing_m", 1.5}};
  const slope::Reinforcement nail = parse_scene(scene.dump()).section->section.reinforcement[0];
  CHECK(nail.application == slope::SupportApplication::passive);
  CHECK(nail.direction == slope::SupportDirection::along);
  CHECK(nail.head_capacity == 90e3);
  CHECK(std::isinf(nail.bond_strength));
  CHECK(nail.tail.y == Approx(1.6 - 5.0 * std::sin(15.0 * degree)).epsilon(1e-12));
  CHECK(slope::capacity_at(nail, 1.0) / nail.spacing == Approx(60e3).epsilon(1e-12));
  // a tieback: its bond length at the tail
  elements[0] = {{"type", "tieback"}, {"head_m", {2.0, 1.6}}, {"tail_m", {12.0, 1.6}}, {"tensile_capacity_kN", 200.0},
                 {"bond_strength_kN_m", 40.0}, {"bond_length_m", 4.0}};
  const slope::Reinforcement tieback = parse_scene(scene.dump()).section->section.reinforcement[0];
  CHECK(tieback.bond_start == Approx(6.0).epsilon(1e-12));
  CHECK(slope::capacity_at(tieback, 3.0) == Approx(160e3).epsilon(1e-12));
  // faults, each at its path
  auto fails_with = [&](nlohmann::json element, const std::string& message) {
    nlohmann::json bad = scene;
    bad["section"]["reinforcement"][1] = std::move(element);
    CHECK_THROWS_WITH(parse_scene(bad.dump()), Catch::Contains(message));
  };
  fails_with({{"type", "anchor"}, {"head_m", {2, 1.6}}, {"tail_m", {9, 1.6}}, {"tensile_capacity_kN", 9}},
             "section.reinforcement[1].type: expected \"soil_nail\", \"tieback\", \"end_anchored\", \"geosynthetic\" or "
             "\"pile\", got \"anchor\"");
  fails_with({{"type", "soil_nail"}, {"head_m", {2, 1.6}}, {"tensile_capacity_kN", 9}},
             "section.reinforcement[1]: give the element's other end");
  fails_with({{"type", "tieback"}, {"head_m", {2, 1.6}}, {"tail_m", {9, 1.6}}, {"tensile_capacity_kN", 9},
              {"bond_strength_kN_m", 10}},
             "section.reinforcement[1].bond_length_m");
  fails_with({{"type", "tieback"}, {"head_m", {2, 1.6}}, {"tail_m", {9, 1.6}}, {"tensile_capacity_kN", 9},
              {"bond_strength_kN_m", 10}, {"bond_length_m", 8}},
             "section.reinforcement[1].bond_length_m: must be at most the element's length, 7 m");
  fails_with({{"type", "pile"}, {"head_m", {2, 1.6}}, {"tail_m", {2, -1}}, {"tensile_capacity_kN", 9}},
             "section.reinforcement[1].shear_capacity_kN");
  fails_with({{"type", "pile"}, {"head_m", {2, 1.6}}, {"tail_m", {2, -1}}, {"shear_capacity_kN", 9},
              {"direction", "along"}},
             "section.reinforcement[1]: a pile's shear acts tangent");
  fails_with({{"type", "soil_nail"}, {"head_m", {2, 1.6}}, {"tail_m", {90, 1.6}}, {"tensile_capacity_kN", 9}},
             "section.reinforcement[1]: must lie on the section");
  // SPH has no structural elements: the run says so, at the path
  scene["analyses"]["sph"] = {{"particle_spacing_m", 1.0}, {"end_time_s", 1.0}};
  scene["section"]["materials"][0]["youngs_modulus_MPa"] = 50.0;
  scene["section"]["materials"][0]["poisson_ratio"] = 0.3;
  const auto left_out = coupling::loads_sph_leaves_out(parse_scene(scene.dump()));
  REQUIRE(left_out.size() == 1);
  CHECK(left_out[0].path == "section.reinforcement");
  CHECK_THAT(left_out[0].name, Catch::Contains("5 reinforcement elements"));
}

TEST_CASE("scene: line loads, trapezoidal strips and k_v are read in kN/m and kPa, and SPH carries them",
          "[scene][loads]") {
  // docs/scene-format.md: section.line_loads[i], section.surcharges[i].pressure_end_kPa,
  // section.seismic.vertical_coefficient.
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases/two_layer_water.json"));
  scene["section"]["line_loads"] = {{{"x_m", 12.0}, {"force_kN_m", 50.0}, {"angle_deg", 30.0}},
                                    {{"x_m", 5.0}, {"force_kN_m", 20.0}}};
  scene["section"]["surcharges"] = {{{"from_x_m", 2.0}, {"to_x_m", 8.0}, {"pressure_kPa", 10.0}, {"pressure_end_kPa", 40.0}}};
  scene["section"]["seismic"] = {{"vertical_coefficient", -0.05}};
  const slope::Section read = parse_scene(scene.dump()).section->section;
  REQUIRE(read.line_loads.size() == 2);
  CHECK(read.line_loads[0].x == 12.0);
  CHECK(read.line_loads[0].force_x == Approx(25e3).epsilon(1e-12));  // 50 sin 30, toward +x
  CHECK(read.line_loads[0].force_y == Approx(-50e3 * std::sqrt(3.0) / 2.0).epsilon(1e-12));
  CHECK(read.line_loads[1].force_x == 0.0);
  CHECK(read.line_loads[1].force_y == -20e3);
  REQUIRE(read.surcharges.size() == 1);
  CHECK(read.surcharges[0].end_pressure() == 40e3);
  CHECK(read.surcharges[0].load_on(0.0, 20.0) == Approx(150e3).epsilon(1e-12));
  CHECK(read.seismic_coefficient == 0.0);
  CHECK(read.vertical_seismic_coefficient == -0.05);
  // faults at their paths
  nlohmann::json bad = scene;
  bad["section"]["line_loads"][1]["x_m"] = 500.0;
  CHECK_THROWS_WITH(parse_scene(bad.dump()), Catch::Contains("section.line_loads[1].x_m: must lie on the section"));
  bad = scene;
  bad["section"]["seismic"] = nlohmann::json::object();
  CHECK_THROWS_WITH(parse_scene(bad.dump()), Catch::Contains("section.seismic: give horizontal_coefficient"));
  bad = scene;
  bad["section"]["seismic"]["vertical_coefficient"] = 1.0;
  CHECK_THROWS_WITH(parse_scene(bad.dump()), Catch::Contains("section.seismic.vertical_coefficient"));
  // SPH carries them: nothing left out unless listed; line_loads may be listed
  scene["analyses"]["sph"] = {{"particle_spacing_m", 1.0}, {"end_time_s", 1.0}};
  CHECK(coupling::loads_sph_leaves_out(parse_scene(scene.dump())).empty());
  scene["analyses"]["sph"]["ignore_loads"] = {"line_loads", "seismic"};
  const auto left_out = coupling::loads_sph_leaves_out(parse_scene(scene.dump()));
  REQUIRE(left_out.size() == 2);
  CHECK(left_out[0].path == "section.line_loads");
  CHECK(left_out[1].path == "section.seismic");
  const sph::soil::Model model = coupling::build_sph_model(parse_scene(scene.dump()));
  CHECK(model.loads.vertical_seismic_coefficient == 0.0);
  scene["analyses"]["sph"].erase("ignore_loads");
  const sph::soil::Model carried = coupling::build_sph_model(parse_scene(scene.dump()));
  CHECK(carried.loads.vertical_seismic_coefficient == -0.05);
  double down = 0.0, across = 0.0;
  const auto& fx = carried.particles.field(*carried.loads.surface_force_x);
  const auto& fy = carried.particles.field(*carried.loads.surface_force_y);
  for (std::size_t i = 0; i < fx.size(); ++i) {
    down -= fy[i];
    across += fx[i];
  }
  CHECK(across == Approx(25e3).epsilon(1e-12));
  CHECK(down == Approx(150e3 + 20e3 + 50e3 * std::sqrt(3.0) / 2.0).epsilon(1e-12));
}

TEST_CASE("scene: the critical seismic coefficient is sought with the method asked for, and reported",
          "[scene][loads][seismic]") {
  // docs/scene-format.md, analyses.lem.critical_seismic_coefficient; report.json lem.critical_seismic_coefficient.
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases/griffiths_lane_1999.json"));
  scene["analyses"] = {{"lem", {{"methods", {"bishop", "spencer"}}, {"critical_seismic_coefficient", nlohmann::json::object()}}}};
  CHECK(parse_scene(scene.dump()).analyses.lem->critical_coefficient_method == slope::Method::bishop);
  scene["analyses"]["lem"]["critical_seismic_coefficient"]["method"] = "janbu";
  CHECK_THROWS_WITH(parse_scene(scene.dump()),
                    Catch::Contains("analyses.lem.critical_seismic_coefficient.method: \"janbu\" is not one of the "
                                    "methods analysed (allowed: bishop, spencer)"));
  scene["analyses"]["lem"]["critical_seismic_coefficient"]["method"] = "spencer";
  const Scene parsed = parse_scene(scene.dump());
  coupling::WorkflowOptions options;
  options.mode = coupling::Mode::lem;
  const coupling::WorkflowResult out = coupling::run_scene(parsed, options);
  REQUIRE(out.status == coupling::ExitStatus::ok);
  const nlohmann::json& k = out.report["lem"]["critical_seismic_coefficient"];
  CHECK(k["method"] == "spencer");
  CHECK(k["factor_of_safety_without"].get<double>() ==
        Approx(out.report["lem"]["methods"]["spencer"]["factor_of_safety"].get<double>()).epsilon(1e-12));
  CHECK(k["factor_of_safety"].get<double>() == Approx(1.0).epsilon(2e-3));
  CHECK(k["k_c"].get<double>() > 0.1);
  CHECK(k["k_c"].get<double>() < 0.2);
  // The surface at k_c, with k_h = k_c on the section, has FS 1 by the same method.
  slope::Section shaken = parsed.section->section;
  shaken.seismic_coefficient = k["k_c"].get<double>();
  const slope::SearchResult again = slope::search_critical(shaken, {slope::Method::spencer}, parsed.analyses.lem->search);
  REQUIRE(again.methods.front().result.factor_of_safety);
  CHECK(*again.methods.front().result.factor_of_safety == Approx(1.0).epsilon(2e-3));
}

TEST_CASE("scene: k_h on a section level at both ends is refused for SPH (no direction)", "[scene][sph]") {
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases/two_layer_water.json"));
  scene["section"]["seismic"]["horizontal_coefficient"] = 0.1;
  scene["section"]["profile_lines"][0]["points_m"] = {{0, 20}, {20, 20}, {30, 10}, {40, 20}, {60, 20}};
  scene["section"]["profile_lines"][1]["points_m"] = {{0, 8}, {60, 8}};
  CHECK_NOTHROW(parse_scene(scene.dump()));  // limit equilibrium alone takes each surface's direction
  scene["analyses"]["sph"] = {{"particle_spacing_m", 1.0}, {"end_time_s", 1.0}};
  CHECK_THROWS_WITH(parse_scene(scene.dump()), Catch::Contains("section.seismic: the ground is level at both ends"));
  scene["analyses"]["sph"]["ignore_loads"] = {"seismic"};
  CHECK_NOTHROW(parse_scene(scene.dump()));
}

TEST_CASE("scene: syntax errors give line and column", "[scene]") {
  try {
    parse_scene("{\n  \"format\": \"sphslope-scene/1\",\n  \"name\": oops\n}\n");
    FAIL("no error");
  } catch (const SceneError& error) {
    REQUIRE(error.messages().size() == 1);
    INFO(error.messages()[0]);
    CHECK(error.messages()[0].find("JSON syntax error at line 3, column") != std::string::npos);
  }
}

TEST_CASE("json reader: unknown keys suggest the closest known one", "[scene]") {
  coupling::Diagnostics diagnostics;
  const json value = json::parse(R"({"frictoin_angle_deg": 1, "notes": "x", "zzz": 2})");
  coupling::JsonReader reader(value, "m", diagnostics);
  reader.number("friction_angle_deg", coupling::Need::optional);
  reader.number("cohesion_kPa", coupling::Need::optional);
  reader.finish();
  REQUIRE(diagnostics.size() == 2);
  CHECK(diagnostics.messages()[0] ==
        "m.frictoin_angle_deg: unknown key (did you mean \"friction_angle_deg\"? allowed here: friction_angle_deg, "
        "cohesion_kPa)");
  CHECK(diagnostics.messages()[1] == "m.zzz: unknown key (allowed here: friction_angle_deg, cohesion_kPa)");
}

TEST_CASE("report: a critical surface in report units", "[report]") {
  slope::Section section;
  section.materials.push_back({"clay", 18000.0, 12000.0, 25 * degree});
  slope::CriticalSurface critical;
  critical.method = slope::Method::spencer;
  slope::SlipMass mass;
  mass.circle = {10.0, 20.0, 15.0};
  mass.entry = {1.0, 10.0};
  mass.exit = {20.0, 2.0};
  slope::Slice slice;
  slice.x_left = 1.0;
  slice.x_right = 2.0;
  slice.width = 1.0;
  slice.base_angle = 30 * degree;
  slice.base_length = 1.1547;
  slice.weight = 36000.0;
  slice.surcharge_load = 5000.0;
  slice.cohesion = 12000.0;
  slice.tan_friction = std::tan(25 * degree);
  slice.pore_pressure = 9810.0;
  mass.slices.push_back(slice);
  critical.mass = mass;
  critical.result.factor_of_safety = 1.25;
  critical.result.lambda = 0.3;
  slope::SliceForces forces;
  forces.normal = 40000.0;
  forces.shear = 15000.0;
  forces.interslice_normal_right = 2000.0;
  forces.interslice_shear_right = 600.0;
  critical.result.forces.push_back(forces);

  const json m = coupling::method_report(section, critical);
  CHECK(m["factor_of_safety"] == 1.25);
  CHECK(m["lambda"] == 0.3);
  CHECK(m["surface"]["type"] == "circle");
  CHECK(m["surface"]["center_m"] == json::parse("[10.0, 20.0]"));
  CHECK(m["surface"]["radius_m"] == 15.0);
  CHECK(m["surface"]["entry_m"] == json::parse("[1.0, 10.0]"));
  CHECK(m["surface"]["exit_m"] == json::parse("[20.0, 2.0]"));
  REQUIRE(m["slices"].size() == 1);
  const json& s = m["slices"][0];
  CHECK(s["weight_kN_m"].get<double>() == Approx(36.0));
  CHECK(s["surcharge_kN_m"].get<double>() == Approx(5.0));
  CHECK(s["base_angle_deg"].get<double>() == Approx(30.0));
  CHECK(s["friction_angle_deg"].get<double>() == Approx(25.0));
  CHECK(s["cohesion_kPa"].get<double>() == Approx(12.0));
  CHECK(s["pore_pressure_kPa"].get<double>() == Approx(9.81));
  CHECK(s["normal_force_kN_m"].get<double>() == Approx(40.0));
  CHECK(s["shear_force_kN_m"].get<double>() == Approx(15.0));
  CHECK(s["interslice_normal_right_kN_m"].get<double>() == Approx(2.0));
  CHECK(s["interslice_shear_right_kN_m"].get<double>() == Approx(0.6));
  CHECK(s["material"] == "clay");

  SECTION("a method that failed everywhere reports null and the reason, never a number") {
    slope::CriticalSurface failed;
    failed.method = slope::Method::bishop;
    failed.result.error = "no convergence";
    const json f = coupling::method_report(section, failed);
    CHECK(f["factor_of_safety"].is_null());
    CHECK(f["error"] == "no convergence");
    CHECK_FALSE(f.contains("lambda"));
  }
}

}  // namespace test_scene_loader
