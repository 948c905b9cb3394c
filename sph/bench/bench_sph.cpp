// Benchmark: granular column collapse (Bui et al. 2008 set-up) at ~50,000 soil particles, double precision.
// Prints soil particle-steps per second for the thread count given by OMP_NUM_THREADS.
// Usage: bench-sph [soil_particles (default 50000)] [steps (default 300)]
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "sph/soil/benchmarks.hpp"
#include "sph/soil/soil_step.hpp"

int main(int argc, char** argv) {
  const double target = argc > 1 ? std::atof(argv[1]) : 50000.0;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 300;
  sph::ColumnCollapseCase c;
  c.dx = std::sqrt(c.length * c.height / target);
  sph::Model model = sph::make_column_collapse(c);
  const std::size_t soil = model.particles.count(sph::ParticleKind::soil);
  sph::SoilStep stepper(model);
  stepper.initialise();
  // warm-up: let the collapse start so that the particles move and the sort does real work
  for (int k = 0; k < 20; ++k) stepper.advance(stepper.stable_time_step());
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) stepper.advance(stepper.stable_time_step());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto e = stepper.energies();
  const double rate = static_cast<double>(soil) * steps / wall;
  std::printf("bench-sph: column collapse, %zu soil + %zu wall particles, dx = %.3g m, h/dx = %.2f, cubic spline\n",
              soil, model.particles.size() - soil, c.dx, c.h_over_dx);
  std::printf("threads %d  steps %d  wall %.3f s  %.3f ms/step  particle-steps/s %.4g  (t = %.4g s, max speed %.3g m/s)\n",
              omp_get_max_threads(), steps, wall, 1e3 * wall / steps, rate, model.state.time, e.max_speed);
  return 0;
}
