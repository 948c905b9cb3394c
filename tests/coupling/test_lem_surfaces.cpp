// Slip surfaces given in the scene (analyses.lem.surfaces): reading, faults at their JSON paths, the report.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/output/report.hpp"
#include "coupling/scene/scene.hpp"

namespace test_lem_surfaces {

using coupling::parse_scene;
using coupling::SceneError;
using nlohmann::json;

namespace {

// The slope of tests/slope/test_lem_tension_crack.cpp: crest at y = 15 from x = 0 to 20, a 45 degree face to the
// toe at (30, 5), level ground to x = 50, rigid base at y = 0; gamma = 18 kN/m^3, c' = 10 kPa, phi' = 25 deg.
// The plane from (10, 15) to the toe with a 2 m water-filled crack.
json wedge_scene() {
  return json::parse(R"({
    "format": "sphslope-scene/1",
    "name": "planar wedge with a tension crack",
    "section": {
      "bottom_y_m": 0.0,
      "profile_lines": [ { "material": "soil", "points_m": [[0, 15], [20, 15], [30, 5], [50, 5]] } ],
      "materials": [ { "name": "soil", "unit_weight_kN_m3": 18, "cohesion_kPa": 10, "friction_angle_deg": 25 } ]
    },
    "analyses": {
      "lem": {
        "methods": ["bishop", "janbu", "spencer", "morgenstern_price"],
        "surfaces": [
          { "name": "wedge", "points_m": [[10, 15], [30, 5]],
            "tension_crack": { "depth_m": 2, "water_filled": true } },
          { "points_m": [[8, 15], [18, 8], [26, 4], [34, 5]], "moment_point_m": [20, 30],
            "tension_crack": { "rankine": true } },
          { "name": "circle", "circle": { "center_m": [32, 22], "radius_m": 18.5 },
            "tension_crack": { "depth_m": 1.5 } }
        ]
      }
    }
  })");
}

std::vector<std::string> errors_of(const json& document) {
  try {
    parse_scene(document.dump(), "scenes/wedge.json");
  } catch (const SceneError& error) {
    return error.messages();
  }
  return {};
}

bool mentions(const std::vector<std::string>& errors, const std::string& text) {
  for (const std::string& e : errors)
    if (e.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("scene: given slip surfaces are read, analysed with every method and reported", "[scene][report]") {
  const coupling::Scene scene = parse_scene(wedge_scene().dump(), "scenes/wedge.json");
  REQUIRE(scene.analyses.lem);
  const coupling::LemAnalysis& lem = *scene.analyses.lem;
  REQUIRE(lem.surfaces.size() == 3);
  CHECK(lem.surfaces[0].name == "wedge");
  CHECK(coupling::summarize(scene).find("lem (4 methods, 3 given slip surfaces)") != std::string::npos);
  CHECK(lem.surfaces[1].name == "surface 1");
  CHECK(lem.surfaces[0].polyline.tension_crack->depth == 2.0);
  CHECK_FALSE(lem.surfaces[1].polyline.tension_crack->depth.has_value());
  const auto results = coupling::analyse_given_surfaces(scene.section->section, lem);
  const json report = coupling::lem_report(scene.section->section, lem, slope::SearchResult{}, results);
  const json& wedge = report["surfaces"][0];
  CHECK(wedge["name"] == "wedge");
  // Hand calculation (tests/slope/test_lem_tension_crack.cpp): F = 1.3411 for the force-equilibrium methods.
  for (const char* key : {"janbu", "spencer", "morgenstern_price"}) {
    INFO(key);
    CHECK(wedge["methods"][key]["factor_of_safety"].get<double>() == Approx(1.3411).epsilon(1e-4));
  }
  const json& surface = wedge["methods"]["spencer"]["surface"];
  CHECK(surface["type"] == "polyline");
  CHECK(surface["tension_crack"]["depth_m"].get<double>() == 2.0);
  CHECK(surface["tension_crack"]["water_force_kN_m"].get<double>() == Approx(19.62));
  CHECK(surface["entry_m"][0].get<double>() == Approx(14.0));
  CHECK(wedge["methods"]["spencer"]["slices"].size() >= 10);
  const json& second = report["surfaces"][1]["methods"]["bishop"];
  CHECK(second["surface"]["moment_point_m"] == json::parse("[20, 30]"));
  // Rankine depth of c' = 10 kPa, phi' = 25 deg, gamma = 18 kN/m^3: 1.7441 m (hand calculation in the slope test)
  CHECK(second["surface"]["tension_crack"]["depth_m"].get<double>() == Approx(1.7441).margin(1e-4));
  // A circle given by centre and radius: 256 chords, moments about its centre, the crack where the arc lies 1.5 m
  // below the crest: 22 - sqrt(18.5^2 - (x - 32)^2) = 13.5, x = 32 - sqrt(342.25 - 72.25) = 15.568 m (closed form).
  REQUIRE(lem.surfaces[2].circle.has_value());
  CHECK(lem.surfaces[2].polyline.points.size() == 257);
  const json& circle = report["surfaces"][2]["methods"]["spencer"];
  INFO(circle.dump().substr(0, 400));
  CHECK(circle["factor_of_safety"].is_number());
  CHECK(circle["surface"]["moment_point_m"] == json::parse("[32, 22]"));
  CHECK(circle["surface"]["entry_m"][0].get<double>() == Approx(32.0 - std::sqrt(342.25 - 72.25)).margin(1e-3));
}

TEST_CASE("scene: faults in given slip surfaces are reported at their JSON paths", "[scene]") {
  json document = wedge_scene();
  json& surfaces = document["analyses"]["lem"]["surfaces"];
  surfaces[0]["points_m"] = json::parse("[[10, 14], [30, 5]]");
  surfaces[1]["tension_crack"] = json::parse(R"({"depth_m": 2, "rankine": true})");
  surfaces.push_back(json::parse(R"({"points_m": [[10, 15], [30, 5]], "tension_crack": {"depth": 2}})"));
  surfaces.push_back(json::parse(R"({"points_m": [[8, 15], [14, 13], [22, 4.5], [34, 5]]})"));
  surfaces.push_back(json::parse(R"({"points_m": [[10, 15], [30]]})"));
  surfaces.push_back(json::parse(R"({"points_m": [[10, 15], [30, 5]], "circle": {"center_m": [32, 22], "radius_m": 18.5}})"));
  surfaces.push_back(json::parse(R"({"circle": {"center_m": [32, 22], "radius_m": 2}})"));
  const auto errors = errors_of(document);
  std::string all;
  for (const std::string& e : errors) all += e + "\n";
  INFO(all);
  CHECK(mentions(errors, "analyses.lem.surfaces[0]: not an admissible slip surface: the end point (10, 14) is not on "
                         "the ground surface"));
  CHECK(mentions(errors, "analyses.lem.surfaces[1].tension_crack: give either depth_m or \"rankine\": true"));
  CHECK(mentions(errors, "analyses.lem.surfaces[3].tension_crack.depth: unknown key (did you mean \"depth_m\"?"));
  CHECK(mentions(errors, "analyses.lem.surfaces[3].tension_crack: needs a depth"));
  CHECK(mentions(errors, "analyses.lem.surfaces[4]: not an admissible slip surface: the surface turns convex"));
  CHECK(mentions(errors, "analyses.lem.surfaces[5].points_m[1]: expected a point [x_m, y_m]"));
  CHECK(mentions(errors, "analyses.lem.surfaces[6]: give either points_m or circle, not both"));
  CHECK(mentions(errors, "analyses.lem.surfaces[7].circle: not an admissible slip circle: the circle does not cut"));
  CHECK(errors.size() == 8);
}

}  // namespace test_lem_surfaces
