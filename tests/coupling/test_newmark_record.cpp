// analyses.lem.critical_seismic_coefficient.acceleration_record: the record read with the scene, Newmark's
// displacement at k_c in the report, and every bad record refused with its JSON path.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/output/newmark_figures.hpp"
#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/scene.hpp"
#include "slope/newmark.hpp"
#include "test_support.hpp"

namespace test_newmark_record {

namespace fs = std::filesystem;
using coupling::AccelerationRecordInput;

// Griffiths & Lane's slope with k_c sought by Bishop and a record in `record_file` (relative to the scene).
nlohmann::json scene_with_record(const std::string& record_file) {
  nlohmann::json scene = read_json(fs::path(test_paths::source_dir()) / "cases/griffiths_lane_1999.json");
  scene["analyses"] = {{"lem",
                        {{"methods", {"bishop"}},
                         {"critical_seismic_coefficient",
                          {{"acceleration_record", {{"file", record_file}, {"scale", 2.0}}}}}}}};
  return scene;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

constexpr const char* record_path = "analyses.lem.critical_seismic_coefficient.acceleration_record.file";

TEST_CASE("Newmark: the displacement at k_c under a record read with the scene", "[scene][seismic]") {
  // A rectangular pulse of 0.2 g (scaled by 2: 0.4 g) for 1 s, every 1 ms, then 1 s at rest; a header line and a
  // comment. The report's displacement is Newmark's for that record at the reported k_c, and near the closed form
  // (A - k_c) A g T^2 / (2 k_c) (the pulse's fall over one step lengthens it by half a step).
  TemporaryFolder folder("newmark");
  std::string csv = "# a rectangular pulse\ntime_s,acceleration_g\n";
  for (int i = 0; i <= 2000; ++i) csv += std::to_string(i * 1e-3) + "," + (i <= 1000 ? "0.2" : "0") + "\n";
  fs::create_directories(folder.path / "records");
  write(folder.path / "records" / "pulse.csv", csv);
  const fs::path scene_file = folder.path / "scene.json";
  write(scene_file, scene_with_record("records/pulse.csv").dump());
  const coupling::Scene scene = coupling::load_scene(scene_file);
  REQUIRE(scene.analyses.lem->acceleration_record);
  CHECK(scene.analyses.lem->acceleration_record->record.acceleration.size() == 2001);
  CHECK(scene.analyses.lem->acceleration_record->record.time_step == Approx(1e-3).epsilon(1e-9));
  coupling::WorkflowOptions options;
  options.mode = coupling::Mode::lem;
  const coupling::WorkflowResult out = coupling::run_scene(scene, options);
  REQUIRE(out.status == coupling::ExitStatus::ok);
  const nlohmann::json& k = out.report["lem"]["critical_seismic_coefficient"];
  const double kc = k["k_c"].get<double>();
  REQUIRE(kc > 0.1);
  REQUIRE(kc < 0.4);
  const nlohmann::json& newmark = k["newmark"];
  CHECK(newmark["file"] == "records/pulse.csv");
  CHECK(newmark["samples"] == 2001);
  CHECK(newmark["peak_acceleration_g"].get<double>() == Approx(0.4).epsilon(1e-12));
  CHECK(newmark["yield_coefficient"].get<double>() == kc);
  const double expected =
      slope::newmark_displacement(scene.analyses.lem->acceleration_record->record, kc, 2.0).displacement;
  CHECK(newmark["displacement_m"].get<double>() == Approx(expected).epsilon(1e-12));
  CHECK(newmark["directions"][0]["displacement_m"].get<double>() == Approx(expected).epsilon(1e-12));
  CHECK(newmark["directions"][1]["displacement_m"].get<double>() == 0.0);  // reversed: upslope only
  const double A = 0.4, g = 9.81;
  CHECK(expected == Approx((A - kc) * A * g / (2.0 * kc)).epsilon(2e-3));
  CHECK(unexplained_nulls(out.report).empty());
  // the figures: the record with k_c, the displacement both ways with the totals
  const AccelerationRecordInput& record = *scene.analyses.lem->acceleration_record;
  const coupling::LemStageResult* lem = out.results.lem_result();
  REQUIRE(lem);
  REQUIRE(lem->newmark);
  CHECK(lem->newmark->as_given_history.size() == 2001);
  CHECK(lem->newmark->as_given_history.back() < expected);  // still sliding at the record's end
  CHECK(coupling::newmark_record_svg(record, kc, "t").find("k_c = " + coupling::format_number(kc)) !=
        std::string::npos);
  const std::string displacement = coupling::newmark_displacement_svg(record, *lem->newmark, "t");
  CHECK(displacement.find("as given: " + coupling::format_number(expected) + " m (with the stop after the record") !=
        std::string::npos);
  CHECK(displacement.find("reversed: 0 m") != std::string::npos);
}

TEST_CASE("Newmark: a bad acceleration record is refused with its path, before anything runs", "[scene][seismic]") {
  TemporaryFolder folder("newmark-bad");
  const fs::path scene_file = folder.path / "scene.json";
  write(scene_file, scene_with_record("record.csv").dump());
  const auto refused = [&](const std::string& csv, const std::string& why) {
    INFO(why);
    write(folder.path / "record.csv", csv);
    CHECK_THROWS_WITH(coupling::load_scene(scene_file), Catch::Contains(std::string(record_path) + ": ") &&
                                                            Catch::Contains(why));
  };
  refused("0,0\n0.01,0.1\n0.03,0.2\n", "uneven time step 0.02 s from 0.01 s");
  refused("0,0\n0.01,0.1\n0.01,0.2\n", "line 3: time 0.01 s is not after 0.01 s");
  refused("t,a\n0,0\n0.01,oops\n", "line 3: \"0.01,oops\" is not a time (s) and an acceleration (g)");
  refused("time,acc\n0,0.1\n", "has 1 samples (at least two");
  fs::remove(folder.path / "record.csv");
  CHECK_THROWS_WITH(coupling::load_scene(scene_file), Catch::Contains(std::string(record_path) + ": cannot read"));
  // a device (endless) is not read
  write(scene_file, scene_with_record("/dev/zero").dump());
  CHECK_THROWS_WITH(coupling::load_scene(scene_file), Catch::Contains(std::string(record_path) + ": cannot read"));
  // the schema: a scale that is not positive, no file
  nlohmann::json scene = scene_with_record("record.csv");
  scene["analyses"]["lem"]["critical_seismic_coefficient"]["acceleration_record"]["scale"] = 0;
  CHECK_THROWS_WITH(coupling::parse_scene(scene.dump()),
                    Catch::Contains("analyses.lem.critical_seismic_coefficient.acceleration_record.scale"));
  scene["analyses"]["lem"]["critical_seismic_coefficient"]["acceleration_record"] = nlohmann::json::object();
  CHECK_THROWS_WITH(coupling::parse_scene(scene.dump()), Catch::Contains("acceleration_record"));
}

}  // namespace test_newmark_record
