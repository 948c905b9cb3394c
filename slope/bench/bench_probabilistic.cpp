// bench-probabilistic: the cost of a probabilistic analysis (slope/probabilistic.hpp) on Li & Lumb's slope
// (cases/li_lumb_1987_probabilistic.json: 10 m at 45 degrees, c' = 18 +- 3.6 kPa, phi' = 30 +- 3 deg, gamma = 18 +-
// 0.9 kN/m3, r_u = 0.2 +- 0.02, Bishop), in two modes:
//   critical surface  every sample on the deterministic critical circle (default 100 000 samples);
//   overall           a circular search for each sample (default 10 000 samples).
// Drawing and analysing are timed apart; the peak resident memory of the process is printed at the end. The threads
// are OpenMP's (OMP_NUM_THREADS). A benchmark program, not a test (docs/performance.md).
// Usage: bench-probabilistic [--samples N] [--overall-samples M] [--lhs]
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <omp.h>

#include "slope/probabilistic.hpp"
#include "sphslope/units.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

slope::Section li_lumb_section() {
  slope::Section s;
  s.bottom_y = 0.0;
  slope::Material m{"soil", 18e3, 18e3, sphslope::radians(30.0)};
  m.pore_pressure_ratio = 0.2;
  s.materials.push_back(m);
  s.profile_lines.push_back({0, {{0, 5}, {5, 5}, {15, 15}, {20, 15}}});
  return s;
}

slope::SamplingPlan plan_of(long samples, bool lhs) {
  using slope::RandomQuantity;
  slope::SamplingPlan plan;
  plan.samples = samples;
  plan.sampling = lhs ? slope::Sampling::latin_hypercube : slope::Sampling::monte_carlo;
  const auto add = [&](RandomQuantity q, double mean, double sd, std::optional<double> min) {
    slope::RandomVariable v;
    v.quantity = q;
    v.mean = mean;
    v.std_dev = sd;
    v.min = min;
    plan.variables.push_back(v);
  };
  add(RandomQuantity::cohesion, 18e3, 3.6e3, 0.0);
  add(RandomQuantity::friction_angle, sphslope::radians(30.0), sphslope::radians(3.0), 0.0);
  add(RandomQuantity::unit_weight, 18e3, 0.9e3, 0.0);
  add(RandomQuantity::pore_pressure_ratio, 0.2, 0.02, 0.0);
  return plan;
}

void run(const char* name, const slope::Section& section, const slope::SamplingPlan& plan,
         const slope::ProbabilisticSurface& surface, const slope::SearchOptions& options) {
  const Clock::time_point start = Clock::now();
  const std::vector<double> values = slope::draw_samples(plan, 0, plan.samples);
  const double draw = since(start);
  const Clock::time_point analyse = Clock::now();
  const auto outcomes = slope::evaluate_samples(section, plan, surface, slope::Method::bishop, options, values);
  const double seconds = since(analyse);
  const slope::ProbabilisticStatistics s = slope::probabilistic_statistics(outcomes);
  std::printf("%-17s %9ld samples  draw %7.3f s  analyse %8.3f s  (%6.1f us a sample per thread)  mean FS %.4f  "
              "sd %.4f  PF %.4f  beta_ln %.3f\n",
              name, plan.samples, draw, seconds, 1e6 * seconds * omp_get_max_threads() / static_cast<double>(plan.samples),
              s.mean, s.std_dev, s.probability_of_failure, s.beta_lognormal.value_or(0.0));
}

}  // namespace

int main(int argc, char** argv) {
  long samples = 100000, overall_samples = 10000;
  bool lhs = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--samples") && i + 1 < argc) samples = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--overall-samples") && i + 1 < argc) overall_samples = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--lhs")) lhs = true;
    else {
      std::fprintf(stderr, "usage: bench-probabilistic [--samples N] [--overall-samples M] [--lhs]\n");
      return 2;
    }
  }
  const slope::Section section = li_lumb_section();
  slope::SearchOptions options;
  const Clock::time_point start = Clock::now();
  const slope::SearchResult search = slope::search_critical(section, {slope::Method::bishop}, options);
  if (!search.methods[0].mass) return 1;
  std::printf("Li & Lumb's slope, Bishop, %s, %d threads; deterministic search %.3f s: FS %.4f\n",
              lhs ? "Latin hypercube" : "Monte Carlo", omp_get_max_threads(), since(start),
              *search.methods[0].result.factor_of_safety);
  slope::ProbabilisticSurface surface;
  surface.circle = search.methods[0].mass->circle;
  if (samples > 0) run("critical surface", section, plan_of(samples, lhs), surface, options);
  surface.kind = slope::ProbabilisticSurface::Kind::overall;
  if (overall_samples > 0) run("overall", section, plan_of(overall_samples, lhs), surface, options);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("peak resident memory %.1f MB\n", static_cast<double>(usage.ru_maxrss) / 1024.0);
  return 0;
}
