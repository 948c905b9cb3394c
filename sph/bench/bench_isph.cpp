// Benchmark: the ISPH fluid on the dam-break geometry of DualSPHysics' 2-D validation case (water column 1 m wide
// x 2 m high against the left wall of a 4 m tank, dp = 0.01 m: 20,000 fluid particles) to 0.5 s physical time.
// Prints wall time, steps and fluid particle-steps per second for the thread count given by OMP_NUM_THREADS, and
// the front against Martin & Moyce (1952, n^2 = 2; T = sqrt(2) t sqrt(g/a), Z = x/a, a = 1 m).
// Usage: bench-isph [dx (default 0.01)] [explicit|iterative (default iterative)] [end time s (default 0.5)]
//                   [solver tolerance (default: the settings' 1e-8)] [cfl (default: the settings')]
//                   [solves per step (default: the settings' wall_passes)] [diagonal|multigrid (default: the
//                   settings' preconditioner)]
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "sph/fluid/cases.hpp"
#include "sph/fluid/run.hpp"
#include "sphslope/units.hpp"

int main(int argc, char** argv) {
  sph::fluid::Settings st;
  st.particle_spacing = argc > 1 ? std::atof(argv[1]) : 0.01;
  st.pressure_mode = sph::fluid::pressure_mode_from(argc > 2 ? argv[2] : "iterative");
  st.end_time = argc > 3 ? std::atof(argv[3]) : 0.5;
  if (argc > 4) st.solver_tolerance = std::atof(argv[4]);
  if (argc > 5) st.cfl = std::atof(argv[5]);
  if (argc > 6) st.wall_passes = std::atoi(argv[6]);
  if (argc > 7) st.preconditioner = sph::fluid::preconditioner_from(argv[7]);
  const double a = 1.0;
  sph::fluid::Model model = sph::fluid::make_dam_break(st, a, 2.0, 4.0);
  long long iterations = 0;
  double worst_density_error = 0;
  sph::RunOptions options;
  options.progress_interval_wall_s = 30.0;
  sph::RunCallbacks callbacks;
  callbacks.progress = [](const sph::Progress& p) {
    std::printf("  t = %.4f s  step %llu  %.1f steps/s  dt %.3g s  max speed %.3g m/s\n", p.time,
                static_cast<unsigned long long>(p.step), p.steps_per_second, p.time_step, p.max_speed);
    std::fflush(stdout);
  };
  const auto sum = sph::fluid::run(model, options, callbacks, [&](const sph::fluid::Step& s, const sph::RunState&) {
    iterations += s.diagnostics().solve.iterations;
    worst_density_error = std::max(worst_density_error, s.diagnostics().max_density_error);
  });
  const double T = std::sqrt(2.0) * model.state.time * std::sqrt(sphslope::standard_gravity / a);
  std::printf(
      "bench-isph: dam break 1 m x 2 m in a 4 m tank, %zu fluid + %zu wall particles, dx = %.3g m, "
      "h/dx = %.2f, cfl %.3g, pressure %s (%s, %s preconditioner, tolerance %.0e, %d solves per step)\n",
      sum.soil_particles, sum.particles - sum.soil_particles, st.particle_spacing, st.h_over_dx,
      st.cfl, sph::fluid::pressure_mode_key(st.pressure_mode), sph::fluid::linear_solver_key(st.solver),
      sph::fluid::preconditioner_key(st.preconditioner), st.solver_tolerance, st.wall_passes);
  std::printf(
      "threads %d  t = %.4g s (%s)  steps %llu  wall %.2f s  %.3f ms/step  particle-steps/s %.4g  "
      "solver iterations/step %.1f  max density error %.3g\n",
      omp_get_max_threads(), model.state.time, sum.stopped_because.c_str(), static_cast<unsigned long long>(sum.steps),
      sum.wall_seconds, 1e3 * sum.wall_seconds / sum.steps, sum.particle_steps_per_second,
      static_cast<double>(iterations) / sum.steps, worst_density_error);
  std::printf("front: Z = x/a = %.3f at T = %.3f (Martin & Moyce n^2 = 2: Z = 2.56 at T = 2.20, 2.78 at 2.32)\n",
              sph::fluid::front_position(model) / a, T);
  return 0;
}
