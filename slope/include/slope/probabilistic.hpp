#pragma once
// Probabilistic limit equilibrium: random material properties, water level, surcharges and k_h; Monte Carlo or Latin
// hypercube samples, seeded and reproducible sample by sample (a sample's values depend on the seed, its index and
// the number of samples alone, so that samples split over several runs and merged are those of one run); the factor
// of safety of each sample on a fixed slip surface or of its own critical circle; the statistics engineers report
// (mean, standard deviation, probability of failure, reliability indices).
//
// Sampling: each variable's value is its inverse CDF at a uniform u in (0, 1). Monte Carlo: u from a counter-based
// generator (SplitMix64 of the seed, the sample and the variable), the same on every platform. Latin hypercube: the
// N samples fall one in each of N equal-probability strata of every variable, u = (stratum + uniform) / N, with the
// strata of each variable in a permutation drawn from the seed. A correlated pair (e.g. c' and phi' of one soil) is
// correlated in standard-normal space: z2 <- rho z1 + sqrt(1 - rho^2) z2, then each z back through Phi to u (for
// normal variables rho is their correlation coefficient; for the others the correlation of their normal scores).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "slope/search.hpp"

namespace slope {

enum class Distribution {
  normal,      // mean, std_dev; optionally truncated to [min, max]
  lognormal,   // mean > 0, std_dev (of the variable itself); optionally truncated to [min, max], min >= 0
  uniform,     // on [min, max]
  triangular,  // on [min, max], its mode the mean value given (the deterministic value)
};

// The quantity of the section a random variable sets, in the section's SI units.
enum class RandomQuantity {
  cohesion,               // Material::cohesion, Pa
  friction_angle,         // Material::friction_angle, rad
  friction_coefficient,   // tan(phi') (Material::friction_angle = atan of it), -
  unit_weight,            // Material::unit_weight, N/m^3
  saturated_unit_weight,  // Material::saturated_unit_weight, N/m^3 (the material must have one)
  cohesion_rate,          // Material::cohesion_rate, Pa/m
  pore_pressure_ratio,    // Material::pore_pressure_ratio, -
  seismic_coefficient,    // Section::seismic_coefficient, -
  water_level,            // every point of the piezometric line raised by this (m; its deterministic value is 0)
  surcharge_pressure,     // Section::surcharges[index]: pressure, Pa (a trapezoid's end pressure in proportion)
};

struct RandomVariable {
  RandomQuantity quantity = RandomQuantity::cohesion;
  std::size_t index = 0;  // the material (or the surcharge) it belongs to
  Distribution distribution = Distribution::normal;
  double mean = 0.0;      // the deterministic value (normal, lognormal: the mean; triangular: the mode)
  double std_dev = 0.0;   // normal, lognormal
  std::optional<double> min, max;  // truncation (normal, lognormal), the range (uniform, triangular: both needed)
};

// A correlation between two variables (indices into the list of variables), in standard-normal space. A variable
// takes part in one correlation at most.
struct VariableCorrelation {
  std::size_t first = 0;
  std::size_t second = 0;
  double coefficient = 0.0;  // in [-1, 1]
};

enum class Sampling { monte_carlo, latin_hypercube };

struct SamplingPlan {
  std::vector<RandomVariable> variables;
  std::vector<VariableCorrelation> correlations;
  Sampling sampling = Sampling::monte_carlo;
  long samples = 1000;     // N, the whole analysis (also when this run computes only some of them)
  std::uint64_t seed = 1;
};

// Empty when the variable can be sampled; otherwise what is wrong with it (a standard deviation that is not > 0, a
// truncation that excludes the mean, a uniform variable without min and max, ...).
std::string variable_error(const RandomVariable& variable);

// Empty when the plan can be sampled; otherwise what is wrong (a negative standard deviation, a truncation that
// excludes the mean, a correlation outside [-1, 1], a variable in two correlations, ...), naming the variable by its
// index.
std::string plan_error(const SamplingPlan& plan);

// The values of samples [first, first + count) of the plan, sample by sample: out[(s - first) * V + v].
std::vector<double> draw_samples(const SamplingPlan& plan, long first, long count);

// The variable's value at probability u in (0, 1) of its (truncated) distribution.
double inverse_cdf(const RandomVariable& variable, double u);
// The standard normal distribution function and its inverse (over p in [1e-300, 0.5]: Phi(z(p)) = p to a relative
// 1e-14, and to the rounding of z times z^2 in the far tail).
double normal_cdf(double z);
double normal_quantile(double p);

// The section with one sample's values set (`values` in the order of plan.variables); `out` is overwritten (a
// working copy of `base`, so that a loop over samples allocates nothing).
void apply_sample(const Section& base, const std::vector<RandomVariable>& variables, const double* values,
                  Section& out);

// The surface each sample is analysed on.
struct ProbabilisticSurface {
  enum class Kind { fixed_circle, fixed_polyline, overall } kind = Kind::fixed_circle;
  Circle circle;          // fixed_circle
  SlipPolyline polyline;  // fixed_polyline
};

struct SampleOutcome {
  std::optional<double> factor_of_safety;  // empty: the method failed (no admissible surface, no convergence)
  std::optional<Circle> circle;            // overall: the sample's critical circle
};

// The factors of safety of samples [first, first + count) by `method` (OpenMP over the samples; the result does not
// depend on the number of threads); `values` from draw_samples(plan, first, count). `progress` (optional) is called
// by one thread now and then with the number of samples done so far.
std::vector<SampleOutcome> evaluate_samples(const Section& section, const SamplingPlan& plan,
                                            const ProbabilisticSurface& surface, Method method,
                                            const SearchOptions& options, const std::vector<double>& values,
                                            const std::function<void(long)>& progress = {});

// Statistics of a set of factors of safety (those of failed samples left out).
struct ConvergencePoint {
  long samples = 0;  // the first `samples` of the analysis
  double mean = 0.0;
  double std_dev = 0.0;
  double probability_of_failure = 0.0;
};

struct ProbabilisticStatistics {
  long samples = 0;        // with a factor of safety
  long failed_samples = 0; // without one
  double mean = 0.0, std_dev = 0.0, min = 0.0, max = 0.0;
  long below_one = 0;      // samples with FS < 1
  double probability_of_failure = 0.0;  // below_one / samples
  // (mean - 1) / std_dev, and ln(mean / sqrt(1 + V^2)) / sqrt(ln(1 + V^2)) with V = std_dev / mean; empty when
  // std_dev = 0 (or mean <= 0 for the lognormal one)
  std::optional<double> beta_normal, beta_lognormal;
  std::vector<ConvergencePoint> convergence;  // at about 30 sample counts from 10 to N, evenly on a log scale
};

ProbabilisticStatistics probabilistic_statistics(const std::vector<SampleOutcome>& outcomes);

}  // namespace slope
