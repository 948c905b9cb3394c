// report.html: the page's content follows report.json (every factor in the table, the verdict, the warnings) and
// stands alone (figures inlined). Its one-page layout is checked in Chromium by scripts/check-report-html.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/output/report_html.hpp"
#include "coupling/scene/scene.hpp"
#include "slope/methods.hpp"
#include "test_support.hpp"

namespace test_report_html {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::size_t count(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

std::string three_decimals(const json& value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", value.get<double>());
  return buffer;
}

}  // namespace

TEST_CASE("report.html of a limit-equilibrium run: every factor of the report, both figures inlined",
          "[report_html][lem]") {
  json scene = json::parse(std::ifstream(fs::path(test_paths::source_dir()) / "cases" / "acads_ex3_weak_layer.json"));
  scene["name"] = "Weak layer <ACADS 3> & its \"specified\" surface";
  const coupling::Scene parsed = coupling::parse_scene(scene.dump(), "acads3.json");
  const TemporaryFolder folder("report-html");
  const fs::path& dir = folder.path;
  const coupling::WorkflowResult out = run_lem_into(parsed, dir);
  REQUIRE(out.status == coupling::ExitStatus::ok);
  CHECK(out.report["report_html"] == "report.html");
  const std::string html = read_text(dir / "report.html");
  CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK_THAT(html, Catch::Contains("Weak layer &lt;ACADS 3&gt; &amp; its &quot;specified&quot; surface"));
  CHECK_THAT(html, Catch::Contains("class=\"status ok\""));
  const json& lem = out.report["lem"];
  REQUIRE(lem["methods"].size() == slope::all_methods().size());  // the scene asks for every method
  for (const auto& [key, method] : lem["methods"].items()) {
    INFO(key);
    CHECK_THAT(html, Catch::Contains("<td class=\"l\">" + key + "</td>"));
    CHECK_THAT(html, Catch::Contains(three_decimals(method["factor_of_safety"])));
    CHECK_THAT(html, Catch::Contains(three_decimals(lem["noncircular"]["methods"][key]["factor_of_safety"])));
    CHECK_THAT(html, Catch::Contains(three_decimals(lem["surfaces"][0]["methods"][key]["factor_of_safety"])));
  }
  // the lowest of each column is marked: Janbu simplified on the specified surface (1.197, ACADS 3(b))
  CHECK_THAT(html, Catch::Contains("class=\"low\">" + three_decimals(lem["surfaces"][0]["methods"]["janbu"]["factor_of_safety"])));
  CHECK(count(html, "<svg") == 2);  // section and safety map, inlined
  CHECK(count(html, "<?xml") == 0);
  CHECK_THAT(html, Catch::Contains("Warnings and errors</h2>\n<p>None.</p>"));
  CHECK_THAT(html, !Catch::Contains("nan") && !Catch::Contains("null"));
}

TEST_CASE("report.html lists errors and warnings once each, marks a failed run, names a missing figure",
          "[report_html]") {
  const coupling::Scene scene = coupling::parse_scene(
      read_text(fs::path(test_paths::source_dir()) / "cases" / "griffiths_lane_1999.json"), "gl.json");
  coupling::RunResults results;
  results.analyses = {"lem", "sph"};
  results.sph.emplace().result.emplace().warnings = {"gravity applied suddenly", "gravity applied suddenly"};
  results.seconds["total"] = 1.5;
  results.lem.emplace().error = "lem: the limit-equilibrium search failed: out of memory";
  const coupling::RunPage page{"failed", {"sph: the run stopped: non-positive density"}, {"figures/missing.svg"}};
  const std::string html =
      coupling::report_html(scene, results, page, fs::temp_directory_path() / "no_such_run_folder");
  CHECK_THAT(html, Catch::Contains("class=\"status failed\""));
  CHECK_THAT(html, Catch::Contains("<li>sph: the run stopped: non-positive density</li>"));
  CHECK(count(html, "gravity applied suddenly") == 1);
  CHECK_THAT(html, Catch::Contains("figures/missing.svg could not be read"));
  CHECK_THAT(html, !Catch::Contains("Limit equilibrium: factor of safety"));  // no lem block, no table
  CHECK_THAT(html, Catch::Contains("<td class=\"l\">soil</td><td>20.00</td><td>10.0</td><td>20.0</td>"));
}

}  // namespace test_report_html
