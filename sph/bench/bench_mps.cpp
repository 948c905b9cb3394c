// Benchmark of the WC-MPS: the seed's dry granular collapse (a column 0.1 m long x 0.06 m high of the default
// granular material at the left wall of a 0.3 m tank, released at t = 0) at about 50,000 grains, double precision.
// Prints moving particle-steps per second for the thread count given by OMP_NUM_THREADS.
// Usage: bench-mps [grains (default 50000)] [steps (default 100)] [paper|case (default paper)]
// "paper": the paper's smoothed p' and eq. 22 (the library's defaults until 2026-11-27, so the earlier figures of
// docs/performance.md are comparable); "case": the library's defaults, as in cases/mps_dry_collapse_lajeunesse.json,
// the thin-layer p' and the full stress divergence.
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "sph/mps/model.hpp"
#include "sph/mps/stepper.hpp"

int main(int argc, char** argv) {
  const double target = argc > 1 ? std::atof(argv[1]) : 50000.0;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 100;
  const std::string forms = argc > 3 ? argv[3] : "paper";
  if (!(target >= 10) || steps < 1 || (forms != "paper" && forms != "case")) {
    std::fprintf(stderr, "bench-mps: usage: bench-mps [grains >= 10 (50000)] [steps >= 1 (100)] [paper|case]\n");
    return 2;
  }
  const double length = 0.1, height = 0.06;  // [m]
  sph::mps::Settings st;
  st.particle_spacing = std::sqrt(length * height / target);
  st.end_time = 1.0;
  if (forms == "paper") {
    st.effective_pressure = sph::mps::EffectivePressure::smoothed;
    st.stress_divergence = sph::mps::StressDivergence::direct;
  }
  sph::mps::Model model(st, {sph::mps::Material::granular_material()});
  const std::size_t grains = sph::mps::add_block(model, 0.0, 0.0, length, height, 0);
  sph::mps::add_box(model, 0.0, 0.3, 0.0, 2 * height, 0);
  sph::mps::Step step(model);
  step.initialise();
  for (int k = 0; k < 10; ++k) step.advance(step.stable_time_step());  // warm-up: the column starts to move
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) step.advance(step.stable_time_step());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("bench-mps: dry collapse (%s forms), %zu grains + %zu wall and dummy particles, dx = %.3g m, r_e = %.1f "
              "dx\n",
              forms.c_str(), grains, model.particles.size() - grains, st.particle_spacing, st.re_over_dx);
  std::printf("threads %d  steps %d  wall %.3f s  %.3f ms/step  particle-steps/s %.4g  (t = %.4g s, candidates "
              "listed %llu times)\n",
              omp_get_max_threads(), steps, wall, 1e3 * wall / steps, static_cast<double>(grains) * steps / wall,
              model.state.time, static_cast<unsigned long long>(step.candidate_listings()));
  return 0;
}
