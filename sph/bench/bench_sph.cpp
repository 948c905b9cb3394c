// Benchmark: granular column collapse (Bui et al. 2008 set-up) at ~50,000 soil particles, double precision.
// Prints, for each time integration (the default sub-stepped Verlet step and the predictor-corrector), soil
// particle-steps per second and simulated time per wall second for the thread count given by OMP_NUM_THREADS.
// A Verlet step evaluates the pair sums twice (kinematics, then forces) and may sub-step the stress update, so its
// particle-steps/s is lower; its step is six times longer (docs/sph.md, "Time step"): compare the simulated time.
// Usage: bench-sph [soil_particles (default 50000)] [steps (default 300)] [verlet|predictor_corrector|both (both)]
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "sph/soil/benchmarks.hpp"
#include "sph/soil/soil_step.hpp"

namespace {

void run(double target, int steps, sph::soil::TimeIntegration integration) {
  sph::soil::ColumnCollapseCase c;
  c.dx = std::sqrt(c.length * c.height / target);
  sph::soil::Model model = sph::soil::make_column_collapse(c);
  model.settings.use_integration(integration);
  const std::size_t soil = model.particles.count(sph::ParticleKind::material);
  sph::soil::SoilStep stepper(model);
  stepper.initialise();
  // warm-up: let the collapse start so that the particles move and the sort does real work
  for (int k = 0; k < 20; ++k) stepper.advance(stepper.stable_time_step());
  const double t_start = model.state.time;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) stepper.advance(stepper.stable_time_step());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto e = stepper.energies();
  const double rate = static_cast<double>(soil) * steps / wall;
  const bool verlet = integration == sph::soil::TimeIntegration::verlet;
  std::printf("bench-sph: column collapse, %zu soil + %zu wall particles, dx = %.3g m, h/dx = %.2f, cubic spline, "
              "%s (cfl %.2g, up to %d stress sub-steps)\n",
              soil, model.particles.size() - soil, c.dx, c.h_over_dx, verlet ? "verlet" : "predictor_corrector",
              model.settings.cfl, model.settings.stress_substeps);
  std::printf("threads %d  steps %d  wall %.3f s  %.3f ms/step  particle-steps/s %.4g  simulated s per wall s %.4g  "
              "(t = %.4g s, max speed %.3g m/s)\n",
              omp_get_max_threads(), steps, wall, 1e3 * wall / steps, rate, (model.state.time - t_start) / wall,
              model.state.time, e.max_speed);
}

}  // namespace

int main(int argc, char** argv) {
  const double target = argc > 1 ? std::atof(argv[1]) : 50000.0;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 300;
  const char* which = argc > 3 ? argv[3] : "both";
  const bool both = std::strcmp(which, "both") == 0;
  const bool verlet = both || std::strcmp(which, "verlet") == 0;
  const bool pc = both || std::strcmp(which, "predictor_corrector") == 0;
  if (!(target > 0) || steps < 1 || !(verlet || pc)) {
    std::fprintf(stderr, "usage: bench-sph [soil_particles > 0] [steps >= 1] [verlet|predictor_corrector|both]\n");
    return 2;
  }
  if (verlet) run(target, steps, sph::soil::TimeIntegration::verlet);
  if (pc) run(target, steps, sph::soil::TimeIntegration::predictor_corrector);
  return 0;
}
