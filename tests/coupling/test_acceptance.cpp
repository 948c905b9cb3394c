// Acceptance criteria of the surface comparison (analyses.compare.acceptance) and the exit status a pipeline reads.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "coupling/compare/acceptance.hpp"
#include "coupling/compare/comparison.hpp"
#include "coupling/output/comparison_report.hpp"
#include "coupling/scene/scene_schema.hpp"
#include "test_support.hpp"

namespace test_acceptance {

namespace fs = std::filesystem;
using coupling::AcceptanceCriteria;
using coupling::Diagnostics;

namespace {

std::string all_messages(const Diagnostics& diagnostics) {
  std::string text;
  for (const auto& message : diagnostics.messages()) text += message + "\n";
  return text;
}

// The figures of a comparison for two methods: Bishop with both surfaces, Spencer without a critical surface.
coupling::ComparisonResult comparison_with(double entry_dx, double mean_distance, double overlap) {
  coupling::MethodComparison bishop;
  bishop.method = "bishop";
  bishop.lem_factor_of_safety = 0.935;
  bishop.factor_of_safety_on_sph_circle = 1.010;
  bishop.has_geometry = true;
  bishop.entry_offset_m = slope::Point{entry_dx, 0.0};
  bishop.exit_offset_m = slope::Point{0.3, 0.4};
  bishop.mean_normal_distance_m = mean_distance;
  bishop.max_normal_distance_m = 3 * mean_distance;
  bishop.intersection_over_union = overlap;
  coupling::MethodComparison spencer;
  spencer.method = "spencer";
  spencer.lem_factor_of_safety = 0.93;
  coupling::ComparisonResult comparison;
  comparison.methods = {bishop, spencer};
  return comparison;
}

}  // namespace

TEST_CASE("acceptance: limits in metres and in particle spacings, at most and at least", "[compare][acceptance]") {
  AcceptanceCriteria c;
  c.methods = {"bishop"};
  c.entry_offset = coupling::LengthLimit{4.0, true};   // 4 spacings of 0.5 m = 2 m
  c.exit_offset = coupling::LengthLimit{0.5, false};   // |(0.3, 0.4)| = 0.5 m: on the limit passes
  c.mean_normal_distance = coupling::LengthLimit{0.25, false};
  c.min_overlap = 0.7;
  c.max_fs_difference = 0.1;                            // |1.010 - 0.935| = 0.075

  const auto pass = coupling::evaluate_acceptance(c, comparison_with(-1.9, 0.2, 0.8), 0.5);
  CHECK(pass.accepted);
  REQUIRE(pass.criteria.size() == 5);
  CHECK(pass.criteria[0].limit == Approx(2.0));
  CHECK(*pass.criteria[0].measured == Approx(1.9));
  CHECK(*pass.criteria[1].measured == Approx(0.5));
  CHECK(*pass.criteria[4].measured == Approx(0.075));

  const auto fail = coupling::evaluate_acceptance(c, comparison_with(2.1, 0.3, 0.6), 0.5);
  CHECK_FALSE(fail.accepted);
  int failed = 0;
  for (const auto& criterion : fail.criteria) failed += criterion.passed ? 0 : 1;
  CHECK(failed == 3);  // entry 2.1 > 2, mean distance 0.3 > 0.25, overlap 0.6 < 0.7
  const auto lines = coupling::failed_criteria_lines(fail);
  REQUIRE(lines.size() == 3);
  CHECK(lines[0] == "bishop entry_offset_m: 2.1 > 2 (4 particle spacings)");
  CHECK(lines[2] == "bishop overlap: 0.6 < 0.7");
}

TEST_CASE("acceptance: a criterion that cannot be measured fails, and says why", "[compare][acceptance]") {
  AcceptanceCriteria c;
  c.methods = {"spencer"};  // no critical surface figures for spencer in this comparison
  c.mean_normal_distance = coupling::LengthLimit{1.0, false};
  const auto result = coupling::evaluate_acceptance(c, comparison_with(0.0, 0.1, 0.9), 0.5);
  CHECK_FALSE(result.accepted);
  REQUIRE(result.criteria.size() == 1);
  CHECK_FALSE(result.criteria[0].measured);
  CHECK(result.criteria[0].note.find("not measured") != std::string::npos);
  CHECK(coupling::acceptance_json(result)["criteria"][0]["measured"].is_null());
}

TEST_CASE("acceptance: the reader names what is wrong", "[compare][acceptance][scene]") {
  const std::vector<std::string> computed = {"bishop", "spencer"};
  Diagnostics d1;
  CHECK_FALSE(coupling::read_acceptance(nlohmann::json::object(), computed, d1));
  CHECK(all_messages(d1).find("analyses.compare.acceptance: no criterion given") != std::string::npos);

  Diagnostics d2;
  coupling::read_acceptance({{"entry_offset_max_m", 1.0}, {"entry_offset_max_spacings", 2.0}}, computed, d2);
  CHECK(all_messages(d2).find("analyses.compare.acceptance.entry_offset_max_spacings: give the limit either in "
                              "metres") != std::string::npos);

  Diagnostics d3;
  // As in a scene: the schema's checks first (overlap_min's bounds are the schema's), then the reader's.
  const nlohmann::json acceptance = {{"methods", {"janbu"}}, {"overlap_min", 1.5}};
  coupling::validate_against_schema({{"analyses", {{"compare", {{"acceptance", acceptance}}}}}}, d3);
  coupling::read_acceptance(acceptance, computed, d3);
  const std::string text = all_messages(d3);
  CHECK(text.find("analyses.compare.acceptance.methods[0]: method \"janbu\" is not computed") != std::string::npos);
  CHECK(text.find("analyses.compare.acceptance.overlap_min: must be in [0, 1]") != std::string::npos);

  Diagnostics d4;
  const auto ok = coupling::read_acceptance({{"exit_offset_max_spacings", 4}}, computed, d4);
  REQUIRE(ok);
  CHECK(d4.empty());
  CHECK(ok->methods == std::vector<std::string>{"bishop"});  // default: Bishop when it is computed
  CHECK(ok->exit_offset->in_spacings);
}

TEST_CASE("acceptance through the program: accepted gives 0, rejected gives 3 with the failed criteria",
          "[compare][acceptance][cli]") {
  // Thesis slope 2 at dx = 0.5 m for 3 s, as the coarse comparison test: the SPH surface exits at the toe within a
  // few spacings of Bishop's circle. Loose limits accept it; a limit no SPH surface can meet (overlap 100 %,
  // entry within 0 m) rejects it, with status 3 and report status "not_accepted".
  TemporaryFolder folder("acceptance");
  nlohmann::json scene = read_json(fs::path(test_paths::source_dir()) / "cases/thesis_slope2.json");
  scene["analyses"]["sph"]["particle_spacing_m"] = 0.5;
  scene["analyses"]["sph"]["end_time_s"] = 3.0;
  scene["analyses"]["lem"]["methods"] = {"bishop"};
  auto run = [&](const nlohmann::json& acceptance, const std::string& name) {
    scene["analyses"]["compare"] = {{"acceptance", acceptance}};
    const fs::path file = folder.path / (name + ".json");
    std::ofstream(file) << scene.dump(2);
    const std::string command = std::string("\"") + test_paths::binary() + "\" run \"" + file.string() + "\" -o \"" +
                                (folder.path / name).string() + "\" > \"" + (folder.path / (name + ".log")).string() +
                                "\" 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  CHECK(run({{"exit_offset_max_spacings", 6}, {"overlap_min", 0.5}}, "loose") == 0);  // measured: 2.13 m, 77 %
  const nlohmann::json loose = read_json(folder.path / "loose/report.json");
  CHECK(loose["status"] == "ok");
  CHECK(loose["comparison"]["acceptance"]["accepted"] == true);

  CHECK(run({{"entry_offset_max_m", 0.0}, {"overlap_min", 1.0}}, "strict") == 3);
  const nlohmann::json strict = read_json(folder.path / "strict/report.json");
  CHECK(strict["status"] == "not_accepted");
  CHECK(strict["comparison"]["acceptance"]["accepted"] == false);
  CHECK(strict["comparison"]["acceptance"]["criteria"].size() == 2);
  std::ifstream log(folder.path / "strict.log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  CHECK(text.find("not accepted: bishop overlap:") != std::string::npos);
}

}  // namespace test_acceptance
