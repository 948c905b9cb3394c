// The surveyed-profile case (cases/surveyed_profile.json: 2427 vertices of a real LiDAR transect) through
// `sphslope lem`, checked against the same profile reduced to its 38 main breaks
// (cases/surveyed_profile_simplified.json, Douglas-Peucker with a 1 m tolerance).
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace test_surveyed_profile {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& text) { return "'" + text + "'"; }

ProgramRun run_lem(const fs::path& scene, const fs::path& out) {
  return run_sphslope("lem " + quoted(scene.string()) + " -o " + quoted(out.string()));
}

// A copy of a case limited to the given methods (the seven methods are run by hand, docs/validation.md).
fs::path with_methods(const fs::path& scene, const nlohmann::json& methods, const fs::path& folder) {
  nlohmann::json json = read_json(scene);
  json["analyses"] = nlohmann::json{{"lem", json["analyses"]["lem"]}};
  json["analyses"]["lem"]["methods"] = methods;
  const fs::path copy = folder / scene.filename();
  std::ofstream(copy) << json.dump();
  return copy;
}

}  // namespace

TEST_CASE("surveyed profile: LE on 2427 LiDAR vertices agrees with the profile reduced to its main breaks",
          "[cli][lem][e2e][survey]") {
  TemporaryFolder folder("survey");
  const fs::path cases = fs::path(test_paths::source_dir()) / "cases";
  const nlohmann::json scene = read_json(cases / "surveyed_profile.json");
  const auto& ground = scene["section"]["profile_lines"][0]["points_m"];
  REQUIRE(ground.size() >= 1000);  // a real survey, not a handful of breaks

  const nlohmann::json methods = {"ordinary", "bishop", "janbu", "janbu_corrected", "spencer", "morgenstern_price",
                                   "morgenstern_price_constant"};
  fs::create_directories(folder.path / "full");
  fs::create_directories(folder.path / "simplified");
  const fs::path full = with_methods(cases / "surveyed_profile.json", methods, folder.path / "full");
  const fs::path simple = with_methods(cases / "surveyed_profile_simplified.json", methods, folder.path / "simplified");

  const ProgramRun a = run_lem(full, folder.path / "full" / "out");
  INFO(a.output);
  REQUIRE(a.status == 0);
  const ProgramRun b = run_lem(simple, folder.path / "simplified" / "out");
  INFO(b.output);
  REQUIRE(b.status == 0);
  const nlohmann::json ra = read_json(folder.path / "full" / "out" / "report.json");
  const nlohmann::json rb = read_json(folder.path / "simplified" / "out" / "report.json");
  REQUIRE(ra["status"] == "ok");
  REQUIRE(rb["status"] == "ok");

  for (const auto& method : methods) {
    const std::string name = method.get<std::string>();
    INFO(name);
    REQUIRE(ra["lem"]["methods"].contains(name));
    const nlohmann::json& m = ra["lem"]["methods"][name];
    REQUIRE(m["factor_of_safety"].is_number());
    const double fs_full = m["factor_of_safety"].get<double>();
    CHECK(std::isfinite(fs_full));
    CHECK(m["surface"]["type"] == "circle");
    // The automatic search over the whole section finds the steep hillside between the first valley (toe near
    // x = 252 m) and the first ridge (x = 300-480 m), as the simplified profile does.
    const double entry = m["surface"]["entry_m"][0].get<double>();
    const double exit = m["surface"]["exit_m"][0].get<double>();
    CHECK(entry >= 300.0);
    CHECK(entry <= 480.0);
    CHECK(exit >= 150.0);
    CHECK(exit <= 300.0);
    double weight = 0.0;
    for (const auto& slice : m["slices"]) weight += slice["weight_kN_m"].get<double>();
    CHECK(weight > 0.0);

    // Independent value: the same slope reduced to 38 vertices, every dropped vertex within 1 m of the reduced
    // line. On a sliding mass about 90 m long and up to 20 m thick a ground surface moved by at most 1 m (by much
    // less on average) changes the driving weight and the resisting base by a few per cent at most, so the two
    // critical factors of safety must agree within 0.05 (about 4 %). A slicing error on the dense profile (a
    // vertex dropped, a slice weight summed twice) moves it by far more.
    const double fs_simple = rb["lem"]["methods"][name]["factor_of_safety"].get<double>();
    CHECK(fs_full == Approx(fs_simple).margin(0.05));
  }
}

}  // namespace test_surveyed_profile
