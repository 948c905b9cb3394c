// The explicit three-step ISPH fluid (sph/fluid, docs/isph.md): its pressure solvers, resume, a still water tank
// and the Martin & Moyce (1952) dam break.
#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sph/fluid/cases.hpp"
#include "sph/fluid/pressure.hpp"
#include "sph/fluid/run.hpp"
#include "sphslope/units.hpp"
#include "same_state.hpp"

namespace test_isph {

namespace {

using namespace sph::fluid;

// A chain of n nodes, node 0 given (P = 0), B = -1 between neighbours; source from a manufactured solution.
PoissonSystem chain_system(std::size_t n, std::vector<double>& exact) {
  PoissonSystem s;
  s.role.assign(n, PressureRole::unknown);
  s.role[0] = PressureRole::given;
  exact.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) exact[i] = 3.0 * static_cast<double>(i) - 0.05 * static_cast<double>(i * i);
  s.start.push_back(0);
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) s.col.push_back(static_cast<std::uint32_t>(i - 1));
    if (i + 1 < n) s.col.push_back(static_cast<std::uint32_t>(i + 1));
    s.start.push_back(static_cast<std::uint32_t>(s.col.size()));
  }
  s.coef.assign(s.col.size(), -1.0);
  s.source.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = s.start[i]; k < s.start[i + 1]; ++k) s.source[i] += -(exact[i] - exact[s.col[k]]);
  return s;
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace

TEST_CASE("ISPH pressure equation: CG, BiCGSTAB and repeated Jacobi sweeps reach the same solution", "[sph][isph]") {
  std::vector<double> exact;
  const PoissonSystem s = chain_system(12, exact);
  for (LinearSolver solver : {LinearSolver::conjugate_gradient, LinearSolver::bicgstab}) {
    std::vector<double> p(exact.size(), 0.0);
    SolverChoice choice;
    choice.solver = solver;
    choice.preconditioner = Preconditioner::diagonal;
    choice.tolerance = 1e-12;
    choice.max_iterations = 500;
    const SolveReport rep = solve_pressure(s, choice, p);
    CHECK(rep.converged);
    CHECK(rep.unknowns == 11);
    CHECK(max_abs_diff(p, exact) < 1e-8);
    CHECK(rep.relative_residual < 1e-10);
  }
  // one sweep (the explicit mode) leaves an error; many sweeps converge to the same solution
  std::vector<double> p(exact.size(), 0.0);
  const SolveReport one = jacobi_sweep(s, p);
  CHECK(one.relative_residual > 0.1);
  for (int k = 0; k < 3000; ++k) jacobi_sweep(s, p);
  CHECK(max_abs_diff(p, exact) < 1e-6);
}

TEST_CASE("ISPH settings: keys and ranges", "[sph][isph]") {
  CHECK(pressure_mode_from("explicit") == PressureMode::explicit_jacobi);
  CHECK(pressure_mode_from("iterative") == PressureMode::iterative);
  CHECK(linear_solver_from("bicgstab") == LinearSolver::bicgstab);
  CHECK_THROWS_AS(pressure_mode_from("implicit"), std::invalid_argument);
  Settings st;
  CHECK_NOTHROW(st.validate());
  st.wall_layers = 2;  // h = 1.5 dx needs 3 rows
  CHECK_THROWS_AS(st.validate(), std::invalid_argument);
  st = Settings{};
  st.surface_beta = 1.2;
  CHECK_THROWS_AS(st.validate(), std::invalid_argument);
  // the engine's settings and ranges (sph/engine/settings.hpp), with the fluid's defaults h = 1.5 dx and CFL 0.1
  st = Settings{};
  CHECK(st.h_over_dx == 1.5);
  CHECK(st.cfl == 0.1);
  CHECK(st.gravity_y == -sphslope::standard_gravity);
  st.h_over_dx = 2.5;  // above EngineSettings::h_over_dx_max
  CHECK_THROWS_AS(st.validate(), std::invalid_argument);
  st = Settings{};
  st.cfl = 0.8;  // above the fluid's 0.5
  CHECK_THROWS_AS(st.validate(), std::invalid_argument);
}

TEST_CASE("ISPH resume from a checkpoint gives bitwise the same state", "[sph][isph]") {
  Settings st;
  st.particle_spacing = 0.02;
  st.end_time = 10.0;
  const std::string dir = (std::filesystem::temp_directory_path() / "sphslope_isph_resume").string();
  std::filesystem::create_directories(dir);
  sph::RunOptions opt;
  opt.max_steps = 30;
  Model straight = make_dam_break(st, 0.1, 2.0, 0.3);
  run(straight, opt);
  Model first = make_dam_break(st, 0.1, 2.0, 0.3);
  opt.max_steps = 15;
  run(first, opt);
  write_checkpoint(dir + "/isph.bin", first);
  Model resumed = make_dam_break(st, 0.1, 2.0, 0.3);
  read_checkpoint(dir + "/isph.bin", resumed);
  opt.max_steps = 30;
  run(resumed, opt);
  REQUIRE(resumed.state.step == 30);
  REQUIRE(straight.state.step == 30);
  CHECK(resumed.state.time == straight.state.time);
  CHECK(same_state::differing_values(resumed.particles, straight.particles) == 0);  // every field, bit for bit
  std::filesystem::remove_all(dir);
}

// docs/reliability.md: the same scene gives bitwise the same result with 1 or 2 threads, for every pressure solver
// (the explicit sweep; CG and BiCGSTAB, each with the diagonal and the multigrid preconditioner). A dam break at
// dx = 2.5 mm (3200 fluid particles: above the 2048 rows from which the multigrid's loops run in parallel), 40
// steps.
TEST_CASE("ISPH gives bitwise the same state with 1 and 2 threads, with every pressure solver", "[sph][isph][threads]") {
  struct Solver {
    const char* name;
    PressureMode mode;
    LinearSolver solver;
    Preconditioner preconditioner;
  };
  const Solver solvers[] = {{"explicit", PressureMode::explicit_jacobi, LinearSolver::conjugate_gradient,
                             Preconditioner::diagonal},
                            {"CG, diagonal", PressureMode::iterative, LinearSolver::conjugate_gradient,
                             Preconditioner::diagonal},
                            {"CG, multigrid", PressureMode::iterative, LinearSolver::conjugate_gradient,
                             Preconditioner::multigrid},
                            {"BiCGSTAB, diagonal", PressureMode::iterative, LinearSolver::bicgstab,
                             Preconditioner::diagonal},
                            {"BiCGSTAB, multigrid", PressureMode::iterative, LinearSolver::bicgstab,
                             Preconditioner::multigrid}};
  const int before = omp_get_max_threads();
  for (const Solver& solver : solvers) {
    INFO(solver.name);
    auto run_with = [&](int threads) {
      omp_set_num_threads(threads);
      Settings st;
      st.particle_spacing = 0.0025;
      st.end_time = 10.0;
      st.pressure_mode = solver.mode;
      st.solver = solver.solver;
      st.preconditioner = solver.preconditioner;
      Model m = make_dam_break(st, 0.1, 2.0, 0.3);
      sph::RunOptions opt;
      opt.max_steps = 40;
      const sph::RunSummary summary = run(m, opt);
      REQUIRE(summary.stopped_because == "step_limit");
      return m;
    };
    Model one = run_with(1);
    Model two = run_with(2);
    CHECK(one.state.time == two.state.time);
    CHECK(same_state::differing_values(one.particles, two.particles) == 0);
  }
  omp_set_num_threads(before);
}

}  // namespace test_isph
