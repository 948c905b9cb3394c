// The coupled run through the scene reader and the sphslope program (analyses.coupled, docs/coupled.md): what a
// coupled scene must hold and what it refuses (each fault with its JSON path), `sphslope check` and `run`, its
// report block, frames with both phases, and --resume giving the run without a stop bitwise.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/analyses/isph_waves.hpp"
#include "coupling/analyses/monitor_table.hpp"
#include "coupling/scene/scene.hpp"
#include "sphslope/units.hpp"
#include "test_support.hpp"

namespace test_coupled_run {

namespace fs = std::filesystem;

namespace {

nlohmann::json still_scene() {
  return read_json(fs::path(test_paths::source_dir()) / "cases" / "coupled_still_water_over_soil.json");
}

std::string quoted(const fs::path& p) {
  std::string q = "'";  // appended, not "'" + p.string(): GCC 12 warns falsely (-Wrestrict) on literal + temporary
  q += p.string();
  return q + "'";
}

fs::path write_scene(const fs::path& dir, const std::string& name, const nlohmann::json& scene) {
  const fs::path file = dir / name;
  std::ofstream(file) << scene.dump(2);
  return file;
}

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

}  // namespace

TEST_CASE("scene: a coupled scene runs its soil and water in one tank", "[scene][coupled]") {
  const nlohmann::json scene = still_scene();
  const coupling::Scene read = coupling::parse_scene(scene.dump());
  REQUIRE(read.analyses.coupled);
  REQUIRE(read.walls);  // the tank is the soil's wall box
  CHECK(read.walls->x_min == 0.0);
  CHECK(read.walls->x_max == 0.5);
  CHECK(read.walls->height == 1.0);
  CHECK(has(coupling::summarize(read), "coupled (sph and isph in one run)"));
}

TEST_CASE("scene: a coupled scene refuses what the coupled run cannot carry, naming the key", "[scene][coupled]") {
  const nlohmann::json base = still_scene();
  auto faults_with = [&](auto&& edit) {
    nlohmann::json scene = base;
    edit(scene);
    return scene_faults(scene);
  };
  CHECK(has(faults_with([](nlohmann::json& s) { s["analyses"]["isph"]["particle_spacing_m"] = 0.02; }),
            "analyses.isph.particle_spacing_m: 0.02 m must equal analyses.sph.particle_spacing_m = 0.025 m"));
  CHECK(has(faults_with([](nlohmann::json& s) { s["analyses"]["isph"]["end_time_s"] = 2.0; }),
            "analyses.isph.end_time_s: 2 s must equal analyses.sph.end_time_s = 1 s"));
  CHECK(has(faults_with([](nlohmann::json& s) { s["bodies"][0]["polygon_m"][1] = {0.6, 0.0}; }),
            "bodies[0].polygon_m[1]: point (0.6, 0) lies outside the tank analyses.isph.tank"));
  CHECK(has(faults_with([](nlohmann::json& s) {
              s["analyses"]["isph"]["water"][0] = {{"x_min_m", 0.1}, {"y_min_m", 0.05}, {"x_max_m", 0.4}, {"y_max_m", 0.2}};
            }),
            "analyses.isph.water[0]: lies entirely inside the soil bodies"));
  CHECK(has(faults_with([](nlohmann::json& s) {
              s["walls"] = {{"x_range_m", {0, 0.5}}, {"bottom_y_m", 0}, {"height_m", 1}};
            }),
            "walls: a coupled run's walls are its tank"));
  CHECK(has(faults_with([](nlohmann::json& s) { s["analyses"]["sph"]["gravity"] = "ramped"; }),
            "analyses.sph.gravity: \"ramped\" is not allowed in a coupled run"));
  CHECK(has(faults_with([](nlohmann::json& s) { s["analyses"]["isph"]["bed_slope_percent"] = 2; }),
            "analyses.isph.bed_slope_percent: must be 0 in a coupled run"));
  CHECK(has(faults_with([](nlohmann::json& s) { s["analyses"]["sph"]["output_interval_s"] = 0.1; }),
            "analyses.sph.output_interval_s: not used in a coupled run"));
  CHECK(has(faults_with([](nlohmann::json& s) { s["analyses"].erase("isph"); }),
            "analyses.coupled: needs analyses.isph"));
  CHECK(has(faults_with([](nlohmann::json& s) { s["analyses"]["coupled"]["exchange"] = 1; }),
            "analyses.coupled.exchange"));
  CHECK(scene_faults(base).empty());
}

// The still layer to 0.0625 s (32 water steps of 2^-9 s, the case's max_time_step_s) through the program, and the
// same stopped at 0.03125 s and continued with --resume (binary fractions: the step times add up exactly): the
// same report numbers to the last bit and the same monitors.csv; the water keeps its volume and stays out of the
// soil; the frames hold both phases.
TEST_CASE("sphslope run: a coupled run, its report and frames, and --resume giving the run without a stop",
          "[cli][coupled][e2e]") {
  TemporaryFolder folder("coupled_resume");
  nlohmann::json scene = still_scene();
  for (const char* block : {"sph", "isph"}) scene["analyses"][block]["end_time_s"] = 0.0625;
  scene["analyses"]["isph"]["output_interval_s"] = 0.03125;
  scene["analyses"]["isph"]["monitors"]["interval_s"] = 0.015625;
  const fs::path full = write_scene(folder.path, "full.json", scene);
  nlohmann::json first = scene;
  for (const char* block : {"sph", "isph"}) first["analyses"][block]["end_time_s"] = 0.03125;
  const fs::path half = write_scene(folder.path, "half.json", first);

  const ProgramRun check = run_sphslope("check " + quoted(full));
  INFO(check.output);
  CHECK(check.status == 0);
  CHECK(has(check.output, "coupled"));
  const ProgramRun straight = run_sphslope("run " + quoted(full) + " -o " + quoted(folder.path / "straight"));
  INFO(straight.output);
  REQUIRE(straight.status == 0);
  REQUIRE(run_sphslope("run " + quoted(half) + " -o " + quoted(folder.path / "split")).status == 0);
  const ProgramRun resumed = run_sphslope("run " + quoted(full) + " -o " + quoted(folder.path / "split") + " --resume");
  INFO(resumed.output);
  REQUIRE(resumed.status == 0);
  CHECK(has(resumed.output, "coupled: resuming at t = 0.03125 s"));

  const nlohmann::json report = read_json(folder.path / "straight" / "report.json");
  CHECK(report["analyses"] == nlohmann::json::array({"coupled"}));
  const nlohmann::json& a = report["coupled"];
  const nlohmann::json b = read_json(folder.path / "split" / "report.json")["coupled"];
  CHECK(a["status"] == "ok");
  CHECK(a["water_steps"] == 32);
  CHECK(b["water_steps"] == a["water_steps"]);
  CHECK(a["particles"]["soil"] == 200);
  CHECK(a["particles"]["water"] == 200);
  CHECK(a["since_start"]["soil_substeps_per_water_step"]["most"].get<int>() > 1);
  CHECK(a["since_start"]["solver_iterations_per_water_step"]["mean"].get<double>() > 0);
  CHECK(std::abs(a["water_volume_m2"]["ratio"].get<double>() - 1.0) < 0.01);
  CHECK(a["water_inside_soil_end"] == 0);
  CHECK(a["warnings"].empty());
  // bitwise: the checkpoint holds both phases, and the report prints every number to the last bit
  CHECK(b["soil_max_displacement_m"].get<double>() == a["soil_max_displacement_m"].get<double>());
  CHECK(b["water_max_speed_end_m_s"].get<double>() == a["water_max_speed_end_m_s"].get<double>());
  CHECK(read_text(folder.path / "split" / "monitors.csv") == read_text(folder.path / "straight" / "monitors.csv"));
  CHECK(read_text(folder.path / "split" / "energy.csv") == read_text(folder.path / "straight" / "energy.csv"));
  const coupling::MonitorTable rows =
      coupling::parse_monitors_csv(read_text(folder.path / "straight" / "monitors.csv"));
  CHECK(rows.times.size() == 5);  // t = 0, then every 15.625 ms
  CHECK(rows.columns == std::vector<std::string>{"middle_m"});
  CHECK(fs::exists(folder.path / "straight" / "figures" / "coupled_gauges.svg"));
  CHECK(fs::exists(folder.path / "straight" / "frames.pvd"));
  const std::string frame = read_text(folder.path / "straight" / "frames" / "frame_000002.vtu");
  CHECK(has(frame, "Name=\"phase\""));
  CHECK(has(frame, "Name=\"pressure\""));
}

TEST_CASE("sphslope run: a bad coupled scene exits 2 with the path and writes nothing", "[cli][coupled]") {
  TemporaryFolder folder("coupled_bad");
  nlohmann::json scene = still_scene();
  scene["analyses"]["isph"]["particle_spacing_m"] = 0.02;
  const fs::path file = write_scene(folder.path, "bad.json", scene);
  const ProgramRun run = run_sphslope("run " + quoted(file) + " -o " + quoted(folder.path / "out"));
  CHECK(run.status == 2);
  CHECK(has(run.output, "analyses.isph.particle_spacing_m"));
  CHECK_FALSE(fs::exists(folder.path / "out"));
}

namespace {

// A stiff soil block (0.3 m x 0.16 m, 2000 kg/m^3, E = 10 MPa, c = 50 kPa: it does not yield) on a 45 deg slope,
// the solid analyses.isph.solids[0] (the walls of both), its face from (0, 2.2) down to (2.2, 0); the block's
// corners 0.1 m below the face's top; water 0.3 m deep at the slope's foot, out of the block's way over the first
// metre of its drop. dx = 20 mm.
nlohmann::json block_on_slope(double delta_deg) {
  const double r = std::sqrt(0.5);
  auto on_face = [r](double s, double n) { return nlohmann::json::array({(s + n) * r, 2.2 + (n - s) * r}); };
  nlohmann::json scene = {
      {"format", "sphslope-scene/1"},
      {"name", "a stiff block slides down a 45 deg slope toward water"},
      {"bodies",
       {{{"name", "block"},
         {"polygon_m", {on_face(0.1, 0.0), on_face(0.4, 0.0), on_face(0.4, 0.16), on_face(0.1, 0.16)}},
         {"material",
          {{"name", "stiff"}, {"unit_weight_kN_m3", 19.62}, {"cohesion_kPa", 50}, {"friction_angle_deg", 30},
           {"youngs_modulus_MPa", 10}, {"poisson_ratio", 0.3}}}}}},
      {"analyses",
       {{"sph",
         {{"particle_spacing_m", 0.02}, {"end_time_s", 0.9}, {"walls", {{"slip", "frictional"}, {"friction_angle_deg", delta_deg}}}}},
        {"isph",
         {{"particle_spacing_m", 0.02},
          {"end_time_s", 0.9},
          {"tank", {{"x_min_m", 0}, {"x_max_m", 3.0}, {"y_min_m", 0}, {"height_m", 2.5}}},
          {"solids", {{{"name", "slope"}, {"polygon_m", {{0, 0}, {0, 2.2}, {2.2, 0}}}}}},
          {"water", {{{"x_min_m", 2.0}, {"y_min_m", 0}, {"x_max_m", 3.0}, {"y_max_m", 0.3}}}},
          {"monitors", {{"interval_s", 0.005}}}}},
        {"coupled", nlohmann::json::object()}}}};
  return scene;
}

// The centroid's speed [m/s] when it has dropped 1 m (linear between the rows of slide.csv around it); -1: never.
double speed_after_one_metre(const coupling::MonitorTable& slide) {
  const auto y = coupling::monitor_column(slide, "centroid_y_m");
  const auto v = coupling::monitor_column(slide, "centroid_speed_m_s");
  for (std::size_t k = 1; k < y.size(); ++k)
    if (y[0].second - y[k].second >= 1.0) {
      const double f = (y[0].second - 1.0 - y[k - 1].second) / (y[k].second - y[k - 1].second);
      return v[k - 1].second + f * (v[k].second - v[k - 1].second);
    }
  return -1.0;
}

}  // namespace

// The slide speed before impact in a coupled scene: the slope a solid shared by the soil and the water
// (sph::add_polygon_walls for the soil), the block's lattice-filled base on its smooth face. Reference: the energy
// line v = [2 g dz (1 - tan(delta) cot(alpha))]^(1/2) at dz = 1 m: 4.43 m/s with delta = 0 (5 %), 3.53 m/s with
// delta = 20 deg (10 %), from the centroid's speed in slide.csv.
TEST_CASE("sphslope run: a soil block slides down a solid 45 deg slope of a coupled scene at the energy line's "
          "speed",
          "[cli][coupled][walls]") {
  TemporaryFolder folder("coupled_slope");
  for (const double delta : {0.0, 20.0}) {
    const fs::path file = write_scene(folder.path, "slope.json", block_on_slope(delta));
    const fs::path out = folder.path / ("delta_" + std::to_string(static_cast<int>(delta)));
    const ProgramRun run = run_sphslope("run " + quoted(file) + " -o " + quoted(out));
    INFO(run.output);
    REQUIRE(run.status == 0);
    const double speed = speed_after_one_metre(coupling::parse_monitors_csv(read_text(out / "slide.csv")));
    const double expected = std::sqrt(2.0 * 9.81 * (1.0 - std::tan(delta * sphslope::degree)));
    std::printf("coupled slope: delta %.0f deg: %.4f m/s after a drop of 1 m (energy line %.4f, %+.2f %%)\n", delta,
                speed, expected, 100.0 * (speed / expected - 1.0));
    CHECK(std::fabs(speed / expected - 1.0) <= (delta == 0.0 ? 0.05 : 0.10));
    const nlohmann::json report = read_json(out / "report.json")["coupled"];
    CHECK(report["water_inside_soil_end"] == 0);
  }
}

namespace {

// Heinrich's landed submarine slide (cases/isph_heinrich_submarine.json) at dx, to 5 s: the rigid block (`soil`
// false: the case as it is), or a soil body of its shape and density (2000 kg/m^3, filled in rows parallel to its
// faces; the walls free-slip, as the rigid block ran without friction) stopped at the slope's foot by a stopper (a
// solid 0.1 m wide, 0.2 m high, its face at x = 1 m, where the rigid block's offshore face stops). E = 10 MPa,
// c = 30 kPa, phi = 30 deg: elastic while it slides (its stresses are about rho g 0.5 m = 10 kPa), plastic where it
// hits the stopper (about rho c_p v = 180 kPa), so that it stops there as the rigid block does; an elastic block
// (c = 200 kPa) springs back 7 cm up the slope at 0.45 m/s and draws the crests down by 15-20 %.
nlohmann::json heinrich(double dx, bool soil) {
  nlohmann::json scene = read_json(fs::path(test_paths::source_dir()) / "cases" / "isph_heinrich_submarine.json");
  nlohmann::json& isph = scene["analyses"]["isph"];
  isph["particle_spacing_m"] = dx;
  isph.erase("snapshots_s");
  isph["output_interval_s"] = 0.25;
  if (!soil) return scene;
  isph["solids"].push_back({{"name", "stopper"}, {"polygon_m", {{1.0, 0}, {1.1, 0}, {1.1, 0.2}, {1.0, 0.2}}}});
  const nlohmann::json block = isph["bodies"][0];
  isph.erase("bodies");
  // HEINRICH_SCALE (a study's experiment, default 1): the block's legs times this, its hypotenuse on the slope and
  // its top 1 cm below the water, as the rigid block's
  const double scale = std::getenv("HEINRICH_SCALE") ? std::atof(std::getenv("HEINRICH_SCALE")) : 1.0;
  const double leg = 0.5 * scale;
  // HEINRICH_COHESION_KPA (a study's experiment, default 30): 200 keeps the block elastic at the stopper
  const double cohesion = std::getenv("HEINRICH_COHESION_KPA") ? std::atof(std::getenv("HEINRICH_COHESION_KPA")) : 30.0;
  const nlohmann::json polygon = scale == 1.0 ? block["polygon_m"]
                                              : nlohmann::json{{0.01, 0.99}, {0.01 + leg, 0.99}, {0.01 + leg, 0.99 - leg}};
  scene["bodies"] = {{{"name", "block"},
                      {"polygon_m", polygon},
                      {"fill", std::getenv("HEINRICH_LATTICE") ? "lattice" : "rows"},
                      {"material",
                       {{"name", "stiff block"}, {"unit_weight_kN_m3", 2000 * 9.81 / 1000}, {"cohesion_kPa", cohesion},
                        {"friction_angle_deg", 30}, {"youngs_modulus_MPa", 10}, {"poisson_ratio", 0.3}}}}};
  scene["analyses"]["sph"] = {{"particle_spacing_m", dx}, {"end_time_s", isph["end_time_s"]},
                              {"walls", {{"slip", "free_slip"}}}};
  scene["analyses"]["coupled"] = nlohmann::json::object();
  return scene;
}

// Each gauge's leading crest (coupling::gauge_waves, as the isph report's waves block), for the scene's gauges.
coupling::GaugeWaves waves_of(const coupling::MonitorTable& table) {
  coupling::TankMonitors setup;
  for (const double x : {4.0, 8.0, 12.0}) setup.gauges.push_back({"x" + std::to_string(static_cast<int>(x)), x});
  setup.still_water = 1.0;
  coupling::Tank tank;
  tank.x_min = -1.5;
  tank.x_max = 14.0;
  tank.height = 2.0;
  return coupling::gauge_waves(table, setup, tank, 9.81);
}

// The RMS difference of two gauge series on the same times over the RMS of the first (the rigid block's) [-].
double normalised_rms_difference(const coupling::MonitorTable& a, const coupling::MonitorTable& b,
                                 const std::string& column) {
  const auto x = coupling::monitor_column(a, column), y = coupling::monitor_column(b, column);
  double diff = 0, ref = 0;
  const std::size_t n = std::min(x.size(), y.size());
  for (std::size_t k = 0; k < n; ++k) {
    diff += (x[k].second - y[k].second) * (x[k].second - y[k].second);
    ref += (x[k].second - x[0].second) * (x[k].second - x[0].second);
  }
  return ref > 0 ? std::sqrt(diff / ref) : 0.0;
}

}  // namespace

// Issue 43, item 3: a stiff soil body with the shape and density of Heinrich's block gives the same gauge records as
// the rigid block within 10 %: each gauge's largest crest, and the RMS difference of the records over 5 s against
// the rigid block's crest; also the time the block reaches the slope's foot (the rigid block's stop). A study
// (about a minute at 0.04 m): `build/tests/test_coupling "[coupled_heinrich_study]"`.
TEST_CASE("study: Heinrich's submarine block as stiff soil makes the rigid block's waves", "[.][coupled_heinrich_study]") {
  TemporaryFolder folder("coupled_heinrich");
  const double dx = std::getenv("HEINRICH_DX") ? std::atof(std::getenv("HEINRICH_DX")) : 0.04;
  coupling::MonitorTable records[2];
  double foot_time[2] = {0, 0};
  for (const bool soil : {false, true}) {
    const fs::path file = write_scene(folder.path, soil ? "soil.json" : "rigid.json", heinrich(dx, soil));
    const fs::path out = folder.path / (soil ? "soil" : "rigid");
    const ProgramRun run = run_sphslope("run " + quoted(file) + " -o " + quoted(out));
    INFO(run.output);
    REQUIRE(run.status == 0);
    records[soil] = coupling::parse_monitors_csv(read_text(out / "monitors.csv"));
    const nlohmann::json report = read_json(out / "report.json");
    if (!soil) {
      foot_time[0] = report["isph"]["bodies"][0]["stopped_at_s"].get<double>();
      continue;
    }
    // the soil block's centroid travel down the slope (direction -45 deg) from slide.csv, to the rigid block's 0.693 m
    const coupling::MonitorTable slide = coupling::parse_monitors_csv(read_text(out / "slide.csv"));
    const auto x = coupling::monitor_column(slide, "centroid_x_m"), y = coupling::monitor_column(slide, "centroid_y_m");
    double farthest = 0, last = 0;
    for (std::size_t k = 0; k < x.size(); ++k) {
      last = ((x[k].second - x[0].second) - (y[k].second - y[0].second)) / std::sqrt(2.0);
      farthest = std::max(farthest, last);
      if (foot_time[1] == 0 && last >= 0.692965 - 2 * dx) foot_time[1] = x[k].first;
    }
    // it stops at the foot as the rigid block does: no spring-back up the slope
    std::printf("heinrich soil block: travel %.4f m at most, %.4f m at the end (the rigid block 0.6930 m)\n", farthest,
                last);
    CHECK(farthest - last <= 0.5 * dx);
    std::printf("heinrich soil block: %d particles, %.1f kg/m (the rigid block 250 kg/m); %s\n",
                report["coupled"]["particles"]["soil"].get<int>(),
                report["coupled"]["soil_mass_kg_per_m"]["start"].get<double>(),
                report["coupled"]["since_start"].dump().c_str());
  }
  std::printf("heinrich at dx %.3f m: the block at the foot at %.3f s (rigid) and within 2 dx of it at %.3f s (soil)\n",
              dx, foot_time[0], foot_time[1]);
  const coupling::GaugeWaves rigid = waves_of(records[0]), soil = waves_of(records[1]);
  for (std::size_t k = 0; k < rigid.gauges.size(); ++k) {
    const coupling::GaugeWave &r = rigid.gauges[k], &w = soil.gauges[k];
    REQUIRE(r.crest);
    REQUIRE(w.crest);
    const double nrms = normalised_rms_difference(records[0], records[1], r.name + "_m");
    std::printf("heinrich %s: leading crest %.4f m at %.2f s (rigid), %.4f m at %.2f s (soil), %+.1f %%; the "
                "records' RMS difference over 5 s %.1f %% of the rigid record's RMS\n",
                r.name.c_str(), *r.crest, *r.crest_at, *w.crest, *w.crest_at, 100 * (*w.crest / *r.crest - 1),
                100 * nrms);
    CHECK(std::fabs(*w.crest / *r.crest - 1) <= 0.10);
    CHECK(nrms <= 0.10);
  }
}

}  // namespace test_coupled_run

namespace test_coupled_run {

// analyses.coupled.impact (docs/coupled.md, "Impact parameters"): cases/coupled_heller_hager_channel.json to 0.8 s
// (its centroid reaches the still water at about 0.64 s). Known answers: the slide's thickness normal to the ramp at
// t = 0 is the rectangle's 0.2 m (within dx/2); the impact is where slide.csv's centroid crosses the still water;
// F, S and M are the measured speed, thickness and mass over sqrt(g h), h and rho_w h^2; the prediction is Heller &
// Hager's from them.
TEST_CASE("sphslope run: a slide into a channel reports its impact parameters", "[cli][coupled][impulse]") {
  TemporaryFolder folder("coupled_impact");
  nlohmann::json scene = read_json(fs::path(test_paths::source_dir()) / "cases" / "coupled_heller_hager_channel.json");
  scene["analyses"]["sph"]["end_time_s"] = 0.8;
  scene["analyses"]["isph"]["end_time_s"] = 0.8;
  const fs::path file = write_scene(folder.path, "channel.json", scene), out = folder.path / "out";
  const ProgramRun run = run_sphslope("run " + quoted(file) + " -o " + quoted(out));
  INFO(run.output);
  REQUIRE(run.status == 0);
  const coupling::MonitorTable slide = coupling::parse_monitors_csv(read_text(out / "slide.csv"));
  const auto thickness = coupling::monitor_column(slide, "thickness_normal_to_ramp_m");
  const auto y = coupling::monitor_column(slide, "centroid_y_m"), v = coupling::monitor_column(slide, "centroid_speed_m_s");
  REQUIRE(thickness.size() == y.size());
  CHECK(std::fabs(thickness[0].second - 0.2) <= 0.01);
  const nlohmann::json impact = read_json(out / "report.json")["coupled"]["impact"];
  INFO(impact.dump(1));
  REQUIRE(impact["status"] == "ok");
  // the crossing of the still water (0.3 m) by slide.csv's centroid, between two rows
  const double t = impact["time_s"].get<double>();
  std::size_t k = 1;
  while (k < y.size() && y[k].second > 0.3) ++k;
  REQUIRE(k < y.size());
  CHECK(t >= y[k - 1].first);
  CHECK(t <= y[k].first);
  const nlohmann::json& s = impact["slide"];
  const double speed = s["centroid_speed_m_s"].get<double>(), h = 0.3, g = 9.81;
  CHECK(speed >= std::min(v[k - 1].second, v[k].second) - 1e-12);
  CHECK(speed <= std::max(v[k - 1].second, v[k].second) + 1e-12);
  const nlohmann::json& p = impact["parameters"];
  CHECK(p["F"].get<double>() == Approx(speed / std::sqrt(g * h)));
  CHECK(p["S"].get<double>() == Approx(s["thickness_m"].get<double>() / h));
  CHECK(p["M"].get<double>() == Approx(s["mass_kg_per_m"].get<double>() / (1000 * h * h)));
  const double P = p["F"].get<double>() * std::sqrt(p["S"].get<double>()) * std::pow(p["M"].get<double>(), 0.25) *
                   std::sqrt(std::cos(6.0 / 7.0 * 45 * sphslope::degree));
  CHECK(p["P"].get<double>() == Approx(P));
  CHECK(impact["heller_hager_2010"]["crest_amplitude_m"].get<double>() == Approx(4.0 / 9.0 * std::pow(P, 0.8) * h));
  // the slide's mass is its particles': 1620 kg/m3 over 0.06 m2, less what the rows leave out where they meet
  CHECK(s["mass_kg_per_m"].get<double>() <= 1620 * 0.06);
  CHECK(s["mass_kg_per_m"].get<double>() >= 0.9 * 1620 * 0.06);
  std::printf("channel impact at %.3f s: v_s %.3f m/s, s %.3f m, F %.3f, S %.3f, M %.3f, P %.3f, a_M %.4f m\n", t, speed,
              s["thickness_m"].get<double>(), p["F"].get<double>(), p["S"].get<double>(), p["M"].get<double>(),
              p["P"].get<double>(), impact["heller_hager_2010"]["crest_amplitude_m"].get<double>());
}

TEST_CASE("scene: an impact block needs a ramp angle above 0 and at most 90 deg, and two gauges",
          "[scene][coupled][impulse]") {
  nlohmann::json scene = read_json(fs::path(test_paths::source_dir()) / "cases" / "coupled_heller_hager_channel.json");
  CHECK_NOTHROW(coupling::parse_scene(scene.dump()));
  scene["analyses"]["coupled"]["impact"]["ramp_angle_deg"] = 0;
  CHECK_THROWS_WITH(coupling::parse_scene(scene.dump()), Catch::Contains("analyses.coupled.impact.ramp_angle_deg"));
  scene["analyses"]["coupled"]["impact"]["ramp_angle_deg"] = 45;
  scene["analyses"]["isph"]["monitors"]["gauges"] = {{{"name", "x1"}, {"x_m", 1.0}}};
  CHECK_THROWS_WITH(coupling::parse_scene(scene.dump()),
                    Catch::Contains("analyses.coupled.impact: needs at least two gauges"));
  scene["analyses"]["coupled"]["impact"].erase("shoreline_x_m");
  CHECK_THROWS_WITH(coupling::parse_scene(scene.dump()), Catch::Contains("analyses.coupled.impact.shoreline_x_m"));
}

}  // namespace test_coupled_run
