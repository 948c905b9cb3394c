// Granular column collapse of Bui, Fukagawa, Sako & Ohno (2008), IJNAMG 32:1537 (aluminium bars,
// 0.2 m x 0.1 m, rho = 2650, E = 0.84 MPa, nu = 0.3, phi = 19.8 deg, c = 0, psi = 0), coarse (dx = 5 mm).
//
// References for the deposit (aspect ratio a = H0/L0 = 0.5):
//  * final height: for a <= 0.65 the top of the column is not reached by the failure, h_inf = h0
//    (Nguyen, Bui & Fukagawa 2015, arXiv:1512.05180, aluminium rods; Lube et al. 2005 PRE 72:041301: H_inf/L0 = a
//    for a < 1.15). Tolerance: -8 % / +5 % (one particle spacing is 5 %).
//  * run-out L_inf from the back wall: the true-2-D law of Nguyen, Bui & Fukagawa (2015) for aluminium rods (the
//    material class of Bui 2008), (d_inf - d0)/d0 = 3.25 a^0.96, fitted for a >= 0.65 and extrapolated to a = 0.5,
//    gives 0.53 m; the quasi-2-D laws of Lube et al. (2005) and Lajeunesse et al. (2005) 0.32 and 0.38 m (secondary-
//    source values, docs/sph.md). At this spacing (40 particles across) the run-out is not converged in the spacing
//    (docs/accuracy.md: 0.447 m at 5 mm, 0.491 m at 2.5 mm, the law 0.534 m), so the law cannot set a tight band.
//    The band is set from what was measured at this spacing (Release, OMP_NUM_THREADS=2 build/tests/test_sph
//    "column collapse resolution study" -s with SPH_STUDY_CFL = 0.8, 0.4, 0.2, 0.1): 0.4339 / 0.4377 / 0.4398 /
//    0.4398 m, so the run-out converged in the step is 0.4398 m and the default step (cfl 0.8) is 1.3 % short of it.
//    Accepted: within 2.5 % of 0.4398 m (0.429 to 0.451 m), the step error and a margin: the default's 0.4339 m
//    fails when it moves 1.2 % down or 3.9 % up (the old band, 0.32 to 0.56 m, let a 9 % change pass), and a broken
//    solver fails (no friction: the mass reaches the far wall at 0.6 m; no flow: 0.2 m).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "sph/soil/benchmarks.hpp"
#include "sph/soil/run.hpp"

namespace test_column_collapse {

TEST_CASE("granular column collapse (Bui et al. 2008) deposit matches the experiments' scaling laws",
          "[sph][validation][collapse]") {
  sph::soil::ColumnCollapseCase c;
  c.dx = 0.005;
  c.end_time = 1.0;
  sph::soil::Model model = sph::soil::make_column_collapse(c);
  model.settings.output_interval = 0;
  sph::RunOptions opt;
  const auto sum = sph::soil::run(model, opt);
  REQUIRE(sum.stopped_because == "end_time");
  const auto d = sph::soil::measure_deposit(model);
  std::printf("column collapse dx = %.4f m: run-out %.4f m, height %.4f m, KE_end %.3g J/m, %zu soil particles, "
              "%llu steps, %.0f particle-steps/s\n",
              c.dx, d.runout, d.height, sum.kinetic_energy, sum.soil_particles,
              static_cast<unsigned long long>(sum.steps), sum.particle_steps_per_second);
  // the walls hold the soil: no particle centre has leaked through the floor or the back wall
  double ymin = 1, xmin = 1;
  for (std::size_t i = 0; i < model.particles.size(); ++i)
    if (model.particles.kind[i] == 0) {
      ymin = std::min(ymin, model.particles.y[i]);
      xmin = std::min(xmin, model.particles.x[i]);
    }
  std::printf("lowest soil particle centre y = %.5f m, leftmost x = %.5f m\n", ymin, xmin);
  CHECK(ymin > 0.0);
  CHECK(xmin > 0.0);
  CHECK(d.height >= 0.092);
  CHECK(d.height <= 0.105);
  const double converged_in_step = 0.4398;  // [m] at this spacing (header)
  CHECK(d.runout >= (1.0 - 0.025) * converged_in_step);
  CHECK(d.runout <= (1.0 + 0.025) * converged_in_step);
  // the deposit is at rest at t = 1 s: kinetic energy below 0.1 % of the potential energy released
  CHECK(sum.kinetic_energy < 1e-3 * (model.state.initial_potential_energy - sum.potential_energy));
  // energy: plastic dissipation must account for most of the released potential energy
  CHECK(sum.plastic_dissipation > 0.3 * (model.state.initial_potential_energy - sum.potential_energy));
}

// Resolution study, print only (not part of ctest: hidden tag). SPH_STUDY_DX selects dx [m], SPH_STUDY_CFL the cfl
// of the default (Verlet) step.
TEST_CASE("column collapse resolution study", "[.study]") {
  sph::soil::ColumnCollapseCase c;
  if (const char* e = std::getenv("SPH_STUDY_DX")) c.dx = std::atof(e);
  if (const char* e = std::getenv("SPH_STUDY_HDX")) c.h_over_dx = std::atof(e);
  if (const char* e = std::getenv("SPH_STUDY_SLIP")) c.wall_slip = std::string(e) == "free" ? sph::soil::WallSlip::free_slip : sph::soil::WallSlip::no_slip;
  c.end_time = 1.0;
  sph::soil::Model model = sph::soil::make_column_collapse(c);
  model.settings.output_interval = 0.05;
  if (const char* e = std::getenv("SPH_STUDY_CFL")) model.settings.cfl = std::atof(e);
  sph::RunOptions opt;
  if (const char* e = std::getenv("SPH_STUDY_OUT")) opt.output_dir = e;
  const auto sum = sph::soil::run(model, opt);
  const auto d = sph::soil::measure_deposit(model);
  std::printf("study dx = %.4f h/dx = %.2f cfl %.3g: run-out %.4f m, height %.4f m, KE_end %.3g, %llu steps, %.3g s wall, %s\n",
              c.dx, c.h_over_dx, model.settings.cfl, d.runout, d.height, sum.kinetic_energy, static_cast<unsigned long long>(sum.steps),
              sum.wall_seconds, sum.stopped_because.c_str());
  // surface profile
  for (double x = 0.0; x < d.runout + 0.01; x += 0.02) {
    double top = 0;
    for (std::size_t i = 0; i < model.particles.size(); ++i)
      if (model.particles.kind[i] == 0 && std::fabs(model.particles.x[i] - x) < c.dx)
        top = std::max(top, model.particles.y[i] + 0.5 * c.dx);
    std::printf("  x = %.3f  surface %.4f\n", x, top);
  }
}

}  // namespace test_column_collapse
