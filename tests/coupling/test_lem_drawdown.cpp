// analyses.lem.rapid_drawdown: USACE EM 1110-2-1902 App. G read from its scene, and every bad input refused with its
// JSON path.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/scene/scene.hpp"
#include "test_support.hpp"

namespace test_lem_drawdown {

namespace fs = std::filesystem;
using nlohmann::json;

json usace() { return read_json(fs::path(test_paths::source_dir()) / "cases/usace_1902_rapid_drawdown.json"); }

TEST_CASE("rapid drawdown: USACE EM 1110-2-1902 App. G from its scene, on the specified circle",
          "[scene][drawdown][validation]") {
  // USACE 1.44, Slide (Duncan-Wright-Wong) 1.443 on the circle (169.5, 210) ft, R = 210 ft; the xslope project's
  // Spencer 1.434. The band: 1.44 within 1.5 %.
  TemporaryFolder folder("drawdown");
  const coupling::WorkflowResult out = run_lem_into(coupling::parse_scene(usace().dump()), folder.path);
  REQUIRE(out.status == coupling::ExitStatus::ok);
  const json& r = out.report["lem"]["rapid_drawdown"];
  CHECK(r["method"] == "spencer");
  REQUIRE(r["surfaces"].size() == 1);
  const json& s = r["surfaces"][0];
  CHECK(s["factor_of_safety"].get<double>() == Approx(1.44).epsilon(0.015));
  // before drawdown the given surface's own Spencer factor (the same slices, the water before)
  CHECK(s["before_drawdown"].get<double>() ==
        Approx(out.report["lem"]["surfaces"][0]["methods"]["spencer"]["factor_of_safety"].get<double>()).epsilon(1e-9));
  CHECK(s["slices_drained"].get<long>() > 0);
  CHECK(unexplained_nulls(out.report).empty());
  CHECK(read_text(folder.path / "report.html").find("Rapid drawdown (spencer") != std::string::npos);
}

TEST_CASE("rapid drawdown: bad input is refused with its JSON path", "[scene][drawdown]") {
  const std::string at = "analyses.lem.rapid_drawdown";
  json scene = usace();
  scene["analyses"]["lem"]["rapid_drawdown"]["materials"][0]["material"] = "core";
  CHECK_THAT(scene_faults(scene), Catch::Contains(at + ".materials[0].material: no material of section.materials is named"));
  scene = usace();
  scene["analyses"]["lem"]["rapid_drawdown"]["materials"].push_back(scene["analyses"]["lem"]["rapid_drawdown"]["materials"][0]);
  CHECK_THAT(scene_faults(scene), Catch::Contains(at + ".materials[1].material: \"embankment\" is listed twice"));
  scene = usace();
  scene["analyses"]["lem"].erase("surfaces");
  CHECK_THAT(scene_faults(scene), Catch::Contains(at + ": rapid drawdown is analysed on the given slip surfaces"));
  scene = usace();
  scene["section"].erase("water");
  CHECK_THAT(scene_faults(scene), Catch::Contains(at + ": rapid drawdown needs section.water"));
  scene = usace();
  scene["analyses"]["lem"]["rapid_drawdown"]["water_after"]["piezometric_line_m"] = {{10, 7}, {121.92, 7}};
  CHECK_THAT(scene_faults(scene), Catch::Contains(at + ".water_after.piezometric_line_m: must span the section's x range"));
  scene = usace();
  scene["analyses"]["lem"]["rapid_drawdown"].erase("water_after");
  CHECK_THAT(scene_faults(scene), Catch::Contains(at + ".water_after"));
  scene = usace();
  scene["analyses"]["lem"]["rapid_drawdown"]["materials"][0]["kc1_friction_angle_deg"] = -3;
  CHECK_THAT(scene_faults(scene), Catch::Contains(at + ".materials[0].kc1_friction_angle_deg: "));
}

}  // namespace test_lem_drawdown
