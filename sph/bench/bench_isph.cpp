// Benchmark: the ISPH fluid on the dam-break geometry of DualSPHysics' 2-D validation case (water column 1 m wide
// x 2 m high against the left wall of a 4 m tank, dp = 0.01 m: 20,000 fluid particles) to 0.5 s physical time.
// Prints wall time, steps and fluid particle-steps per second for the thread count given by OMP_NUM_THREADS, and
// the front against Martin & Moyce (1952, n^2 = 2; T = sqrt(2) t sqrt(g/a), Z = x/a, a = 1 m): the RMS relative
// error of Z over their table's points with 0.84 <= T <= the end, without a time shift and with the best shift in
// [-0.3, 0] (as the validation test and the study, docs/isph.md section 5).
// The benchmark's time-step factor is 0.2, twice the paper's default 0.1: on the Martin & Moyce case it gives the
// same front error in half the steps (docs/performance.md, "ISPH fluid").
// Usage: bench-isph [dx (default 0.01)] [explicit|iterative (default iterative)] [end time s (default 0.5)]
//                   [solver tolerance (default: the settings' 1e-8)] [cfl (default 0.2)]
//                   [solves per step (default: the settings' wall_passes)] [diagonal|multigrid (default: the
//                   settings' preconditioner)]
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "sph/fluid/cases.hpp"
#include "sph/fluid/reference_fronts.hpp"
#include "sph/fluid/run.hpp"
#include "sphslope/units.hpp"

namespace {

constexpr double kBenchCfl = 0.2;

sph::fluid::Settings settings_from(int argc, char** argv) {
  sph::fluid::Settings st;
  st.particle_spacing = argc > 1 ? std::atof(argv[1]) : 0.01;
  st.pressure_mode = sph::fluid::pressure_mode_from(argc > 2 ? argv[2] : "iterative");
  st.end_time = argc > 3 ? std::atof(argv[3]) : 0.5;
  if (argc > 4) st.solver_tolerance = std::atof(argv[4]);
  st.cfl = argc > 5 ? std::atof(argv[5]) : kBenchCfl;
  if (argc > 6) st.wall_passes = std::atoi(argv[6]);
  if (argc > 7) st.preconditioner = sph::fluid::preconditioner_from(argv[7]);
  return st;
}

}  // namespace

int main(int argc, char** argv) {
  const sph::fluid::Settings st = settings_from(argc, argv);
  const double a = 1.0, n = sph::fluid::martin_moyce_1952_n2_2_n, g = sphslope::standard_gravity;
  sph::fluid::Model model = sph::fluid::make_dam_break(st, a, 2.0, 4.0);
  long long iterations = 0, fallbacks = 0;
  double worst_density_error = 0;
  sph::fluid::FrontSeries front;
  front.T.push_back(0.0);
  front.Z.push_back(sph::fluid::front_position(model) / a);
  sph::RunOptions options;
  options.progress_interval_wall_s = 30.0;
  sph::RunCallbacks callbacks;
  callbacks.progress = [](const sph::Progress& p) {
    std::printf("  t = %.4f s  step %llu  %.1f steps/s  dt %.3g s  max speed %.3g m/s\n", p.time,
                static_cast<unsigned long long>(p.step), p.steps_per_second, p.time_step, p.max_speed);
    std::fflush(stdout);
  };
  const auto sum = sph::fluid::run(model, options, callbacks, [&](const sph::fluid::Step& s, const sph::RunState& r) {
    iterations += s.diagnostics().solve_iterations;
    fallbacks += s.diagnostics().fallbacks;
    worst_density_error = std::max(worst_density_error, s.diagnostics().max_density_error);
    front.T.push_back(n * r.time * std::sqrt(g / a));
    front.Z.push_back(sph::fluid::front_position(model) / a);
  });
  std::printf(
      "bench-isph: dam break 1 m x 2 m in a 4 m tank, %zu fluid + %zu wall particles, dx = %.3g m, "
      "h/dx = %.2f, cfl %.3g, pressure %s (%s, %s preconditioner, tolerance %.0e, %d solves per step)\n",
      sum.soil_particles, sum.particles - sum.soil_particles, st.particle_spacing, st.h_over_dx, st.cfl,
      sph::fluid::pressure_mode_key(st.pressure_mode), sph::fluid::linear_solver_key(st.solver),
      sph::fluid::preconditioner_key(st.preconditioner), st.solver_tolerance, st.wall_passes);
  std::printf(
      "threads %d  t = %.4g s (%s)  steps %llu  wall %.2f s  %.3f ms/step  particle-steps/s %.4g  "
      "solver iterations/step %.1f (all solves)  fallbacks %lld  max density error %.3g\n",
      omp_get_max_threads(), model.state.time, sum.stopped_because.c_str(), static_cast<unsigned long long>(sum.steps),
      sum.wall_seconds, 1e3 * sum.wall_seconds / sum.steps, sum.particle_steps_per_second,
      static_cast<double>(iterations) / sum.steps, fallbacks, worst_density_error);
  const auto table = sph::fluid::martin_moyce_1952_n2_2();
  const double T_end = front.T.back(), T_min = 0.84;
  const double plain = sph::fluid::front_rms_error(front, table, T_min, T_end);
  const auto shifted = sph::fluid::best_shifted_front_error(front, table, T_min, T_end, -0.3, 0.01);
  std::printf("front: Z = x/a = %.3f at T = %.3f; against Martin & Moyce (n^2 = 2) over %.2f <= T <= %.3f: RMS "
              "relative error %.4f without a shift, %.4f with dT = %.2f\n",
              front.Z.back(), T_end, T_min, T_end, plain, shifted.error, shifted.shift);
  return 0;
}
