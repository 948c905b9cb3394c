// sphslope batch through the program: parallel jobs, summary files, JUnit XML valid against its schema,
// resumption (finished scenes skipped, interrupted ones resumed), array-job index mode and Ctrl-C.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "test_support.hpp"

extern char** environ;

namespace test_batch {

namespace fs = std::filesystem;

namespace {

const fs::path source = test_paths::source_dir();

struct Outcome {
  int status = -1;
  std::string output;
};

Outcome run_batch(const std::string& arguments, const fs::path& log) {
  const std::string command =
      std::string("\"") + test_paths::binary() + "\" batch " + arguments + " > \"" + log.string() + "\" 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1,
          std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>())};
}

// "path" (built by appending: g++ 12 warns falsely (-Wrestrict) on "literal" + temporary string).
std::string quoted(const fs::path& path) {
  std::string text(1, '"');
  text += path.string();
  text += '"';
  return text;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Three scenes: two limit-equilibrium cases and one invalid scene.
fs::path make_scene_folder(const fs::path& root) {
  const fs::path scenes = root / "scenes";
  fs::create_directories(scenes);
  fs::copy_file(source / "cases/griffiths_lane_1999.json", scenes / "griffiths_lane_1999.json");
  fs::copy_file(source / "cases/arai_tagyo_1985_water_table.json", scenes / "arai_tagyo.json");
  fs::copy_file(source / "tests/coupling/bad_scenes/negative_cohesion.json", scenes / "negative_cohesion.json");
  return scenes;
}

}  // namespace

TEST_CASE("batch: a folder of scenes with 2 jobs gives a summary, a valid JUnit file and the worst exit status",
          "[batch][cli]") {
  TemporaryFolder folder("batch");
  const fs::path scenes = make_scene_folder(folder.path);
  const fs::path out = folder.path / "out";
  const Outcome first = run_batch(quoted(scenes) + " -o " + quoted(out) + " -j 2", folder.path / "1.log");
  INFO(first.output);
  CHECK(first.status == 1);  // one scene is invalid input
  const nlohmann::json summary = read_json(out / "summary.json");
  REQUIRE(summary["scenes"].size() == 3);
  // sorted by file name: arai_tagyo, griffiths_lane_1999, negative_cohesion
  CHECK(summary["scenes"][0]["status"] == "ok");
  CHECK(summary["scenes"][1]["status"] == "ok");
  CHECK(summary["scenes"][1]["factor_of_safety"]["bishop"].get<double>() == Approx(1.378).margin(0.002));
  CHECK(summary["scenes"][2]["status"] == "invalid_input");
  CHECK(summary["scenes"][2]["reason"].get<std::string>().find("cohesion_kPa: must be >= 0") != std::string::npos);
  const std::string csv = text_of(out / "summary.csv");
  CHECK(csv.rfind("scene,status,exit_status,seconds,fs_bishop", 0) == 0);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 4);
  // JUnit XML valid against tests/coupling/junit.xsd (xmllint from libxml2-utils)
  const std::string validate = "xmllint --noout --schema " + quoted(source / "tests/coupling/junit.xsd") + " " +
                               quoted(out / "junit.xml") + " > /dev/null 2>&1";
  CHECK(std::system(validate.c_str()) == 0);
  const std::string junit = text_of(out / "junit.xml");
  CHECK(junit.find("tests=\"3\" failures=\"0\" errors=\"1\"") != std::string::npos);

  // Again: the finished scenes are skipped, the same summary is written.
  const Outcome second = run_batch(quoted(scenes) + " -o " + quoted(out) + " -j 2", folder.path / "2.log");
  CHECK(second.status == 1);
  CHECK(second.output.find("griffiths_lane_1999.json: finished in an earlier batch, skipped") != std::string::npos);
  const nlohmann::json again = read_json(out / "summary.json");
  REQUIRE(again["scenes"].size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(again["scenes"][i]["status"] == summary["scenes"][i]["status"]);
    CHECK(again["scenes"][i]["factor_of_safety"] == summary["scenes"][i]["factor_of_safety"]);
  }
}

TEST_CASE("batch: an array job runs one scene by index, and the summary is gathered afterwards", "[batch][cli]") {
  TemporaryFolder folder("batch_index");
  const fs::path scenes = make_scene_folder(folder.path);
  const fs::path manifest = folder.path / "manifest.txt";
  std::ofstream(manifest) << "# two scenes\nscenes/griffiths_lane_1999.json\n\nscenes/arai_tagyo.json\n";
  const fs::path out = folder.path / "out";
  const Outcome one = run_batch(quoted(manifest) + " -o " + quoted(out) + " --index 1", folder.path / "1.log");
  CHECK(one.status == 0);
  CHECK(fs::exists(out / "arai_tagyo/report.json"));
  CHECK_FALSE(fs::exists(out / "griffiths_lane_1999"));
  CHECK(run_batch(quoted(manifest) + " -o " + quoted(out) + " --index 2", folder.path / "2.log").status == 2);
  run_batch(quoted(manifest) + " -o " + quoted(out) + " --index 0", folder.path / "3.log");
  const Outcome gathered = run_batch(quoted(manifest) + " -o " + quoted(out) + " --summary-only",
                                     folder.path / "4.log");
  CHECK(gathered.status == 0);
  const nlohmann::json summary = read_json(out / "summary.json");
  REQUIRE(summary["scenes"].size() == 2);
  CHECK(summary["scenes"][0]["status"] == "ok");
  CHECK(summary["scenes"][1]["status"] == "ok");
}

TEST_CASE("batch: Ctrl-C stops the runs with checkpoints, says how to continue, and the next batch resumes",
          "[batch][cli][resume]") {
  TemporaryFolder folder("batch_interrupt");
  const fs::path scenes = folder.path / "scenes";
  fs::create_directories(scenes);
  nlohmann::json scene = read_json(source / "cases/bui2008_column_collapse.json");
  scene["analyses"]["sph"]["particle_spacing_m"] = 0.005;
  scene["analyses"]["sph"]["end_time_s"] = 0.4;
  scene["analyses"]["sph"]["checkpoint_interval_s"] = 0.05;
  std::ofstream(scenes / "collapse.json") << scene.dump(2);
  const fs::path out = folder.path / "out";
  std::vector<std::string> args = {test_paths::binary(), "batch", scenes.string(), "-o", out.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string log = (folder.path / "interrupted.log").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  REQUIRE(posix_spawn(&pid, test_paths::binary(), &actions, nullptr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&actions);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(out / "collapse/checkpoint.bin") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGINT);  // to the batch only: it must pass the interruption on to its runs
  int status = 0;
  ::waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 1);
  CHECK(text_of(log).find("run the same command again to continue") != std::string::npos);
  CHECK(read_json(out / "collapse/report.json")["sph"]["stopped_because"] == "interrupted");

  const Outcome resumed = run_batch(quoted(scenes) + " -o " + quoted(out) + "", folder.path / "2.log");
  INFO(resumed.output);
  CHECK(resumed.status == 0);
  CHECK(resumed.output.find("collapse.json (resuming)") != std::string::npos);
  const nlohmann::json report = read_json(out / "collapse/report.json");
  CHECK(report["sph"]["stopped_because"] == "end_time");
  CHECK(report["sph"]["steps_this_session"].get<long>() < report["sph"]["steps"].get<long>());
}

}  // namespace test_batch
