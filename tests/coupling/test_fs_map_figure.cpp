// The safety map of the search (figures/fs_map.svg): its method from the scene (default Bishop), its clipped band
// scale, the critical circular and non-circular surfaces drawn on it.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/output/figures.hpp"
#include "coupling/scene/scene.hpp"
#include "test_support.hpp"

namespace test_fs_map_figure {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json weak_layer_scene() {
  return json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases" / "acads_ex3_weak_layer.json"));
}

}  // namespace

TEST_CASE("fs_band_edges: nice steps covering the range, 1.0 on an edge", "[figures][fs_map]") {
  struct Range {
    double lowest, top;
    bool straddles_one;  // the edges run from below 1.0 to above it: 1.0 must be one of them
  };
  for (const auto& [lowest, top, straddles_one] : {Range{0.912, 1.368, true}, Range{1.376, 2.064, false},
                                                   Range{0.43, 3.1, true}, Range{2.5, 2.5, false}}) {
    INFO(lowest << " .. " << top);
    const std::vector<double> edges = coupling::fs_band_edges(lowest, top);
    REQUIRE(edges.size() >= 3);
    CHECK(edges.size() <= 16);
    CHECK(edges.front() <= lowest);
    CHECK(edges.back() >= std::max(top, lowest + 0.1) - 1e-12);
    const double step = edges[1] - edges[0];
    for (std::size_t k = 1; k < edges.size(); ++k) CHECK(edges[k] - edges[k - 1] == Approx(step));
    REQUIRE((edges.front() < 1.0 && edges.back() > 1.0) == straddles_one);
    bool on_edge = false;
    for (double e : edges) on_edge = on_edge || std::abs(e - 1.0) < 1e-12;
    CHECK(on_edge == straddles_one);
  }
}

TEST_CASE("analyses.lem.fs_map: method defaults to Bishop, refused when not analysed, and the figure shows both "
          "critical surfaces",
          "[lem][fs_map][figures]") {
  json scene = weak_layer_scene();
  scene["analyses"]["lem"]["noncircular_search"] = json::object();
  const coupling::Scene defaults = coupling::parse_scene(scene.dump());
  REQUIRE(defaults.analyses.lem->search.fs_map_method);
  CHECK(*defaults.analyses.lem->search.fs_map_method == slope::Method::bishop);  // ordinary is listed first
  CHECK_FALSE(defaults.analyses.lem->fs_map_scale_max);

  json bad = scene;
  bad["analyses"]["lem"]["methods"] = {"spencer", "janbu"};
  bad["analyses"]["lem"]["fs_map"] = {{"method", "bishop"}};
  CHECK_THROWS_WITH(coupling::parse_scene(bad.dump()),
                    Catch::Contains("analyses.lem.fs_map.method") && Catch::Contains("spencer, janbu"));
  bad["analyses"]["lem"]["fs_map"] = {{"colour_scale_max", -1.0}};
  CHECK_THROWS_WITH(coupling::parse_scene(bad.dump()), Catch::Contains("analyses.lem.fs_map.colour_scale_max"));
  bad["analyses"]["lem"]["fs_map"] = {{"methd", "spencer"}};
  CHECK_THROWS_WITH(coupling::parse_scene(bad.dump()), Catch::Contains("methd"));
  bad["analyses"]["lem"].erase("fs_map");
  CHECK(*coupling::parse_scene(bad.dump()).analyses.lem->search.fs_map_method == slope::Method::spencer);

  scene["analyses"]["lem"]["methods"] = {"bishop", "spencer"};
  scene["analyses"]["lem"]["fs_map"] = {{"method", "spencer"}, {"colour_scale_max", 2.0}};
  const coupling::Scene parsed = coupling::parse_scene(scene.dump());
  const TemporaryFolder folder("fs-map");
  const fs::path& dir = folder.path;
  const coupling::WorkflowResult out = run_lem_into(parsed, dir);
  REQUIRE(out.status == coupling::ExitStatus::ok);
  CHECK(out.report["lem"]["search"]["fs_map_method"] == "spencer");
  const std::string svg = read_text(dir / "figures" / "fs_map.svg");
  CHECK_THAT(svg, Catch::Contains("Safety map of the search (spencer)"));
  char circle[64], polyline[64];
  std::snprintf(circle, sizeof circle, "critical circle, FS = %.3f",
                out.report["lem"]["methods"]["spencer"]["factor_of_safety"].get<double>());
  std::snprintf(polyline, sizeof polyline, "critical non-circular surface, FS = %.3f",
                out.report["lem"]["noncircular"]["methods"]["spencer"]["factor_of_safety"].get<double>());
  CHECK_THAT(svg, Catch::Contains(circle) && Catch::Contains(polyline));
  CHECK_THAT(svg, Catch::Contains("&gt; 2<"));  // the scale stops at the given 2.0
}

}  // namespace test_fs_map_figure
