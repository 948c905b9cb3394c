// Probabilistic limit equilibrium (probabilistic.hpp): each sample's section, its factor of safety, the statistics.
#include "slope/probabilistic.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>

#include <omp.h>

namespace slope {

void apply_sample(const Section& base, const std::vector<RandomVariable>& variables, const double* values,
                  Section& out) {
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const RandomVariable& v = variables[i];
    const double x = values[i];
    switch (v.quantity) {
      case RandomQuantity::cohesion: out.materials[v.index].cohesion = x; break;
      case RandomQuantity::friction_angle: out.materials[v.index].friction_angle = x; break;
      case RandomQuantity::friction_coefficient: out.materials[v.index].friction_angle = std::atan(x); break;
      case RandomQuantity::unit_weight: out.materials[v.index].unit_weight = x; break;
      case RandomQuantity::saturated_unit_weight: out.materials[v.index].saturated_unit_weight = x; break;
      case RandomQuantity::cohesion_rate: out.materials[v.index].cohesion_rate = x; break;
      case RandomQuantity::pore_pressure_ratio: out.materials[v.index].pore_pressure_ratio = x; break;
      case RandomQuantity::seismic_coefficient: out.seismic_coefficient = x; break;
      case RandomQuantity::water_level: {
        const std::vector<Point>& line = base.water->piezometric_line;
        for (std::size_t p = 0; p < line.size(); ++p) out.water->piezometric_line[p].y = line[p].y + x;
        break;
      }
      case RandomQuantity::surcharge_pressure: {
        const Surcharge& given = base.surcharges[v.index];
        Surcharge& load = out.surcharges[v.index];
        load.pressure = x;
        // A trapezoid keeps its shape: its end pressure in proportion (or shifted alike when the start is zero).
        if (given.pressure_end)
          load.pressure_end = given.pressure != 0.0 ? *given.pressure_end * (x / given.pressure)
                                                    : *given.pressure_end + x;
        break;
      }
    }
  }
}

namespace {

SampleOutcome analyse_sample(const Section& section, const ProbabilisticSurface& surface, Method method,
                             const SearchOptions& options) {
  SampleOutcome out;
  try {
    if (surface.kind == ProbabilisticSurface::Kind::overall) {
      SearchResult result = search_critical(section, {method}, options);
      const CriticalSurface& critical = result.methods.front();
      if (result.error.empty() && critical.mass && critical.result.factor_of_safety) {
        out.factor_of_safety = critical.result.factor_of_safety;
        out.circle = critical.mass->circle;
      }
      return out;
    }
    const std::optional<SlipMass> mass = surface.kind == ProbabilisticSurface::Kind::fixed_circle
                                             ? slice_circle(section, surface.circle, options.slicing)
                                             : slice_polyline(section, surface.polyline, options.slicing);
    if (mass) out.factor_of_safety = factor_of_safety(*mass, method).factor_of_safety;
  } catch (const std::exception&) {
    out = {};  // a sample whose analysis throws counts as failed, like one that does not converge
  }
  if (out.factor_of_safety && !std::isfinite(*out.factor_of_safety)) out.factor_of_safety.reset();
  return out;
}

}  // namespace

std::vector<SampleOutcome> evaluate_samples(const Section& section, const SamplingPlan& plan,
                                            const ProbabilisticSurface& surface, Method method,
                                            const SearchOptions& options, const std::vector<double>& values,
                                            const std::function<void(long)>& progress) {
  const std::size_t nv = plan.variables.size();
  const long count = nv == 0 ? 0 : static_cast<long>(values.size() / nv);
  std::vector<SampleOutcome> out(static_cast<std::size_t>(count));
  SearchOptions search = options;
  search.fs_map_method = method;
  std::atomic<long> done{0};
#pragma omp parallel
  {
    Section work = section;
#pragma omp for schedule(dynamic, 8)
    for (long s = 0; s < count; ++s) {
      apply_sample(section, plan.variables, &values[static_cast<std::size_t>(s) * nv], work);
      out[static_cast<std::size_t>(s)] = analyse_sample(work, surface, method, search);
      const long finished = ++done;
      if (progress && omp_get_thread_num() == 0) progress(finished);
    }
  }
  return out;
}

namespace {

// Running mean and variance (Welford) with the count below 1.
struct Running {
  long n = 0, below = 0;
  double mean = 0.0, m2 = 0.0;
  void add(double x) {
    ++n;
    below += x < 1.0 ? 1 : 0;
    const double d = x - mean;
    mean += d / static_cast<double>(n);
    m2 += d * (x - mean);
  }
  double std_dev() const { return n > 1 ? std::sqrt(m2 / static_cast<double>(n - 1)) : 0.0; }
  double probability() const { return n > 0 ? static_cast<double>(below) / static_cast<double>(n) : 0.0; }
};

// About 30 sample counts from 10 to n, evenly on a log scale, n last.
std::vector<long> convergence_counts(long n) {
  std::vector<long> counts;
  if (n <= 0) return counts;
  const long start = std::min(10L, n);
  constexpr int points = 30;
  for (int k = 0; k < points; ++k) {
    const double f = static_cast<double>(k) / (points - 1);
    const long c = std::lround(static_cast<double>(start) * std::pow(static_cast<double>(n) / start, f));
    if (counts.empty() || c > counts.back()) counts.push_back(c);
  }
  if (counts.back() != n) counts.push_back(n);
  return counts;
}

}  // namespace

ProbabilisticStatistics probabilistic_statistics(const std::vector<SampleOutcome>& outcomes) {
  ProbabilisticStatistics out;
  const std::vector<long> counts = convergence_counts(static_cast<long>(outcomes.size()));
  Running running;
  std::size_t next = 0;
  out.min = INFINITY;
  out.max = -INFINITY;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    if (const auto& f = outcomes[i].factor_of_safety) {
      running.add(*f);
      out.min = std::min(out.min, *f);
      out.max = std::max(out.max, *f);
    } else {
      ++out.failed_samples;
    }
    if (next < counts.size() && static_cast<long>(i + 1) == counts[next]) {
      out.convergence.push_back({counts[next], running.mean, running.std_dev(), running.probability()});
      ++next;
    }
  }
  out.samples = running.n;
  if (out.samples == 0) out.min = out.max = 0.0;
  out.mean = running.mean;
  out.std_dev = running.std_dev();
  out.below_one = running.below;
  out.probability_of_failure = running.probability();
  if (out.std_dev > 0.0) {
    out.beta_normal = (out.mean - 1.0) / out.std_dev;
    if (out.mean > 0.0) {
      const double v = out.std_dev / out.mean, s2 = std::log1p(v * v);
      out.beta_lognormal = std::log(out.mean / std::sqrt(1.0 + v * v)) / std::sqrt(s2);
    }
  }
  return out;
}

}  // namespace slope
