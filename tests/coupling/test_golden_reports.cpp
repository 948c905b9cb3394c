// Golden tests of what a run writes: report.json, report.html and the SVG figures of representative scenes (every
// analysis: LE with given surfaces and the non-circular search, SPH with the comparison, strength reduction, the
// particle scene, the ISPH tank and landslide, the WC-MPS collapse) and the study of a coarse column, pinned before
// the output code is restructured ("a restructure changes no result").
//
// The files are large (report.json of a slope holds the safety map's circles: megabytes), so the golden file
// tests/golden/reports.txt keeps, for each run, a 64-bit FNV-1a hash of every block of report.json down to the
// second level (so a change names the block that changed), of report.html and of each figure. What varies from run
// to run is left out first: wall-clock times (keys timing_s, seconds, wall_s, *_seconds, *_per_second; in the HTML
// every number of seconds), the temporary folder's path and the source tree's (CI builds in another folder).
//
// Regenerate with scripts/update-golden "[reports]" -- only when a run's output is MEANT to change.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/output/run_files.hpp"
#include "coupling/studies/study.hpp"
#include "test_support.hpp"

namespace test_golden_reports {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path golden_file = fs::path(test_paths::source_dir()) / "tests" / "golden" / "reports.txt";

bool update_mode() {
  const char* value = std::getenv("SPHSLOPE_UPDATE_GOLDEN");
  return value != nullptr && std::string(value) == "1";
}

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string hex(std::uint64_t h) {
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

bool volatile_key(const std::string& key) {
  return key == "timing_s" || key == "seconds" || key == "wall_s" || key.ends_with("_seconds") ||
         key.ends_with("_per_second");
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); !from.empty() && at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// A text with the run folder's path as <dir> and the source tree's (where the cases are read from) as <source>.
std::string without_paths(const std::string& text, const std::string& dir) {
  return replace_all(replace_all(text, dir, "<dir>"), test_paths::source_dir(), "<source>");
}

// The report without wall-clock times, with the paths of the run folder and the source tree replaced.
json normalised(const json& value, const std::string& dir) {
  if (value.is_object()) {
    json out = json::object();
    for (auto it = value.begin(); it != value.end(); ++it)
      if (!volatile_key(it.key())) out[it.key()] = normalised(it.value(), dir);
    return out;
  }
  if (value.is_array()) {
    json out = json::array();
    for (const json& item : value) out.push_back(normalised(item, dir));
    return out;
  }
  if (value.is_string()) return without_paths(value.get<std::string>(), dir);
  return value;
}

// "name/<path> <hash>" lines: every block of the report to the second level, report.html, every file under figures/.
std::vector<std::string> fingerprint(const std::string& name, const fs::path& run, const fs::path& root,
                                     const char* report_name = "report.json", bool with_figures = true) {
  std::vector<std::string> lines;
  const json report = normalised(read_json(run / report_name), root.string());
  for (auto it = report.begin(); it != report.end(); ++it) {
    if (it.value().is_object()) {
      for (auto inner = it.value().begin(); inner != it.value().end(); ++inner)
        lines.push_back(name + "/" + report_name + ":" + it.key() + "." + inner.key() + " " +
                        hex(fnv1a(inner.value().dump())));
    } else {
      lines.push_back(name + "/" + report_name + ":" + it.key() + " " + hex(fnv1a(it.value().dump())));
    }
  }
  if (fs::exists(run / "report.html")) {
    static const std::regex seconds(R"([0-9]+(\.[0-9]+)? s\b)");
    const std::string html = std::regex_replace(without_paths(read_text(run / "report.html"), root.string()),
                                                seconds, "# s");
    lines.push_back(name + "/report.html " + hex(fnv1a(html)));
  }
  if (with_figures && fs::exists(run / "figures")) {
    std::vector<fs::path> figures;
    for (const auto& entry : fs::directory_iterator(run / "figures")) figures.push_back(entry.path());
    std::sort(figures.begin(), figures.end());
    for (const fs::path& f : figures)
      lines.push_back(name + "/figures/" + f.filename().string() + " " +
                      hex(fnv1a(without_paths(read_text(f), root.string()))));
  }
  return lines;
}

struct GoldenRun {
  const char* name;
  const char* scene;  // in cases/
  const char* patch;  // merged into the scene
  coupling::Mode mode = coupling::Mode::run;
};

const GoldenRun golden_runs[] = {
    {"slope2_sph_compare", "thesis_slope2.json",
     R"({"analyses": {"sph": {"particle_spacing_m": 0.5, "end_time_s": 3.0},
                      "lem": {"noncircular_search": {}}, "compare": {}}})"},
    {"acads3_lem", "acads_ex3_weak_layer.json", "{}", coupling::Mode::lem},
    {"two_layer_water_lem", "two_layer_water.json", "{}", coupling::Mode::lem},
    {"usace_rapid_drawdown", "usace_1902_rapid_drawdown.json", "{}", coupling::Mode::lem},
    {"li_lumb_probabilistic", "li_lumb_1987_probabilistic.json",
     R"({"analyses": {"lem": {"probabilistic": {"samples": 500, "sampling": "latin_hypercube",
                                                "correlations": [{"material": "soil", "cohesion_friction": -0.3}]}}}})",
     coupling::Mode::lem},
    {"griffiths_lane_srm", "griffiths_lane_1999_srm.json",
     R"({"analyses": {"sph": {"particle_spacing_m": 1.0}, "srm": {"tolerance": 0.1}}})"},
    {"bui_column", "bui2008_column_collapse.json",
     R"({"analyses": {"sph": {"particle_spacing_m": 0.01, "end_time_s": 0.2}}})"},
    {"isph_martin_moyce", "isph_dam_break_martin_moyce.json",
     R"({"analyses": {"isph": {"particle_spacing_m": 0.005715, "end_time_s": 0.12, "snapshots_s": [0.06]}}})"},
    {"isph_still_tank", "isph_still_tank.json",
     R"({"analyses": {"isph": {"particle_spacing_m": 0.04, "end_time_s": 0.3, "snapshots_s": [0.3]}}})"},
    {"isph_heinrich_submarine", "isph_heinrich_submarine.json",
     R"({"analyses": {"isph": {"particle_spacing_m": 0.05, "end_time_s": 0.6, "snapshots_s": [0.5]}}})"},
    {"mps_dry_collapse", "mps_dry_collapse_lajeunesse.json",
     R"({"analyses": {"mps": {"particle_spacing_m": 0.01, "end_time_s": 0.2}}})"},
};

}  // namespace

TEST_CASE("golden: report.json, report.html and the figures of representative runs", "[golden][reports]") {
  TemporaryFolder folder("golden-reports");
  std::vector<std::string> actual;
  for (const GoldenRun& g : golden_runs) {
    INFO(g.name);
    json scene = read_json(fs::path(test_paths::source_dir()) / "cases" / g.scene);
    scene.merge_patch(json::parse(g.patch));
    const fs::path file = folder.path / (std::string(g.name) + ".json");
    std::ofstream(file) << scene.dump(1);
    coupling::WorkflowOptions options;
    options.mode = g.mode;
    options.output_dir = folder.path / g.name;
    const coupling::WorkflowResult out = coupling::run_scene_file(file, options);
    INFO([&] {
      std::string errors;
      for (const std::string& e : out.errors) errors += e + "\n";
      return errors;
    }());
    REQUIRE(out.report_file);
    const std::vector<std::string> lines = fingerprint(g.name, folder.path / g.name, folder.path);
    actual.insert(actual.end(), lines.begin(), lines.end());
  }
  {  // the study of a coarse elastic column at two spacings: study.json (its figure plots the wall time: left out)
    coupling::StudyOptions options;
    options.spacings = {0.1, 0.05};
    options.output_dir = folder.path / "study_elastic_column";
    const coupling::StudyResult study =
        coupling::run_study(fs::path(test_paths::source_dir()) / "cases" / "elastic_column.json", options);
    REQUIRE(study.status == coupling::ExitStatus::ok);
    const std::vector<std::string> lines =
        fingerprint("study_elastic_column", options.output_dir, folder.path, "study.json", false);
    actual.insert(actual.end(), lines.begin(), lines.end());
  }
  if (update_mode()) {
    std::ofstream out(golden_file);
    out << "# hashes of the normalised outputs of the runs of tests/coupling/test_golden_reports.cpp; generated by:"
           " scripts/update-golden \"[reports]\"\n";
    for (const std::string& line : actual) out << line << "\n";
    FAIL_CHECK("update mode (SPHSLOPE_UPDATE_GOLDEN=1): wrote " << golden_file.string() << ", compared nothing");
    return;
  }
  std::map<std::string, std::string> golden;
  {
    std::ifstream in(golden_file);
    REQUIRE(in.good());
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      const std::size_t space = line.rfind(' ');
      golden[line.substr(0, space)] = line.substr(space + 1);
    }
  }
  CHECK(actual.size() == golden.size());
  for (const std::string& line : actual) {
    const std::size_t space = line.rfind(' ');
    const std::string what = line.substr(0, space);
    INFO(what);
    const auto g = golden.find(what);
    if (g == golden.end()) {
      FAIL_CHECK(what << " is not in " << golden_file.string() << " (a new block or file? scripts/update-golden)");
    } else {
      CHECK(line.substr(space + 1) == g->second);
    }
  }
}

}  // namespace test_golden_reports
