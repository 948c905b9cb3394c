// Random variables and their samples (probabilistic.hpp): distributions, the counter-based generator, Monte Carlo
// and Latin hypercube plans, correlation in standard-normal space.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "slope/probabilistic.hpp"

namespace slope {

namespace {

// SplitMix64's output function (Steele, Lea & Flood 2014): a bijection of 64-bit words whose outputs pass the
// usual statistical batteries as a counter runs through it.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The word of stream `stream` (0: Monte Carlo and the points inside the strata, 1: the strata's permutations) at
// (sample, variable) for `seed`.
std::uint64_t word(std::uint64_t seed, std::uint64_t stream, std::uint64_t sample, std::uint64_t variable) {
  return mix(mix(mix(seed ^ (stream << 62)) + sample) + variable);
}

// A uniform number in (0, 1) from the word's top 53 bits.
double unit(std::uint64_t w) { return (static_cast<double>(w >> 11) + 0.5) * 0x1.0p-53; }

// Where a truncated normal-family variable's probability starts and ends in its untruncated distribution.
struct Tails {
  double low = 0.0;   // F(min) of the distribution before truncation
  double high = 1.0;  // F(max)
};

double lognormal_sigma(const RandomVariable& v) { return std::sqrt(std::log1p((v.std_dev / v.mean) * (v.std_dev / v.mean))); }
double lognormal_mu(const RandomVariable& v) {
  const double s = lognormal_sigma(v);
  return std::log(v.mean) - 0.5 * s * s;
}

// The standard normal score of x for a normal or lognormal variable.
double score(const RandomVariable& v, double x) {
  if (v.distribution == Distribution::normal) return (x - v.mean) / v.std_dev;
  if (x <= 0.0) return -INFINITY;
  return (std::log(x) - lognormal_mu(v)) / lognormal_sigma(v);
}

Tails tails(const RandomVariable& v) {
  Tails t;
  if (v.min) t.low = normal_cdf(score(v, *v.min));
  if (v.max) t.high = normal_cdf(score(v, *v.max));
  return t;
}

// A normal-family variable's value at the standard normal score z.
double from_score(const RandomVariable& v, double z) {
  if (v.distribution == Distribution::normal) return v.mean + v.std_dev * z;
  return std::exp(lognormal_mu(v) + lognormal_sigma(v) * z);
}

}  // namespace

std::string variable_error(const RandomVariable& v) {
  const bool normal_family = v.distribution == Distribution::normal || v.distribution == Distribution::lognormal;
  if (normal_family) {
    if (!(v.std_dev > 0.0) || !std::isfinite(v.std_dev)) return "its standard deviation must be > 0";
    if (v.distribution == Distribution::lognormal && !(v.mean > 0.0))
      return "a lognormal variable's mean must be > 0";
    if (v.min && !(*v.min < v.mean)) return "its truncation's min must be below the mean (it would exclude it)";
    if (v.max && !(*v.max > v.mean)) return "its truncation's max must be above the mean (it would exclude it)";
    const Tails t = tails(v);
    if (!(t.high - t.low > 1e-12)) return "its truncation leaves no probability (min and max too far in one tail)";
    return {};
  }
  if (!v.min || !v.max) return "a uniform or triangular variable needs min and max";
  if (!(*v.min < *v.max)) return "its min must be below its max";
  if (!(*v.min <= v.mean && v.mean <= *v.max)) return "its deterministic value must lie in [min, max]";
  return {};
}

namespace {

// Latin hypercube: for each variable the stratum of each sample, a permutation of 0..N-1 (Fisher-Yates, from
// stream 1 of the seed).
std::vector<std::vector<long>> strata(const SamplingPlan& plan) {
  std::vector<std::vector<long>> out(plan.variables.size());
  for (std::size_t v = 0; v < out.size(); ++v) {
    std::vector<long>& p = out[v];
    p.resize(static_cast<std::size_t>(plan.samples));
    std::iota(p.begin(), p.end(), 0L);
    for (long i = plan.samples - 1; i > 0; --i) {
      const std::uint64_t w = word(plan.seed, 1, static_cast<std::uint64_t>(i), v);
      const long j = static_cast<long>(w % static_cast<std::uint64_t>(i + 1));
      std::swap(p[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(j)]);
    }
  }
  return out;
}

}  // namespace

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// Acklam's rational approximation (relative error 1.15e-9), then one Halley step on erfc, which brings it to the
// precision of erfc.
double normal_quantile(double p) {
  if (!(p > 0.0)) return -INFINITY;
  if (!(p < 1.0)) return INFINITY;
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                                 1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                                 6.680131188771972e+01,  -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                                 -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                 3.754408661907416e+00};
  constexpr double p_low = 0.02425;
  double x;
  if (p < p_low || p > 1.0 - p_low) {
    const double q = std::sqrt(-2.0 * std::log(p < p_low ? p : 1.0 - p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
    if (p > 1.0 - p_low) x = -x;
  } else {
    const double q = p - 0.5, r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  }
  // Halley's step on e = Phi(x) - p, computed in the tail where it is relative to the smaller of p and 1 - p.
  const double e = p < 0.5 ? normal_cdf(x) - p : (1.0 - p) - normal_cdf(-x);
  constexpr double sqrt_two_pi = 2.5066282746310002;
  const double u = e * sqrt_two_pi * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

double inverse_cdf(const RandomVariable& v, double u) {
  switch (v.distribution) {
    case Distribution::normal:
    case Distribution::lognormal: {
      if (!v.min && !v.max) return from_score(v, normal_quantile(u));
      const Tails t = tails(v);
      const double x = from_score(v, normal_quantile(t.low + u * (t.high - t.low)));
      return std::clamp(x, v.min.value_or(-INFINITY), v.max.value_or(INFINITY));
    }
    case Distribution::uniform: return *v.min + u * (*v.max - *v.min);
    case Distribution::triangular: {
      const double a = *v.min, b = *v.max, c = v.mean;
      if (u * (b - a) < c - a) return a + std::sqrt(u * (b - a) * (c - a));
      return b - std::sqrt((1.0 - u) * (b - a) * (b - c));
    }
  }
  return v.mean;
}

std::string plan_error(const SamplingPlan& plan) {
  if (plan.variables.empty()) return "no random variables";
  if (plan.samples < 1) return "the number of samples must be >= 1";
  for (std::size_t i = 0; i < plan.variables.size(); ++i) {
    const std::string fault = variable_error(plan.variables[i]);
    if (!fault.empty()) return "variable " + std::to_string(i) + ": " + fault;
  }
  std::vector<int> uses(plan.variables.size(), 0);
  for (std::size_t i = 0; i < plan.correlations.size(); ++i) {
    const VariableCorrelation& c = plan.correlations[i];
    const std::string name = "correlation " + std::to_string(i) + ": ";
    if (!(c.coefficient >= -1.0 && c.coefficient <= 1.0)) return name + "its coefficient must be in [-1, 1]";
    if (c.first >= uses.size() || c.second >= uses.size() || c.first == c.second)
      return name + "it must join two different variables";
    if (++uses[c.first] > 1 || ++uses[c.second] > 1) return name + "a variable may take part in one correlation only";
  }
  return {};
}

std::vector<double> draw_samples(const SamplingPlan& plan, long first, long count) {
  const std::size_t nv = plan.variables.size();
  std::vector<double> u(static_cast<std::size_t>(count) * nv);
  const auto permutations =
      plan.sampling == Sampling::latin_hypercube ? strata(plan) : std::vector<std::vector<long>>{};
  for (long s = 0; s < count; ++s) {
    const auto sample = static_cast<std::uint64_t>(first + s);
    for (std::size_t v = 0; v < nv; ++v) {
      double x = unit(word(plan.seed, 0, sample, v));
      if (!permutations.empty())
        x = (static_cast<double>(permutations[v][static_cast<std::size_t>(first + s)]) + x) /
            static_cast<double>(plan.samples);
      u[static_cast<std::size_t>(s) * nv + v] = x;
    }
    for (const VariableCorrelation& c : plan.correlations) {
      double* row = &u[static_cast<std::size_t>(s) * nv];
      const double z1 = normal_quantile(row[c.first]), z2 = normal_quantile(row[c.second]);
      const double rho = c.coefficient;
      row[c.second] = normal_cdf(rho * z1 + std::sqrt(std::max(0.0, 1.0 - rho * rho)) * z2);
    }
  }
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double p = std::clamp(u[i], 0x1.0p-60, 1.0 - 0x1.0p-53);
    u[i] = inverse_cdf(plan.variables[i % nv], p);
  }
  return u;
}

}  // namespace slope
