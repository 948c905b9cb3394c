// Scenes built to hurt (issue 17): nesting hundreds of thousands of levels deep, arrays far larger than anything
// physical, files of hundreds of megabytes, millions of faults. Each is refused with exit status 2 and a message
// naming the JSON path, the limit and why; none may crash the program. The limits are in
// coupling/include/coupling/input_limits.hpp; the large scenes are generated here, in a temporary folder.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/scene/input_limits.hpp"
#include "coupling/scene/scene.hpp"
#include "test_support.hpp"

namespace test_hostile_input {

namespace fs = std::filesystem;

namespace {

nlohmann::json case_scene(const std::string& name) {
  return read_json(fs::path(test_paths::source_dir()) / "cases" / name);
}

// `levels` arrays nested in one another: [[[...]]].
std::string nested_arrays(std::size_t levels) { return std::string(levels, '[') + std::string(levels, ']'); }

// The scene with its "notes" replaced by `levels` nested arrays, so the document nests levels + 1 deep.
std::string with_deep_notes(nlohmann::json scene, std::size_t levels) {
  scene["notes"] = "@deep@";
  std::string text = scene.dump(1);
  text.replace(text.find("\"@deep@\""), 8, nested_arrays(levels));
  return text;
}

fs::path write_file(const fs::path& folder, const std::string& name, const std::string& text) {
  const fs::path file = folder / name;
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

ProgramRun check(const fs::path& scene) { return run_sphslope("check '" + scene.string() + "'"); }

}  // namespace

TEST_CASE("hostile input: a scene nested 300 000 levels deep is refused (exit 2), not a crash", "[cli][hostile]") {
  TemporaryFolder folder("deep-300000");
  const std::string text = "{\"format\": \"sphslope-scene/1\", \"notes\": " + nested_arrays(300'000) + "}";
  const ProgramRun run = check(write_file(folder.path, "deep.json", text));
  INFO(run.output.substr(0, 2000));
  CHECK(run.status == 2);
  CHECK(run.output.find("notes[0][0][0][0][0][0][0]<... ") != std::string::npos);
  CHECK(run.output.find("nested deeper than " + std::to_string(coupling::max_nesting_depth) + " levels") !=
        std::string::npos);
}

TEST_CASE("hostile input: one level beyond the nesting limit is refused, the limit itself is accepted",
          "[cli][hostile]") {
  const nlohmann::json scene = case_scene("thesis_slope2.json");
  const std::size_t limit = coupling::max_nesting_depth;
  TemporaryFolder folder("deep-limit");

  // The top-level object is one level, so `limit - 1` nested arrays in "notes" make the document exactly `limit`
  // deep: a valid scene.
  const ProgramRun at_limit = check(write_file(folder.path, "at_limit.json", with_deep_notes(scene, limit - 1)));
  INFO(at_limit.output.substr(0, 2000));
  CHECK(at_limit.status == 0);
  CHECK(at_limit.output.find("nested deeper") == std::string::npos);

  const ProgramRun beyond = check(write_file(folder.path, "beyond.json", with_deep_notes(scene, limit)));
  INFO(beyond.output.substr(0, 2000));
  CHECK(beyond.status == 2);
  CHECK(beyond.output.find("notes[0][0][0][0][0][0][0]<... " + std::to_string(limit - 12) +
                           " levels ...>[0][0][0][0]: nested deeper than " + std::to_string(limit) +
                           " levels of objects and arrays (at most " + std::to_string(limit) + " allowed") !=
        std::string::npos);
}

TEST_CASE("hostile input: the nesting scan names keys and indices and ignores brackets inside strings",
          "[scene][hostile]") {
  // Depth 3 allowed: the object at a.b[1] would be the fourth level.
  const auto fault = coupling::nesting_depth_fault(R"({"a": {"b": [1, {"c": 2}]}})", 3);
  REQUIRE(fault);
  CHECK(fault->rfind("a.b[1]: nested deeper than 3 levels", 0) == 0);

  // Brackets and escaped quotes inside strings (keys and values) are text, not nesting.
  CHECK_FALSE(coupling::nesting_depth_fault(R"({"[[[[": "{{{{\"[[[[", "k": ["]]]]"]})", 2));
  CHECK(coupling::nesting_depth_fault(R"({"[[[[": "{{{{\"[[[[", "k": [["]]]]"]]})", 2));
  CHECK_FALSE(coupling::nesting_depth_fault("[[]]", 2));
  CHECK(coupling::nesting_depth_fault("[[[]]]", 2));
}

TEST_CASE("hostile input: a scene file above the size limit is refused before it is read", "[cli][hostile]") {
  TemporaryFolder folder("huge-file");
  const fs::path file = folder.path / "huge.json";
  std::ofstream(file).close();
  // A sparse file: no disk space is used, and reading it would take seconds and as much memory.
  fs::resize_file(file, coupling::max_scene_file_bytes + 1);
  const ProgramRun run = check(file);
  INFO(run.output.substr(0, 2000));
  CHECK(run.status == 2);
  CHECK(run.output.find("is too large (" + std::to_string(coupling::max_scene_file_bytes + 1) + " bytes; at most " +
                        std::to_string(coupling::max_scene_file_bytes) + " bytes allowed") != std::string::npos);
}

namespace {

struct OversizedArray {
  const char* scene;            // in cases/
  const char* pointer;          // JSON pointer of the array made too large
  const char* path;             // the same, as the message writes it
  const char* element;          // JSON of one element
  coupling::SizeLimit limit;
  const char* setup = nullptr;  // JSON merged into the scene first (to reach the array), if any
};

const OversizedArray oversized_arrays[] = {
    {"thesis_slope2.json", "/section/profile_lines/0/points_m", "section.profile_lines[0].points_m", "[1, 10]",
     coupling::limits::polyline_points},
    {"thesis_slope2.json", "/section/profile_lines", "section.profile_lines",
     R"({"material": "cohesive soil", "points_m": [[0, 10], [30, 0]]})", coupling::limits::profile_lines},
    {"thesis_slope2.json", "/section/materials", "section.materials",
     R"({"name": "m", "unit_weight_kN_m3": 20, "cohesion_kPa": 1, "friction_angle_deg": 20})",
     coupling::limits::materials},
    {"thesis_slope2.json", "/section/surcharges", "section.surcharges",
     R"({"from_x_m": 0, "to_x_m": 5, "pressure_kPa": 10})", coupling::limits::surcharges},
    {"thesis_slope2.json", "/analyses/lem/methods", "analyses.lem.methods", R"("bishop")",
     coupling::limits::name_list},
    {"thesis_slope2.json", "/analyses/sph/ignore_loads", "analyses.sph.ignore_loads", R"("water")",
     coupling::limits::name_list},
    {"thesis_slope2.json", "/analyses/sph/walls/sides", "analyses.sph.walls.sides", R"("left")",
     coupling::limits::name_list, R"({"analyses": {"sph": {"walls": {}}}})"},
    {"thesis_slope2.json", "/analyses/compare/acceptance/methods", "analyses.compare.acceptance.methods",
     R"("bishop")", coupling::limits::name_list, R"({"analyses": {"compare": {"acceptance": {"overlap_min": 0.5}}}})"},
    {"thesis_slope2.json", "/section/water/piezometric_line_m", "section.water.piezometric_line_m", "[1, 5]",
     coupling::limits::polyline_points, R"({"section": {"water": {"piezometric_line_m": []}}})"},
    {"thesis_slope2.json", "/analyses/lem/surfaces", "analyses.lem.surfaces",
     R"({"name": "s", "points_m": [[5, 10], [20, 0]]})", coupling::limits::slip_surfaces},
    {"thesis_slope2.json", "/analyses/lem/surfaces/0/points_m", "analyses.lem.surfaces[0].points_m", "[5, 10]",
     coupling::limits::slip_surface_points, R"({"analyses": {"lem": {"surfaces": [{"name": "s"}]}}})"},
    {"bui2008_column_collapse.json", "/bodies", "bodies", "{}", coupling::limits::bodies},
    {"bui2008_column_collapse.json", "/bodies/0/polygon_m", "bodies[0].polygon_m", "[0, 0]",
     coupling::limits::polygon_vertices},
};

}  // namespace

TEST_CASE("hostile input: every array beyond its size limit is refused with its path, the limit and why",
          "[cli][hostile]") {
  TemporaryFolder folder("oversized");
  for (const OversizedArray& c : oversized_arrays) {
    nlohmann::json scene = case_scene(c.scene);
    if (c.setup != nullptr) scene.merge_patch(nlohmann::json::parse(c.setup));
    scene[nlohmann::json::json_pointer(c.pointer)] =
        nlohmann::json::array_t(c.limit.max + 1, nlohmann::json::parse(c.element));
    const ProgramRun run = check(write_file(folder.path, "oversized.json", scene.dump()));
    const std::string expected = std::string(c.path) + ": too many " + std::string(c.limit.what) + " (got " +
                                 std::to_string(c.limit.max + 1) + "; at most " + std::to_string(c.limit.max) +
                                 " allowed: " + std::string(c.limit.reason) + ")";
    INFO(c.pointer << "\n" << run.output.substr(0, 2000));
    CHECK(run.status == 2);
    CHECK(run.output.find(expected) != std::string::npos);
  }
}

TEST_CASE("hostile input: a scene with a thousand faults prints the first 200 and counts the rest",
          "[scene][hostile]") {
  nlohmann::json scene = case_scene("thesis_slope2.json");
  const std::size_t bad_points = 1000;
  scene["section"]["profile_lines"][0]["points_m"] = nlohmann::json::array_t(bad_points, "not a point");
  try {
    coupling::parse_scene(scene.dump());
    FAIL("the scene was accepted");
  } catch (const coupling::SceneError& error) {
    const auto& messages = error.messages();
    REQUIRE(messages.size() == coupling::max_reported_faults + 1);
    CHECK(messages.front().rfind("section.profile_lines[0].points_m[0]: expected a point", 0) == 0);
    CHECK(messages.back() == "... and " + std::to_string(bad_points - coupling::max_reported_faults) +
                                 " more faults (only the first " + std::to_string(coupling::max_reported_faults) +
                                 " are shown)");
  }
}

}  // namespace test_hostile_input
