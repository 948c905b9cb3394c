// Error against run time (sphslope study): the order estimates on manufactured data, the elastic-column study
// against the closed form (convergence with refinement), resume, and the refusals.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/scene.hpp"
#include "coupling/studies/convergence.hpp"
#include "coupling/studies/study.hpp"
#include "sph/fluid/reference_fronts.hpp"

namespace test_study {

namespace fs = std::filesystem;
using namespace coupling;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("sphslope_study_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

fs::path write_scene(const fs::path& dir, const std::string& name, const nlohmann::json& scene) {
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream(file) << scene.dump(2);
  return file;
}

nlohmann::json case_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

nlohmann::json case_file(const std::string& name) {
  std::ifstream in(std::string(test_paths::source_dir()) + "/cases/" + name);
  return nlohmann::json::parse(in);
}

// The study of cases/<name> at the spacings into dir (options and log kept by the caller for further runs); it must
// finish.
StudyResult finished_study(const std::string& name, const std::vector<double>& spacings, const fs::path& dir,
                           StudyOptions& options, std::ostringstream& log) {
  options.spacings = spacings;
  options.output_dir = dir;
  options.log = &log;
  const StudyResult r = run_study(fs::path(test_paths::source_dir()) / "cases" / name, options);
  INFO(log.str());
  REQUIRE(r.status == ExitStatus::ok);
  return r;
}

}  // namespace

TEST_CASE("study: observed order of manufactured errors e = 3 h^2", "[study]") {
  const std::vector<double> h{0.4, 0.2, 0.1, 0.05};
  std::vector<double> e;
  for (double x : h) e.push_back(3.0 * x * x);
  const auto p = observed_order(h, e);
  REQUIRE(p);
  CHECK(*p == Approx(2.0).epsilon(1e-9));
  CHECK_FALSE(observed_order({0.1}, {0.01}));                  // one run: no slope
  CHECK_FALSE(observed_order({0.1, 0.1}, {0.01, 0.02}));       // one distinct spacing
  CHECK_FALSE(observed_order({0.2, 0.1}, {0.0, 0.01}));        // a zero error is left out: one run remains
}

TEST_CASE("study: self-convergence order and Richardson value of f = 1 + 0.5 h^1.5", "[study]") {
  auto f = [](double h) { return 1.0 + 0.5 * std::pow(h, 1.5); };
  const auto sc = self_convergence(0.4, f(0.4), 0.2, f(0.2), 0.1, f(0.1));
  REQUIRE(sc);
  CHECK(sc->order == Approx(1.5).epsilon(1e-9));
  CHECK(sc->extrapolated == Approx(1.0).epsilon(1e-9));
  // unequal ratios: 0.3, 0.2, 0.05
  const auto uneven = self_convergence(0.3, f(0.3), 0.2, f(0.2), 0.05, f(0.05));
  REQUIRE(uneven);
  CHECK(uneven->order == Approx(1.5).epsilon(1e-6));
  // oscillating (not asymptotic): no order
  CHECK_FALSE(self_convergence(0.4, 1.1, 0.2, 0.95, 0.1, 1.02));
  CHECK_FALSE(self_convergence(0.1, f(0.1), 0.2, f(0.2), 0.4, f(0.4)));  // spacings must decrease
}

// Reference: closed form of a laterally confined elastic column, sigma_yy = -rho g d, sigma_xx = nu/(1-nu) sigma_yy
// (cases/elastic_column.json). Tolerances: below 8 % at dx = H/10 and 4 % at H/20 (measured 5.5 % and 2.2 %,
// docs/accuracy.md), and the error must fall with refinement (observed order > 0.5).
TEST_CASE("study: elastic column converges to the closed-form stress", "[study][validation]") {
  const fs::path dir = fresh_dir("column");
  StudyOptions options;
  options.spacings = {0.05, 0.1};  // any order: run coarse to fine
  options.output_dir = dir;
  std::ostringstream log;
  options.log = &log;
  const StudyResult r = run_study(fs::path(test_paths::source_dir()) / "cases/elastic_column.json", options);
  INFO(log.str());
  REQUIRE(r.status == ExitStatus::ok);
  const auto& study = r.study;
  CHECK(study["reference_case"] == "elastic_column");
  REQUIRE(study["runs"].size() == 2u);
  CHECK(study["runs"][0]["particle_spacing_m"].get<double>() == 0.1);
  CHECK(study["runs"][0]["soil_particles"].get<int>() == 50);
  CHECK(study["runs"][1]["soil_particles"].get<int>() == 200);
  const double coarse = study["runs"][0]["errors_vs_reference"][0].get<double>();
  const double fine = study["runs"][1]["errors_vs_reference"][0].get<double>();
  CHECK(coarse < 0.08);
  CHECK(fine < 0.04);
  CHECK(fine < coarse);
  REQUIRE(study["quantities"][0]["observed_order"].is_number());
  CHECK(study["quantities"][0]["observed_order"].get<double>() > 0.5);
  CHECK(study["quantities"][0]["reference_source"].get<std::string>().find("closed form") != std::string::npos);
  // files: study.json equal to the result, a figure with one line per quantity, a run folder per spacing
  std::ifstream in(dir / "study.json");
  CHECK(nlohmann::json::parse(in) == study);
  std::ifstream svg_in(dir / "figures" / "error_vs_runtime.svg");
  std::stringstream svg;
  svg << svg_in.rdbuf();
  std::size_t lines = 0;
  for (std::size_t at = svg.str().find("<polyline"); at != std::string::npos; at = svg.str().find("<polyline", at + 1))
    ++lines;
  CHECK(lines == 2u);
  CHECK(fs::exists(dir / "runs" / "dx_0.1_m" / "report.json"));
  CHECK(fs::exists(dir / "runs" / "dx_0.05_m" / "quantities.json"));

  SECTION("--resume reuses the finished spacings") {
    std::ostringstream again;
    options.log = &again;
    options.resume = true;
    const StudyResult resumed = run_study(fs::path(test_paths::source_dir()) / "cases/elastic_column.json", options);
    REQUIRE(resumed.status == ExitStatus::ok);
    CHECK(again.str().find("dx = 0.1 m already done") != std::string::npos);
    CHECK(again.str().find("sph:") == std::string::npos);  // nothing was run again
    CHECK(resumed.study["runs"][1]["errors_vs_reference"][0].get<double>() == fine);
  }
  fs::remove_all(dir);
}

TEST_CASE("study: the WC-MPS dry collapse is measured against the 2-D scaling laws", "[study][mps]") {
  // Lube et al. / Lajeunesse et al. (2005), 2-D scaling laws as quoted second-hand: L = l0 (1 + 1.5 a) =
  // 0.1 (1 + 1.5 x 0.6) = 0.19 m; the height at the wall stays h0 = 0.06 m for a < 0.7.
  const fs::path dir = fresh_dir("mps");
  StudyOptions options;
  std::ostringstream log;
  const StudyResult r = finished_study("mps_dry_collapse_lajeunesse.json", {0.01, 0.02}, dir, options, log);
  const fs::path scene = fs::path(test_paths::source_dir()) / "cases/mps_dry_collapse_lajeunesse.json";
  const auto& study = r.study;
  CHECK(study["reference_case"] == "mps_dry_collapse");
  CHECK(study["quantities"][0]["key"] == "runout_m");
  CHECK(study["quantities"][0]["reference"].get<double>() == Approx(0.19).epsilon(1e-12));
  CHECK(study["quantities"][1]["key"] == "wall_height_m");
  CHECK(study["quantities"][1]["reference"].get<double>() == Approx(0.06).epsilon(1e-12));
  REQUIRE(study["runs"].size() == 2u);
  CHECK(study["runs"][0]["particles"].get<int>() == 15);  // 5 x 3 at 20 mm
  CHECK(study["runs"][1]["particles"].get<int>() == 60);  // 10 x 6 at 10 mm
  // each error is the run's own report against the law
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& run = study["runs"][k];
    const nlohmann::json report = case_json(dir / run["folder"].get<std::string>() / "report.json");
    const double front = report["mps"]["deposit"]["front_x_m"]["end"].get<double>();
    const double height = report["mps"]["deposit"]["wall_height_m"]["end"].get<double>();
    CHECK(run["values"][0].get<double>() == front);
    CHECK(run["errors_vs_reference"][0].get<double>() == Approx(std::fabs(front - 0.19) / 0.19).epsilon(1e-12));
    CHECK(run["errors_vs_reference"][1].get<double>() == Approx(std::fabs(height - 0.06) / 0.06).epsilon(1e-12));
  }
  CHECK(fs::exists(dir / "figures" / "error_vs_runtime.svg"));

  {
    INFO("a column the reference does not cover is refused");
    nlohmann::json tall = case_json(scene);
    tall["analyses"]["mps"]["blocks"][0]["y_max_m"] = 0.1;  // a = 1
    options.output_dir = dir / "tall";
    const StudyResult refused = run_study(write_scene(dir, "tall.json", tall), options);
    REQUIRE(refused.status == ExitStatus::invalid_input);
    CHECK(refused.errors.front().find("covers a < 0.7") != std::string::npos);
    nlohmann::json away = case_json(scene);
    away["analyses"]["mps"]["blocks"][0]["x_min_m"] = 0.05;
    away["analyses"]["mps"]["blocks"][0]["x_max_m"] = 0.15;
    const StudyResult moved = run_study(write_scene(dir, "away.json", away), options);
    REQUIRE(moved.status == ExitStatus::invalid_input);
    CHECK(moved.errors.front().find("against the tank's left wall") != std::string::npos);
  }
  fs::remove_all(dir);
}

// The ISPH dam break (cases/isph_dam_break_martin_moyce.json) at a/10: each error is the run's own front, read
// here from its monitors.csv, against Martin & Moyce's (1952) tabulated front (sph/src/fluid/reference_fronts.cpp),
// recomputed independently: Z = x_front / a against T = sqrt(2) t sqrt(g/a), linear between the rows, RMS of
// Z_run / Z - 1 over the points with 0.84 <= T <= 3.33; without a shift, and the smallest over dT = 0, -0.01, ...,
// -0.3.
TEST_CASE("study: the ISPH dam break is measured against Martin & Moyce's table", "[study][isph]") {
  const fs::path dir = fresh_dir("isph");
  StudyOptions options;
  std::ostringstream log;
  const StudyResult r = finished_study("isph_dam_break_martin_moyce.json", {0.005715}, dir, options, log);
  const fs::path scene = fs::path(test_paths::source_dir()) / "cases/isph_dam_break_martin_moyce.json";
  const auto& study = r.study;
  CHECK(study["reference_case"] == "isph_dam_break_martin_moyce");
  CHECK(study["quantities"][0]["key"] == "front_rms_error");
  CHECK(study["quantities"][1]["key"] == "front_rms_error_shifted");
  REQUIRE(study["runs"].size() == 1u);
  const auto& run = study["runs"][0];
  CHECK(run["particles"].get<int>() == 200);  // 10 x 20 at a/10

  std::vector<double> T, Z;
  std::ifstream csv(dir / run["folder"].get<std::string>() / "monitors.csv");
  std::string line;
  std::getline(csv, line);
  REQUIRE(line == "time_s,depth_at_0p1_m,front_x_m");
  const double a = 0.05715, scale = std::sqrt(2.0) * std::sqrt(9.81 / a);
  while (std::getline(csv, line)) {
    double t = 0, gauge = 0, x = 0;
    char c1 = 0, c2 = 0;
    std::istringstream(line) >> t >> c1 >> gauge >> c2 >> x;
    T.push_back(t * scale);
    Z.push_back(x / a);
  }
  REQUIRE(T.back() > 3.33);
  auto rms = [&](double shift) {
    double sum = 0;
    int n = 0;
    for (const sph::fluid::FrontPoint& p : sph::fluid::martin_moyce_1952_n2_2()) {
      if (p.T < 0.84 || p.T > 3.33) continue;
      const double at = p.T + shift;
      std::size_t k = 1;
      while (k + 1 < T.size() && T[k] < at) ++k;
      const double z = Z[k - 1] + (at - T[k - 1]) / (T[k] - T[k - 1]) * (Z[k] - Z[k - 1]);
      sum += (z / p.Z - 1.0) * (z / p.Z - 1.0);
      ++n;
    }
    CHECK(n == 14);
    return std::sqrt(sum / n);
  };
  double shifted = rms(0.0);
  for (int k = 1; k <= 30; ++k) shifted = std::min(shifted, rms(-0.01 * k));
  CHECK(run["values"][0].get<double>() == Approx(rms(0.0)).epsilon(1e-9));
  CHECK(run["values"][1].get<double>() == Approx(shifted).epsilon(1e-9));
  CHECK(run["errors_vs_reference"][0].get<double>() == run["values"][0].get<double>());
  CHECK(run["values"][0].get<double>() < 0.2);  // a gross-failure bound only (docs/isph.md section 5: 15 % at a/20)

  {
    INFO("a scene without the table as its reference, or too short for it, is refused");
    nlohmann::json plain = case_json(scene);
    plain["analyses"]["isph"].erase("front_reference");
    options.output_dir = dir / "plain";
    const StudyResult refused = run_study(write_scene(dir, "plain.json", plain), options);
    REQUIRE(refused.status == ExitStatus::invalid_input);
    CHECK(refused.errors.front().find("study: analyses.isph.front_reference") != std::string::npos);
    nlohmann::json short_run = case_json(scene);
    short_run["analyses"]["isph"]["end_time_s"] = 0.15;
    short_run["analyses"]["isph"]["snapshots_s"] = {0.05};
    const StudyResult cut = run_study(write_scene(dir, "short.json", short_run), options);
    REQUIRE(cut.status == ExitStatus::invalid_input);
    CHECK(cut.errors.front().find("analyses.isph.end_time_s: the front is compared up to T = 3.33") !=
          std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("study: refusals name what is wrong", "[study]") {
  const fs::path dir = fresh_dir("refusals");
  StudyOptions options;
  options.output_dir = dir / "out";
  const fs::path column = fs::path(test_paths::source_dir()) / "cases/elastic_column.json";

  options.spacings = {};
  auto r = run_study(column, options);
  CHECK(r.status == ExitStatus::invalid_input);
  options.spacings = {0.1, -0.05};
  r = run_study(column, options);
  REQUIRE(r.status == ExitStatus::invalid_input);
  CHECK(r.errors.front().find("--spacings: -0.05") != std::string::npos);

  options.spacings = {0.1};
  nlohmann::json no_slip = case_file("elastic_column.json");
  no_slip["analyses"]["sph"]["walls"]["slip"] = "no_slip";
  r = run_study(write_scene(dir, "no_slip.json", no_slip), options);
  REQUIRE(r.status == ExitStatus::invalid_input);
  CHECK(r.errors.front().find("analyses.sph.walls.slip") != std::string::npos);

  nlohmann::json lem_only = case_file("griffiths_lane_1999.json");
  lem_only["analyses"].erase("sph");
  lem_only["analyses"].erase("srm");
  r = run_study(write_scene(dir, "lem_only.json", lem_only), options);
  REQUIRE(r.status == ExitStatus::invalid_input);
  CHECK(r.errors.front().find("no analyses.sph") != std::string::npos);
  CHECK_FALSE(fs::exists(options.output_dir));  // nothing written for invalid input
  fs::remove_all(dir);
}

namespace {

// The scene file with its particle_spacing_m replaced in the JSON text and read again: what the study did before it
// changed the spacing on the typed scene, kept here as the reference the typed route must match.
coupling::Scene read_with_spacing(const std::string& file, double spacing) {
  std::ifstream in(fs::path(test_paths::source_dir()) / "cases" / file);
  nlohmann::json document = nlohmann::json::parse(in);
  for (const char* block : {"mps", "isph", "sph"})
    if (document["analyses"].contains(block)) {
      document["analyses"][block]["particle_spacing_m"] = spacing;
      break;
    }
  return coupling::scene_from_json(document, file);
}

std::vector<std::string> refusal(const std::function<coupling::Scene()>& read) {
  try {
    read();
  } catch (const coupling::SceneError& error) {
    return error.messages();
  }
  return {};
}

}  // namespace

TEST_CASE("study: the scene at another spacing is the scene file read with that spacing", "[study][scene]") {
  const std::vector<std::pair<std::string, std::vector<double>>> cases = {
      {"thesis_slope2.json", {0.5, 0.1}},
      {"bui2008_column_collapse.json", {0.004, 0.001}},
      {"isph_dam_break_martin_moyce.json", {0.02, 0.005}},
      {"mps_dry_collapse_gate.json", {0.01, 0.0025}},
  };
  for (const auto& [file, spacings] : cases) {
    const coupling::Scene scene = coupling::load_scene(fs::path(test_paths::source_dir()) / "cases" / file);
    for (const double dx : spacings) {
      INFO(file << " at " << dx << " m");
      const coupling::Scene typed = coupling::scene_with_spacing(scene, dx);
      const coupling::Scene read = read_with_spacing(file, dx);
      CHECK(coupling::summarize(typed) == coupling::summarize(read));
      if (read.analyses.sph) {
        CHECK(typed.analyses.sph->settings.particle_spacing == dx);
        CHECK(typed.analyses.sph->wall_layers == read.analyses.sph->wall_layers);
      }
      if (read.analyses.isph) {
        const auto& t = typed.analyses.isph->settings;
        const auto& r = read.analyses.isph->settings;
        CHECK(t.particle_spacing == dx);
        CHECK(t.domain_x_min == r.domain_x_min);
        CHECK(t.domain_x_max == r.domain_x_max);
        CHECK(t.domain_y_min == r.domain_y_min);
      }
      if (read.analyses.mps) {
        CHECK(typed.analyses.mps->settings.particle_spacing == dx);
        CHECK(typed.analyses.mps->gate_x == read.analyses.mps->gate_x);
      }
    }
  }
  // The refusals a spacing brings are the reader's, word for word: too few particles across the slope, a gate that
  // overlaps the column once it is ceil(r_e/dx) spacings thick, too many time steps.
  const std::vector<std::pair<std::string, double>> refused = {
      {"thesis_slope2.json", 4.0}, {"mps_dry_collapse_gate.json", 0.06}, {"mps_dry_collapse_gate.json", 1e-6}};
  for (const auto& entry : refused) {
    const std::string& file = entry.first;  // named copies, not structured bindings: clang 14 cannot capture those
    const double dx = entry.second;
    INFO(file << " at " << dx << " m");
    const coupling::Scene scene = coupling::load_scene(fs::path(test_paths::source_dir()) / "cases" / file);
    const auto typed = refusal([&] { return coupling::scene_with_spacing(scene, dx); });
    REQUIRE_FALSE(typed.empty());
    CHECK(typed == refusal([&] { return read_with_spacing(file, dx); }));
  }
}

}  // namespace test_study
