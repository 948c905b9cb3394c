// Resume-after-kill: N steps uninterrupted == k steps + checkpoint + resume to N, bitwise (the step is
// deterministic: gathered pair sums in a fixed order, stable counting sort, fixed-block reductions).
#include <catch2/catch.hpp>

#include <omp.h>

#include <filesystem>
#include <fstream>

#include "sph/soil/benchmarks.hpp"
#include "sph/soil/checkpoint.hpp"
#include "sph/soil/run.hpp"
#include "same_state.hpp"

namespace test_checkpoint {

namespace {
sph::soil::Model small_collapse() {
  sph::soil::ColumnCollapseCase c;
  c.dx = 0.01;
  c.end_time = 10.0;
  auto m = sph::soil::make_column_collapse(c);
  m.settings.output_interval = 0.01;
  m.settings.checkpoint_interval_wall_s = 0;  // only the checkpoint on stop
  return m;
}
}  // namespace

TEST_CASE("resume from a checkpoint gives the same final state as an uninterrupted run", "[sph][checkpoint]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "sphslope_test_checkpoint";
  fs::remove_all(dir);
  const std::uint64_t N = 600, k = 230;

  auto a = small_collapse();
  sph::RunOptions oa;
  oa.output_dir = (dir / "a").string();
  oa.max_steps = N;
  const auto sa = sph::soil::run(a, oa);
  REQUIRE(sa.stopped_because == "step_limit");

  auto b = small_collapse();
  sph::RunOptions ob;
  ob.output_dir = (dir / "b").string();
  ob.max_steps = k;
  REQUIRE(sph::soil::run(b, ob).stopped_because == "step_limit");
  REQUIRE(fs::exists(dir / "b" / "checkpoint.bin"));

  auto c = small_collapse();  // a fresh model from the "scene", as after a kill
  sph::soil::read_checkpoint((dir / "b" / "checkpoint.bin").string(), c);
  REQUIRE(c.state.step == k);
  ob.max_steps = N;
  const auto sc = sph::soil::run(c, ob);
  REQUIRE(sc.stopped_because == "step_limit");
  REQUIRE(c.state.step == N);
  CHECK(c.state.time == a.state.time);
  REQUIRE(c.particles.size() == a.particles.size());
  std::size_t mismatches = 0;
  auto& pa = a.particles;
  auto& pc = c.particles;
  std::vector<std::vector<double>*> fa, fc;
  pa.for_each_double_array([&](std::vector<double>& v) { fa.push_back(&v); });
  pc.for_each_double_array([&](std::vector<double>& v) { fc.push_back(&v); });
  for (std::size_t f = 0; f < fa.size(); ++f)
    for (std::size_t i = 0; i < pa.size(); ++i) mismatches += (*fa[f])[i] != (*fc[f])[i];
  for (std::size_t i = 0; i < pa.size(); ++i) mismatches += pa.id[i] != pc.id[i];
  CHECK(mismatches == 0);
  // the output series continues: same number of frames and identical energy history
  CHECK(c.state.frames_written == a.state.frames_written);
  auto slurp = [](const fs::path& p) { std::ifstream f(p); return std::string(std::istreambuf_iterator<char>(f), {}); };
  CHECK(slurp(dir / "a" / "energy.csv") == slurp(dir / "b" / "energy.csv"));
  CHECK(fs::exists(dir / "b" / "frames.pvd"));

  // a corrupt checkpoint is refused with a clear error
  {
    std::ofstream f(dir / "bad.bin", std::ios::binary);
    f << "SPHSLOPE-CKPT garbage";
  }
  auto d = small_collapse();
  CHECK_THROWS_AS(sph::soil::read_checkpoint((dir / "bad.bin").string(), d), std::runtime_error);
  fs::remove_all(dir);
}

TEST_CASE("a blow-up stops the run with a diagnostic naming particle, field and step", "[sph][checkpoint]") {
  auto m = small_collapse();
  m.settings.cfl = 0.5;
  m.settings.acceleration_safety = 0.5;
  m.settings.viscosity.alpha = 0;
  m.settings.viscosity.beta = 0;
  m.materials[0].youngs_modulus = 0.84e6;
  // sabotage: a particle with a huge velocity
  m.particles.vx[5] = 1e4;
  sph::RunOptions o;
  o.max_steps = 50;
  const auto s = sph::soil::run(m, o);
  CHECK(s.stopped_because == "blow_up");
  INFO(s.diagnostic);
  CHECK(s.diagnostic.find("particle") != std::string::npos);
  CHECK(s.diagnostic.find("step") != std::string::npos);
  CHECK(s.diagnostic.find("velocity") != std::string::npos);
}

TEST_CASE("the step gives the same state for 1 and 2 threads (no order-dependent reductions)", "[sph][checkpoint][threads]") {
  auto run_with = [](int threads) {
    omp_set_num_threads(threads);
    auto m = small_collapse();
    m.settings.output_interval = 0;
    sph::RunOptions o;
    o.max_steps = 300;
    const sph::RunSummary s = sph::soil::run(m, o);
    REQUIRE(s.stopped_because == "step_limit");
    return m;
  };
  const int before = omp_get_max_threads();
  auto a = run_with(1);
  auto b = run_with(2);
  omp_set_num_threads(before);
  REQUIRE(a.state.step == 300);
  REQUIRE(b.state.step == 300);
  CHECK(a.state.time == b.state.time);
  CHECK(same_state::differing_values(a.particles, b.particles) == 0);  // every field, bit for bit
}

}  // namespace test_checkpoint
