// Run-loop behaviour: progress callback, interruption, output files (VTU frames, PVD series, energy CSV),
// and the assembled step variants (Wendland C2, XSPH, free-slip walls) running stably.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "sph/soil/benchmarks.hpp"
#include "sph/soil/run.hpp"

namespace test_run_options {

namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}
}  // namespace

TEST_CASE("progress is reported, interruption stops the run, and frames/energy are written", "[sph][run]") {
  const fs::path dir = fs::temp_directory_path() / "sphslope_test_run_options";
  fs::remove_all(dir);
  sph::soil::ColumnCollapseCase c;
  c.dx = 0.01;
  c.end_time = 0.05;
  auto m = sph::soil::make_column_collapse(c);
  m.settings.output_interval = 0.01;
  sph::RunOptions o;
  o.output_dir = dir.string();
  o.progress_interval_wall_s = 0;  // every step
  int calls = 0;
  double last_time = -1;
  sph::RunCallbacks cb;
  cb.progress = [&](const sph::Progress& p) {
    ++calls;
    CHECK(p.time > last_time);
    CHECK(p.end_time == 0.05);
    last_time = p.time;
  };
  const auto s = sph::soil::run(m, o, cb);
  CHECK(s.stopped_because == "end_time");
  CHECK(m.state.time == Approx(0.05).epsilon(1e-12));
  CHECK(calls > 10);
  CHECK(s.frames_written == 6);  // t = 0, 0.01, ..., 0.05
  const std::string pvd = slurp(dir / "frames.pvd");
  CHECK(pvd.find("frames/frame_000005.vtu") != std::string::npos);
  const std::string vtu = slurp(dir / "frames" / "frame_000005.vtu");
  CHECK(vtu.rfind("<?xml", 0) == 0);
  CHECK(vtu.find("Name=\"plastic_strain\"") != std::string::npos);
  CHECK(vtu.find("Name=\"displacement\"") != std::string::npos);
  CHECK(vtu.find("</VTKFile>") != std::string::npos);
  CHECK(vtu.size() > m.particles.size() * 8 * 20);  // binary appended data is present
  const std::string csv = slurp(dir / "energy.csv");
  CHECK(csv.rfind("time_s,kinetic_J_m,potential_J_m,plastic_dissipation_J_m,max_speed_m_s\n", 0) == 0);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 7);
  CHECK(fs::exists(dir / "checkpoint.bin"));

  auto m2 = sph::soil::make_column_collapse(c);
  int polls = 0;
  sph::RunCallbacks stop;
  stop.interrupt = [&] { return ++polls > 5; };
  const auto s2 = sph::soil::run(m2, {}, stop);
  CHECK(s2.stopped_because == "interrupted");
  CHECK(s2.steps == 5);
  fs::remove_all(dir);
}

TEST_CASE("step variants (Wendland C2, XSPH, free-slip walls) run the collapse stably", "[sph][run]") {
  sph::soil::ColumnCollapseCase c;
  c.dx = 0.01;
  c.end_time = 0.4;
  c.kernel = sph::KernelType::wendland_c2;
  c.h_over_dx = 1.5;
  c.wall_slip = sph::soil::WallSlip::free_slip;
  auto m = sph::soil::make_column_collapse(c);
  m.settings.output_interval = 0;
  m.settings.xsph.enabled = true;
  const auto s = sph::soil::run(m, {});
  INFO(s.diagnostic);
  REQUIRE(s.stopped_because == "end_time");
  const auto d = sph::soil::measure_deposit(m);
  // the column has collapsed and spread (sanity band, not a validation: 0.4 s is mid-flow)
  CHECK(d.runout > 0.3);
  CHECK(d.height > 0.05);  // a frictionless back wall lets the top-left corner slide down too
}

TEST_CASE("a run stops as quasi-static when every particle is slower than the threshold", "[sph][run]") {
  sph::soil::ColumnCollapseCase c;
  c.dx = 0.01;
  c.end_time = 5.0;
  auto m = sph::soil::make_column_collapse(c);
  m.settings.output_interval = 0;
  sph::RunOptions o;
  o.quasi_static_speed = 1e-3;    // m/s
  o.quasi_static_min_time = 0.3;  // s: after the collapse has started and stopped
  const auto s = sph::soil::run(m, o);
  CHECK(s.stopped_because == "quasi_static");
  CHECK(s.simulated_time < 5.0);
  CHECK(s.simulated_time >= 0.3);
}

}  // namespace test_run_options
