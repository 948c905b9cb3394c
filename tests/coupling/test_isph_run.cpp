// The isph analysis through the sphslope program: --resume, the figures of the run folder, the frames' fields and
// the still tank against hydrostatics (docs/isph.md, docs/scene-format.md).
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/analyses/tank_run.hpp"
#include "coupling/analyses/monitor_table.hpp"
#include "sph/fluid/reference_fronts.hpp"
#include "test_support.hpp"

namespace test_isph_run {

namespace fs = std::filesystem;

namespace {

constexpr double kA = 0.05715;  // Martin & Moyce's column width [m]
constexpr double kG = 9.81;

std::string quoted(const fs::path& p) {
  std::string q = "'";  // appended, not "'" + p.string(): GCC 12 warns falsely (-Wrestrict) on literal + temporary
  q += p.string();
  return q + "'";
}

nlohmann::json case_scene(const std::string& name) {
  return read_json(fs::path(test_paths::source_dir()) / "cases" / name);
}

fs::path write_scene(const fs::path& dir, const std::string& name, const nlohmann::json& scene) {
  const fs::path file = dir / name;
  std::ofstream(file) << scene.dump(2);
  return file;
}

ProgramRun run_into(const fs::path& scene, const fs::path& out, const std::string& extra = "") {
  return run_sphslope("run " + quoted(scene) + " -o " + quoted(out) + extra);
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The dam break of cases/ at a/10 (200 fluid particles) to 0.1 s, with snapshots at 0.03 and 0.08 s. The time step
// is held at 2.5e-4 s by max_time_step_s (below the CFL limit while the water is slower than 2.3 m/s), so that a run
// stopped at 0.05 s takes the same steps as one that runs through: a free step would end the shorter run with a
// step cut to its end time, and the two would part by 4e-5 m at 0.1 s (measured).
nlohmann::json coarse_dam_break() {
  nlohmann::json scene = case_scene("isph_dam_break_martin_moyce.json");
  nlohmann::json& isph = scene["analyses"]["isph"];
  isph["particle_spacing_m"] = kA / 10.0;
  isph["end_time_s"] = 0.1;
  isph["max_time_step_s"] = 2.5e-4;
  isph["snapshots_s"] = {0.03, 0.08};
  return scene;
}

}  // namespace

// The mps stage's --resume (docs/scene-format.md) for isph: a run stopped at 0.05 s and continued with --resume to
// 0.1 s ends as the run without a stop, bitwise: the same rows of monitors.csv, the same front, step count and
// largest density error of the whole run, and the snapshots of both parts listed.
TEST_CASE("sphslope run --resume continues an isph run to the state of a run without a stop", "[cli][isph][e2e]") {
  TemporaryFolder folder("isph_resume");
  const nlohmann::json scene = coarse_dam_break();
  const fs::path full = write_scene(folder.path, "full.json", scene);
  nlohmann::json first = scene;
  first["analyses"]["isph"]["end_time_s"] = 0.05;
  first["analyses"]["isph"]["snapshots_s"] = {0.03};
  const fs::path half = write_scene(folder.path, "half.json", first);

  const ProgramRun straight = run_into(full, folder.path / "straight");
  INFO(straight.output);
  REQUIRE(straight.status == 0);
  CHECK(straight.output.find("isph: warning") == std::string::npos);  // the bound applied: no warning
  REQUIRE(run_into(half, folder.path / "split").status == 0);
  const ProgramRun resumed = run_into(full, folder.path / "split", " --resume");
  INFO(resumed.output);
  REQUIRE(resumed.status == 0);
  CHECK(resumed.output.find("isph: resuming at t = 0.05 s") != std::string::npos);

  const nlohmann::json a = read_json(folder.path / "straight" / "report.json")["isph"];
  const nlohmann::json b = read_json(folder.path / "split" / "report.json")["isph"];
  CHECK(b["simulated_time_s"].get<double>() == Approx(0.1));
  CHECK(b["steps"] == a["steps"]);
  CHECK(a["steps"] == 400);  // 0.1 s / 2.5e-4 s
  // bitwise: the checkpoint holds the whole state, and the report prints every number to the last bit
  CHECK(b["front_x_m"].get<double>() == a["front_x_m"].get<double>());
  CHECK(b["max_density_error"].get<double>() == a["max_density_error"].get<double>());
  CHECK(b["largest_time_step_s"].get<double>() == Approx(2.5e-4).epsilon(1e-9));
  const coupling::MonitorTable ra = coupling::parse_monitors_csv(read_text(folder.path / "straight" / "monitors.csv"));
  const coupling::MonitorTable rb = coupling::parse_monitors_csv(read_text(folder.path / "split" / "monitors.csv"));
  REQUIRE(ra.times.size() == 21);  // t = 0, then every 5 ms
  REQUIRE(rb.times.size() == ra.times.size());
  CHECK(rb.columns == ra.columns);
  std::size_t different = 0;  // cells of monitors.csv that differ (the rows are written as text: compared exactly)
  for (std::size_t k = 0; k < ra.times.size(); ++k) {
    different += rb.times[k] != ra.times[k];
    for (std::size_t c = 0; c < ra.columns.size(); ++c) different += rb.rows[k][c] != ra.rows[k][c];
  }
  CHECK(different == 0);
  const std::vector<std::string> snapshots{"figures/isph_snapshot_0.03s.svg", "figures/isph_snapshot_0.08s.svg"};
  for (const std::string& f : snapshots) {
    CHECK(fs::exists(folder.path / "split" / f));
    CHECK(std::find(b["figures"].begin(), b["figures"].end(), f) != b["figures"].end());
  }
}

// An interrupted run (Ctrl-C: the run loop stops at the end of a step and writes its checkpoint) fails with a
// message that says how to continue it; any other stop fails with its diagnostic.
TEST_CASE("an interrupted isph or mps run says to continue it with --resume", "[isph][mps]") {
  sph::RunSummary summary;
  summary.stopped_because = "interrupted";
  summary.simulated_time = 0.042;
  coupling::StageOutcome outcome;
  coupling::tank_run_outcome(summary, "isph", outcome);
  CHECK(outcome.status == coupling::ExitStatus::failed);
  REQUIRE(outcome.errors.size() == 1);
  CHECK(outcome.errors[0] == "isph: the run was interrupted at t = 0.042 s; continue it with --resume");
  summary.stopped_because = "blow_up";
  summary.diagnostic = "blow-up at step 7";
  coupling::StageOutcome blown;
  coupling::tank_run_outcome(summary, "mps", blown);
  REQUIRE(blown.errors.size() == 1);
  CHECK(blown.errors[0] == "mps: stopped (blow_up) blow-up at step 7");
  summary.stopped_because = "end_time";
  coupling::StageOutcome done;
  coupling::tank_run_outcome(summary, "isph", done);
  CHECK(done.status == coupling::ExitStatus::ok);
  CHECK(done.errors.empty());
}

// The figures of the run folder, listed in report.json's isph block: the gauges and the front against time (axes
// with units), the front with Martin & Moyce's points that fall within the run (T = n t sqrt(g/a) <= T(0.1 s)) and
// Ritter's line, a snapshot with one mark per particle and a pressure bar in kPa; and the VTU frames carry the
// pressure, the velocity and the kind of every particle.
TEST_CASE("an isph run draws its gauges, its front with the references and its snapshots", "[cli][isph]") {
  TemporaryFolder folder("isph_figures");
  nlohmann::json scene = coarse_dam_break();
  scene["analyses"]["isph"]["output_interval_s"] = 0.05;
  const fs::path out = folder.path / "out";
  const ProgramRun run = run_into(write_scene(folder.path, "scene.json", scene), out);
  INFO(run.output);
  REQUIRE(run.status == 0);
  const nlohmann::json isph = read_json(out / "report.json")["isph"];
  CHECK(isph["figures"] == nlohmann::json({"figures/isph_snapshot_0.03s.svg", "figures/isph_snapshot_0.08s.svg",
                                           "figures/isph_gauges.svg", "figures/isph_front.svg"}));
  const std::string gauges = read_text(out / "figures" / "isph_gauges.svg");
  CHECK(gauges.find("time t (s)") != std::string::npos);
  CHECK(gauges.find("surface elevation above y = 0 m (m)") != std::string::npos);
  CHECK(gauges.find("depth_at_0p1 at x = 0.1 m") != std::string::npos);

  const std::string front = read_text(out / "figures" / "isph_front.svg");
  CHECK(front.find("front x (m)") != std::string::npos);
  CHECK(front.find("Ritter (1892)") != std::string::npos);
  const double T_end = std::sqrt(2.0) * 0.1 * std::sqrt(kG / kA);
  std::size_t within = 0;
  for (const sph::fluid::FrontPoint& p : sph::fluid::martin_moyce_1952_n2_2()) within += p.T <= T_end ? 1 : 0;
  CHECK(within == 6);
  CHECK(count_of(front, "<circle") == within);

  const std::string snapshot = read_text(out / "figures" / "isph_snapshot_0.08s.svg");
  const std::size_t particles = isph["particles"]["fluid"].get<std::size_t>() + isph["particles"]["wall"].get<std::size_t>();
  CHECK(count_of(snapshot, "<circle") == particles);
  CHECK(snapshot.find("pressure (kPa)") != std::string::npos);
  CHECK(snapshot.find("particles at t = 0.08") != std::string::npos);

  const std::string frame = read_text(out / "frames" / "frame_000001.vtu");
  for (const char* field : {"Name=\"pressure\"", "Name=\"velocity\"", "Name=\"kind\""}) {
    INFO(field);
    CHECK(frame.find(field) != std::string::npos);
  }
}

// cases/isph_still_tank.json at dx = 0.04 m (100 fluid particles) to 2 s, both pressure modes. Reference:
// hydrostatics. The scheme imposes P = 0 at the top row's centres, dx/2 below the surface (docs/isph.md D6), so the
// floor pressure is rho0 g (H - dx/2) = 3727.8 Pa, within 0.5 % of rho0 g H (measured 0.08 % and 0.14 %); the
// fitted -dP/dy within 0.5 % of rho0 g (0.03 %, 0.02 %); the largest speed at the end below 1.5 % of sqrt(g H), the
// bound of the finer still tank in tests/sph/test_isph_validation.cpp (measured 0.90 %, 0.98 %); no particle past
// the walls, the mass kept.
TEST_CASE("the still tank keeps the hydrostatic floor pressure and stays at rest", "[cli][isph][validation]") {
  TemporaryFolder folder("isph_still_tank");
  const double depth = 0.4, dx = 0.04, rho_g = 1000.0 * kG;
  for (const char* mode : {"iterative", "explicit"}) {
    INFO("pressure " << mode);
    nlohmann::json scene = case_scene("isph_still_tank.json");
    scene["analyses"]["isph"]["particle_spacing_m"] = dx;
    scene["analyses"]["isph"]["pressure"] = mode;
    const fs::path out = folder.path / mode;
    const ProgramRun run = run_into(write_scene(folder.path, std::string(mode) + ".json", scene), out);
    INFO(run.output);
    REQUIRE(run.status == 0);
    const nlohmann::json isph = read_json(out / "report.json")["isph"];
    CHECK(isph["particles"]["fluid"] == 100);
    const nlohmann::json& tank = isph["still_tank"];
    CHECK(tank["rho_g_depth_Pa"].get<double>() == Approx(rho_g * depth));
    CHECK(std::abs(tank["floor_pressure_Pa"].get<double>() - rho_g * (depth - 0.5 * dx)) < 0.005 * rho_g * depth);
    CHECK(tank["floor_pressure_ratio"].get<double>() ==
          Approx(tank["floor_pressure_Pa"].get<double>() / (rho_g * depth)));
    CHECK(tank["pressure_gradient_ratio"].get<double>() == Approx(1.0).margin(0.005));
    CHECK(tank["sqrt_g_depth_m_s"].get<double>() == Approx(std::sqrt(kG * depth)));
    CHECK(tank["max_speed_end_m_s"].get<double>() < 0.015 * std::sqrt(kG * depth));
    CHECK(isph["fluid_past_walls"]["most"] == 0);
    CHECK(isph["fluid_mass_kg_per_m"]["end"].get<double>() ==
          Approx(isph["fluid_mass_kg_per_m"]["start"].get<double>()).epsilon(1e-12));
    CHECK(isph["warnings"].empty());
  }
  // a dam break is no still tank: no such block
  nlohmann::json dam = coarse_dam_break();
  dam["analyses"]["isph"]["end_time_s"] = 0.01;
  dam["analyses"]["isph"].erase("snapshots_s");
  REQUIRE(run_into(write_scene(folder.path, "dam.json", dam), folder.path / "dam").status == 0);
  CHECK_FALSE(read_json(folder.path / "dam" / "report.json")["isph"].contains("still_tank"));
}

}  // namespace test_isph_run
