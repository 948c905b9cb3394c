// The scene schema (docs/scene.schema.json) as the one source of the format: every case validates against it, the
// docs and the fuzz dictionary list exactly its keys and names, and the reader reports where the program and the
// schema disagree (a default, an enum's names).
#include <catch2/catch.hpp>
#include "test_paths.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "coupling/scene/input_limits.hpp"
#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/scene.hpp"
#include "coupling/scene/scene_schema.hpp"
#include "slope/methods.hpp"
#include "sph/engine/settings.hpp"
#include "sph/fluid/settings.hpp"
#include "sph/mps/settings.hpp"
#include "sph/soil/model.hpp"

namespace test_scene_schema {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

fs::path source(const std::string& relative) { return fs::path(test_paths::source_dir()) / relative; }

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every property name and every enum or constant string of the schema, through its definitions too.
void schema_names(const nlohmann::ordered_json& node, std::set<std::string>& keys, std::set<std::string>& values) {
  if (node.is_object()) {
    if (const auto p = node.find("properties"); p != node.end() && p->is_object())
      for (const auto& [key, child] : p->items()) keys.insert(key);
    if (const auto e = node.find("enum"); e != node.end() && e->is_array())
      for (const auto& v : *e)
        if (v.is_string()) values.insert(v.get<std::string>());
    if (const auto c = node.find("const"); c != node.end() && c->is_string()) values.insert(c->get<std::string>());
    for (const auto& [key, child] : node.items()) schema_names(child, keys, values);
  } else if (node.is_array()) {
    for (const auto& child : node) schema_names(child, keys, values);
  }
}

std::vector<std::string> faults_of(const json& document) {
  coupling::Diagnostics diagnostics;
  coupling::validate_against_schema(document, diagnostics);
  return diagnostics.messages();
}

}  // namespace

TEST_CASE("schema: every scene in cases/ validates against the scene schema", "[scene][schema]") {
  // The stability matrix's cases beyond a limit are refused by design (scripts/stability_matrix.py checks their
  // messages): the schema refuses these two at their cfl, the others pass it and meet a check of the program's.
  const std::map<std::string, std::string> refused = {{"isph_cfl_beyond_limit.json", "analyses.isph.cfl: must be"},
                                                      {"mps_cfl_beyond_limit.json", "analyses.mps.cfl: must be"}};
  std::size_t scenes = 0;
  for (const auto& entry : fs::recursive_directory_iterator(source("cases"))) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path().string());
    const json document = json::parse(text_of(entry.path()));
    const auto faults = faults_of(document);
    if (const auto r = refused.find(entry.path().filename().string()); r != refused.end()) {
      REQUIRE(faults.size() == 1);
      CHECK(faults[0].find(r->second) == 0);
      continue;
    }
    CHECK(faults.empty());
    if (entry.path().parent_path().filename() != "stability")
      CHECK_NOTHROW(coupling::scene_from_json(document, entry.path()));
    ++scenes;
  }
  CHECK(scenes > 60);
}

TEST_CASE("schema: the cases point editors at the schema", "[scene][schema]") {
  for (const auto& entry : fs::recursive_directory_iterator(source("cases"))) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path().string());
    const json document = json::parse(text_of(entry.path()));
    const fs::path schema = fs::relative(source("docs/scene.schema.json"), entry.path().parent_path());
    CHECK(document.value("$schema", "") == schema.generic_string());
  }
}

TEST_CASE("schema: its faults are worded like every other scene fault, at their JSON paths", "[scene][schema]") {
  json scene = json::parse(text_of(source("cases/thesis_slope2.json")));
  scene["section"]["materials"][0]["cohesion_kPa"] = -1;
  scene["section"]["materials"][0]["cohesion_kpa"] = 1;
  scene["section"]["materials"][0]["friction_angle_deg"] = "twenty";
  scene["analyses"]["lem"]["slices"] = 4.5;
  scene["section"].erase("bottom_y_m");
  const auto messages = faults_of(scene);
  auto has = [&](const std::string& text) {
    for (const auto& m : messages)
      if (m.find(text) != std::string::npos) return true;
    return false;
  };
  INFO([&] {
    std::string all;
    for (const auto& m : messages) all += m + "\n";
    return all;
  }());
  CHECK(has("section.materials[0].cohesion_kPa: must be >= 0 (got -1)"));
  CHECK(has("section.materials[0].cohesion_kpa: unknown key (did you mean \"cohesion_kPa\"? allowed here: name, "));
  CHECK(has("section.materials[0].friction_angle_deg: expected a number (in [0, 90)), got a string \"twenty\""));
  CHECK(has("analyses.lem.slices: expected a whole number (in [5, 1000]), got a number 4.5"));
  CHECK(has("section.bottom_y_m: missing (required: a number)"));
  CHECK(messages.size() == 5);  // each fault once: the objects above them add none of their own
}

TEST_CASE("schema: docs/scene-format.md documents every key of the schema and no other", "[scene][schema]") {
  std::set<std::string> keys, values;
  schema_names(coupling::scene_schema(), keys, values);
  keys.erase("notes");
  keys.erase("$schema");
  // The key cells of the tables of the scene part (before the error messages): `a`, or `a`, `b` in one row.
  const std::string docs = text_of(source("docs/scene-format.md"));
  const std::string scene_part = docs.substr(0, docs.find("\n## Error messages"));
  std::set<std::string> documented;
  const std::regex row(R"(\n\| ((?:`[^`|]+`(?:, )?)+) \|)");
  const std::regex name("`\"?([A-Za-z_][A-Za-z0-9_]*)\"?`");
  for (auto it = std::sregex_iterator(scene_part.begin(), scene_part.end(), row); it != std::sregex_iterator(); ++it) {
    const std::string cell = (*it)[1];
    for (auto n = std::sregex_iterator(cell.begin(), cell.end(), name); n != std::sregex_iterator(); ++n)
      documented.insert((*n)[1]);
  }
  for (const std::string& key : keys) {
    INFO("in the schema, not in a table of docs/scene-format.md: " << key);
    CHECK(documented.count(key) == 1);
  }
  for (const std::string& key : documented) {
    INFO("in a table of docs/scene-format.md, not in the schema: " << key);
    CHECK(keys.count(key) == 1);
  }
}

TEST_CASE("schema: the fuzz dictionary lists every key and name of the schema (tests/fuzz/make_dict.py)",
          "[scene][schema]") {
  std::set<std::string> keys, values;
  schema_names(coupling::scene_schema(), keys, values);
  std::set<std::string> names;
  std::ifstream dict(source("tests/fuzz/scene.dict"));
  const std::regex quoted_name(R"re(^"\\"(.*)\\""$)re");
  for (std::string line; std::getline(dict, line);) {
    std::smatch m;
    if (std::regex_match(line, m, quoted_name)) names.insert(m[1]);
  }
  std::set<std::string> expected = keys;
  expected.insert(values.begin(), values.end());
  CHECK(names == expected);
}

TEST_CASE("schema: the reader reports where the program and the schema disagree", "[scene][schema]") {
  coupling::Diagnostics diagnostics;
  const json lem = {{"refine", true}};
  coupling::JsonReader reader(lem, "analyses.lem", diagnostics);
  REQUIRE(reader.schema() != nullptr);
  SECTION("a default") {
    // The schema's default for analyses.lem.slices is 50; a program that fell back to 49 would disagree.
    const auto node = coupling::schema_node_at("analyses.lem.slices");
    REQUIRE(node.default_value() != nullptr);
    CHECK(reader.number_or("slices", node.default_value()->get<double>()) == 50);
    CHECK(diagnostics.empty());
    reader.number_or("slices", 49);
    REQUIRE(diagnostics.size() == 1);
    CHECK(diagnostics.messages()[0].find("analyses.lem.slices: the program and its scene schema") == 0);
  }
  SECTION("an enum's names") {
    const json sph = json::object();
    coupling::JsonReader block(sph, "analyses.sph", diagnostics);
    const auto node = coupling::schema_node_at("analyses.sph.kernel");
    const auto names = node.enum_names();
    REQUIRE(names.size() >= 2);
    const std::string current = node.default_value() ? node.default_value()->get<std::string>() : names[0];
    coupling::check_names_against_schema(block, "kernel", names, current);
    CHECK(diagnostics.empty());
    coupling::check_names_against_schema(block, "kernel", {names[1], names[0]}, current);
    REQUIRE(diagnostics.size() == 1);
    CHECK(diagnostics.messages()[0].find("analyses.sph.kernel: the program and its scene schema") == 0);
  }
  SECTION("the names of an array's elements") {
    const json sph = json::object();
    coupling::JsonReader block(sph, "analyses.sph", diagnostics);
    coupling::check_names_against_schema(block, "ignore_loads", coupling::names_of(coupling::section_load_names), "",
                                         /*items=*/true);
    CHECK(diagnostics.empty());
    coupling::check_names_against_schema(block, "ignore_loads", {"water", "seismic"}, "", /*items=*/true);
    REQUIRE(diagnostics.size() == 1);
    CHECK(diagnostics.messages()[0].find("analyses.sph.ignore_loads: the program and its scene schema") == 0);
  }
}

TEST_CASE("schema: the bounds the engine owns are the schema's", "[scene][schema]") {
  using sph::EngineSettings;
  using Fluid = sph::fluid::Settings;
  using Mps = sph::mps::Settings;
  const double soil_cfl = std::max(sph::soil::max_cfl(sph::soil::TimeIntegration::verlet),
                                   sph::soil::max_cfl(sph::soil::TimeIntegration::predictor_corrector));
  const std::vector<std::pair<const char*, coupling::Bounds>> owned = {
      {"analyses.sph.smoothing_length_ratio",
       coupling::Bounds::closed(EngineSettings::h_over_dx_min, EngineSettings::h_over_dx_max)},
      {"analyses.sph.cfl", {0.0, false, soil_cfl, true}},
      {"analyses.isph.h_over_dx",
       coupling::Bounds::closed(EngineSettings::h_over_dx_min, EngineSettings::h_over_dx_max)},
      {"analyses.isph.wall_clearance", coupling::Bounds::half_open(0.0, Fluid::max_wall_clearance)},
      {"analyses.isph.cfl", {0.0, false, Fluid::max_cfl, true}},
      {"analyses.mps.re_over_dx", coupling::Bounds::closed(Mps::min_re_over_dx, Mps::max_re_over_dx)},
      {"analyses.mps.surface_beta", coupling::Bounds::closed(Mps::min_surface_beta, Mps::max_surface_beta)},
      {"analyses.mps.cfl", {0.0, false, Mps::max_cfl, true}},
  };
  for (const auto& [path, bounds] : owned) {
    INFO(path);
    const auto node = coupling::schema_node_at(path);
    REQUIRE(node);
    CHECK(node.bounds().describe() == bounds.describe());
  }
}

TEST_CASE("schema: the method names and their default list are the method table's", "[scene][schema]") {
  // The table (slope/src/method_table.cpp) is read by the search and the report; the schema by the scene reader
  // and editors: a method added to one alone would be run but refused by name, or the other way round.
  std::vector<std::string> table;
  for (const slope::Method m : slope::all_methods()) table.emplace_back(slope::method_key(m));
  CHECK(coupling::schema_node_at("analyses.lem.methods[0]").enum_names() == table);
  const auto* listed = coupling::schema_node_at("analyses.lem.methods").default_value();
  REQUIRE(listed != nullptr);
  CHECK(listed->get<std::vector<std::string>>() == table);
}

TEST_CASE("schema: its array size limits are the program's limits on hostile input", "[scene][schema]") {
  namespace limits = coupling::limits;
  const std::vector<std::pair<const char*, coupling::SizeLimit>> arrays = {
      {"section.profile_lines[0].points_m", limits::polyline_points},
      {"section.water.piezometric_line_m", limits::polyline_points},
      {"section.profile_lines", limits::profile_lines},
      {"section.materials", limits::materials},
      {"section.surcharges", limits::surcharges},
      {"section.line_loads", limits::line_loads},
      {"section.reinforcement", limits::reinforcement},
      {"analyses.lem.methods", limits::name_list},
      {"analyses.lem.surfaces", limits::slip_surfaces},
      {"analyses.lem.surfaces[0].points_m", limits::slip_surface_points},
      {"analyses.sph.ignore_loads", limits::name_list},
      {"analyses.compare.acceptance.methods", limits::name_list},
      {"bodies", limits::bodies},
      {"analyses.isph.solids", limits::solids},
      {"bodies[0].polygon_m", limits::polygon_vertices},
  };
  for (const auto& [path, limit] : arrays) {
    INFO(path);
    const auto node = coupling::schema_node_at(path);
    REQUIRE(node);
    const auto& json = *node.json();
    REQUIRE(json.contains("maxItems"));
    CHECK(json["maxItems"].get<double>() == static_cast<double>(limit.max));
    CHECK(json.value("x-items", "") == limit.what);
    CHECK(json.value("x-limit-reason", "") == limit.reason);
  }
}

}  // namespace test_scene_schema
