// The non-circular search on every slope scene of cases/, and its scene key and report block.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "coupling/output/run_files.hpp"
#include "coupling/scene/scene.hpp"
#include "slope/search.hpp"

namespace test_lem_noncircular {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::vector<fs::path> case_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(test_paths::source_dir()) / "cases"))
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("non-circular search on every case: the optimised polyline is not above the critical circle",
          "[lem][noncircular]") {
  int scenes = 0;
  int weak_layer_methods = 0;  // searched methods on the ACADS 3 weak layer
  for (const fs::path& file : case_files()) {
    const coupling::Scene scene = coupling::load_scene(file);
    if (!scene.section) continue;
    ++scenes;
    const coupling::LemAnalysis lem = scene.analyses.lem ? *scene.analyses.lem : coupling::default_lem_analysis();
    const slope::SearchResult circular = slope::search_critical(scene.section->section, lem.methods, lem.search);
    const slope::NonCircularResult r = slope::search_noncircular(scene.section->section, circular, lem.search);
    REQUIRE(r.methods.size() == circular.methods.size());
    for (const slope::NonCircularSurface& m : r.methods) {
      INFO(file.filename().string() << " " << slope::method_key(m.method));
      REQUIRE(m.circle_factor_of_safety);
      REQUIRE(m.result.factor_of_safety);
      CHECK(m.searched == (m.method != slope::Method::ordinary));
      // what the report says it is: the circle, or a polyline that beats it
      if (m.from_circle) {
        CHECK(*m.result.factor_of_safety == *m.circle_factor_of_safety);
      } else {
        REQUIRE(m.polyline_factor_of_safety);
        CHECK(*m.result.factor_of_safety == *m.polyline_factor_of_safety);
        CHECK(*m.polyline_factor_of_safety < *m.circle_factor_of_safety);
      }
      // a weak layer is what a polyline follows and a circle cannot: there it is well below the circle
      if (file.filename() == "acads_ex3_weak_layer.json" && m.searched) {
        ++weak_layer_methods;
        CHECK_FALSE(m.from_circle);
        CHECK(*m.result.factor_of_safety < 0.95 * *m.circle_factor_of_safety);
      }
      // the search itself, before the fallback to the circle, reaches the circle's factor of safety
      if (m.searched) {
        REQUIRE(m.polyline_factor_of_safety);
        CHECK(*m.polyline_factor_of_safety <= *m.circle_factor_of_safety * (1.0 + 1e-3));
      }
    }
  }
  CHECK(scenes >= 10);
  CHECK(weak_layer_methods >= 5);
}

TEST_CASE("analyses.lem.noncircular_search: read, refused when wrong, reported", "[lem][noncircular]") {
  const fs::path file = fs::path(test_paths::source_dir()) / "cases" / "acads_ex3_weak_layer.json";
  json scene = json::parse(std::ifstream(file));
  scene["analyses"]["lem"]["methods"] = {"spencer", "ordinary"};
  scene["analyses"]["lem"]["noncircular_search"] = {{"segments", 16}};
  const coupling::Scene parsed = coupling::parse_scene(scene.dump());
  REQUIRE(parsed.analyses.lem->noncircular);
  CHECK(parsed.analyses.lem->noncircular->segments == 16);

  json bad = scene;
  bad["analyses"]["lem"]["noncircular_search"] = {{"segments", 24}};
  try {
    (void)coupling::parse_scene(bad.dump());
    FAIL("segments 24 accepted");
  } catch (const coupling::SceneError& e) {
    CHECK_THAT(e.what(), Catch::Contains("analyses.lem.noncircular_search.segments") && Catch::Contains("8, 16, 32"));
  }
  bad["analyses"]["lem"]["noncircular_search"] = {{"segmnts", 16}};
  CHECK_THROWS_WITH(coupling::parse_scene(bad.dump()), Catch::Contains("segmnts"));

  coupling::WorkflowOptions options;
  options.mode = coupling::Mode::lem;
  const coupling::WorkflowResult out = coupling::run_scene(parsed, options);
  REQUIRE(out.status == coupling::ExitStatus::ok);
  const json& nc = out.report["lem"]["noncircular"];
  CHECK(nc["settings"]["segments"] == 16);
  const json& spencer = nc["methods"]["spencer"];
  CHECK(spencer["searched"] == true);
  CHECK(spencer["from_circle"] == false);
  CHECK(spencer["surface"]["type"] == "polyline");
  CHECK(spencer["surface"]["points_m"].size() == 17);
  CHECK(spencer["factor_of_safety"].get<double>() < out.report["lem"]["methods"]["spencer"]["factor_of_safety"].get<double>());
  CHECK(nc["methods"]["ordinary"]["searched"] == false);
  CHECK(nc["methods"]["ordinary"]["surface"]["type"] == "circle");
  CHECK(out.report["timing_s"].contains("lem_noncircular"));
}

}  // namespace test_lem_noncircular
