// Probabilistic limit equilibrium (slope/probabilistic.hpp): the distributions, the sampling plans and a planar
// sliding block whose factor of safety is linear in c' and tan(phi'), so that its distribution is known in closed form.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "slope/probabilistic.hpp"

namespace test_lem_probabilistic {

namespace {

using slope::Distribution;
using slope::RandomQuantity;
using slope::RandomVariable;

RandomVariable variable(Distribution d, double mean, double std_dev, std::optional<double> min = {},
                        std::optional<double> max = {}) {
  RandomVariable v;
  v.distribution = d;
  v.mean = mean;
  v.std_dev = std_dev;
  v.min = min;
  v.max = max;
  return v;
}

struct Moments {
  double mean = 0.0, std_dev = 0.0;
};

Moments moments(const std::vector<double>& x, std::size_t stride, std::size_t offset) {
  Moments m;
  const std::size_t n = x.size() / stride;
  for (std::size_t i = 0; i < n; ++i) m.mean += x[i * stride + offset];
  m.mean /= static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) m.std_dev += std::pow(x[i * stride + offset] - m.mean, 2);
  m.std_dev = std::sqrt(m.std_dev / static_cast<double>(n - 1));
  return m;
}

double standard_density(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * 3.14159265358979323846); }

}  // namespace

TEST_CASE("probabilistic: the standard normal quantile inverts the distribution function to its precision",
          "[slope][probabilistic]") {
  // Published values (e.g. Abramowitz & Stegun 26.2): z(0.975) = 1.959963984540054, z(0.001) = -3.090232306167813.
  CHECK(slope::normal_quantile(0.975) == Approx(1.959963984540054).epsilon(1e-15));
  CHECK(slope::normal_quantile(0.001) == Approx(-3.090232306167813).epsilon(1e-15));
  CHECK(slope::normal_quantile(0.5) == 0.0);
  double worst = 0.0;
  for (double e = -300.0; e <= -0.31; e += 0.37) {
    const double p = std::pow(10.0, e);
    // Phi's relative change over one unit in the last place of z is about z^2 times that unit: the round trip is
    // held to that conditioning
    const double z = slope::normal_quantile(p);
    worst = std::max(worst, std::fabs(slope::normal_cdf(z) - p) / p / std::max(1.0, z * z));
    // the upper tail: 1 - Phi(z(1 - p)) = p to the precision 1 - p is held in
    if (p > 1e-15) {
      const double q = 1.0 - p;
      CHECK(std::fabs(slope::normal_cdf(-slope::normal_quantile(q)) - (1.0 - q)) <= 4e-16);
    }
  }
  CHECK(worst < 2e-15);
}

TEST_CASE("probabilistic: each distribution's samples have its mean and standard deviation",
          "[slope][probabilistic]") {
  slope::SamplingPlan plan;
  plan.sampling = slope::Sampling::latin_hypercube;
  plan.samples = 20000;
  plan.seed = 7;
  // normal 30 +- 3; lognormal of mean 18, sd 3.6; normal 10 +- 2 truncated to [9, 14]; uniform [2, 6];
  // triangular [1, 7] with mode 2
  plan.variables = {variable(Distribution::normal, 30.0, 3.0), variable(Distribution::lognormal, 18.0, 3.6),
                    variable(Distribution::normal, 10.0, 2.0, 9.0, 14.0), variable(Distribution::uniform, 4.0, 0.0, 2.0, 6.0),
                    variable(Distribution::triangular, 2.0, 0.0, 1.0, 7.0)};
  REQUIRE(slope::plan_error(plan).empty());
  const std::vector<double> x = slope::draw_samples(plan, 0, plan.samples);
  const std::size_t nv = plan.variables.size();
  // Truncated normal (a, b in standard scores): mean mu + sd (pdf(a) - pdf(b)) / Z,
  // variance sd^2 [1 + (a pdf(a) - b pdf(b)) / Z - ((pdf(a) - pdf(b)) / Z)^2].
  const double a = -0.5, b = 2.0, Z = slope::normal_cdf(b) - slope::normal_cdf(a);
  const double shift = (standard_density(a) - standard_density(b)) / Z;
  const double truncated_sd = 2.0 * std::sqrt(1.0 + (a * standard_density(a) - b * standard_density(b)) / Z - shift * shift);
  const double expected_mean[] = {30.0, 18.0, 10.0 + 2.0 * shift, 4.0, (1.0 + 7.0 + 2.0) / 3.0};
  const double expected_sd[] = {3.0, 3.6, truncated_sd, 4.0 / std::sqrt(12.0),
                                std::sqrt((1.0 + 49.0 + 4.0 - 7.0 - 2.0 - 14.0) / 18.0)};
  for (std::size_t v = 0; v < nv; ++v) {
    INFO("variable " << v);
    const Moments m = moments(x, nv, v);
    CHECK(m.mean == Approx(expected_mean[v]).epsilon(2e-3));
    CHECK(m.std_dev == Approx(expected_sd[v]).epsilon(1e-2));
  }
  for (std::size_t i = 0; i < x.size(); i += nv) {
    REQUIRE(x[i + 2] >= 9.0);
    REQUIRE(x[i + 2] <= 14.0);
    REQUIRE(x[i + 1] > 0.0);
  }
}

TEST_CASE("probabilistic: a Latin hypercube puts one sample in each stratum of every variable",
          "[slope][probabilistic]") {
  slope::SamplingPlan plan;
  plan.sampling = slope::Sampling::latin_hypercube;
  plan.samples = 500;
  plan.variables = {variable(Distribution::uniform, 0.5, 0.0, 0.0, 1.0), variable(Distribution::uniform, 0.5, 0.0, 0.0, 1.0)};
  const std::vector<double> x = slope::draw_samples(plan, 0, plan.samples);
  for (std::size_t v = 0; v < 2; ++v) {
    std::vector<int> hits(500, 0);
    for (long s = 0; s < 500; ++s) ++hits[static_cast<std::size_t>(std::floor(x[static_cast<std::size_t>(s) * 2 + v] * 500))];
    CHECK(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }));
  }
  // Monte Carlo does not stratify: some stratum is empty (with 500 samples, all filled has probability ~1e-215).
  plan.sampling = slope::Sampling::monte_carlo;
  const std::vector<double> y = slope::draw_samples(plan, 0, plan.samples);
  std::vector<int> hits(500, 0);
  for (long s = 0; s < 500; ++s) ++hits[static_cast<std::size_t>(std::floor(y[static_cast<std::size_t>(s) * 2] * 500))];
  CHECK(std::count(hits.begin(), hits.end(), 0) > 100);
}

TEST_CASE("probabilistic: samples drawn in parts are those drawn at once, bit for bit, and another seed draws others",
          "[slope][probabilistic]") {
  for (slope::Sampling sampling : {slope::Sampling::monte_carlo, slope::Sampling::latin_hypercube}) {
    slope::SamplingPlan plan;
    plan.sampling = sampling;
    plan.samples = 1000;
    plan.seed = 42;
    plan.variables = {variable(Distribution::normal, 18.0, 3.6), variable(Distribution::normal, 30.0, 3.0),
                      variable(Distribution::lognormal, 18.0, 0.9)};
    plan.correlations = {{0, 1, -0.5}};
    const std::vector<double> whole = slope::draw_samples(plan, 0, 1000);
    std::vector<double> parts;
    for (long first : {0L, 333L, 334L, 900L}) {
      const long count = first == 0 ? 333 : first == 333 ? 1 : first == 334 ? 566 : 100;
      const std::vector<double> part = slope::draw_samples(plan, first, count);
      parts.insert(parts.end(), part.begin(), part.end());
    }
    CHECK(parts == whole);
    plan.seed = 43;
    CHECK(slope::draw_samples(plan, 0, 1000) != whole);
  }
}

TEST_CASE("probabilistic: a correlation of two normal variables is their correlation coefficient",
          "[slope][probabilistic]") {
  for (double rho : {-0.7, 0.0, 0.5}) {
    slope::SamplingPlan plan;
    plan.samples = 20000;
    plan.variables = {variable(Distribution::normal, 18.0, 3.6), variable(Distribution::normal, 30.0, 3.0)};
    plan.correlations = {{0, 1, rho}};
    const std::vector<double> x = slope::draw_samples(plan, 0, plan.samples);
    const Moments c = moments(x, 2, 0), f = moments(x, 2, 1);
    double cov = 0.0;
    for (long s = 0; s < plan.samples; ++s) cov += (x[2 * s] - c.mean) * (x[2 * s + 1] - f.mean);
    cov /= static_cast<double>(plan.samples - 1);
    // the sample correlation's standard error is (1 - rho^2) / sqrt(N) <= 0.007
    CHECK(cov / (c.std_dev * f.std_dev) == Approx(rho).margin(0.025));
    CHECK(f.std_dev == Approx(3.0).epsilon(0.03));
  }
}

TEST_CASE("probabilistic: a plan that cannot be sampled is refused with the variable named", "[slope][probabilistic]") {
  slope::SamplingPlan plan;
  plan.variables = {variable(Distribution::normal, 18.0, -1.0)};
  CHECK(slope::plan_error(plan).find("variable 0: its standard deviation must be > 0") != std::string::npos);
  plan.variables = {variable(Distribution::normal, 18.0, 3.6, 20.0)};
  CHECK(slope::plan_error(plan).find("exclude") != std::string::npos);
  plan.variables = {variable(Distribution::normal, 18.0, 3.6, std::nullopt, 10.0)};
  CHECK(slope::plan_error(plan).find("exclude") != std::string::npos);
  plan.variables = {variable(Distribution::lognormal, 0.0, 1.0)};
  CHECK(slope::plan_error(plan).find("mean must be > 0") != std::string::npos);
  plan.variables = {variable(Distribution::uniform, 18.0, 0.0, 20.0, 30.0)};
  CHECK(slope::plan_error(plan).find("[min, max]") != std::string::npos);
  plan.variables = {variable(Distribution::triangular, 18.0, 0.0, 10.0)};
  CHECK(slope::plan_error(plan).find("needs min and max") != std::string::npos);
  plan.variables = {variable(Distribution::normal, 18.0, 3.6), variable(Distribution::normal, 30.0, 3.0)};
  plan.correlations = {{0, 1, 1.5}};
  CHECK(slope::plan_error(plan).find("correlation 0: its coefficient must be in [-1, 1]") != std::string::npos);
  plan.correlations = {{0, 1, 0.5}, {1, 0, 0.2}};
  CHECK(slope::plan_error(plan).find("one correlation only") != std::string::npos);
  plan.correlations = {{0, 1, -1.0}};
  CHECK(slope::plan_error(plan).empty());
}

namespace {

// A planar block: ground (0, 10)-(20, 10)-(30, 0)-(50, 0) (a 45-degree face 10 m high), the plane from (10, 10) on
// the crest to the toe (30, 0), alpha = atan(1/2). The block is the triangle (10,10)-(20,10)-(30,0): 50 m^2, W = 50
// gamma; the plane's length L = sqrt(500) m. For every slice the base angle is alpha, and Janbu's simplified method
// is then the block's equilibrium along the plane: F = c L / (W sin alpha) + tan(phi) / tan(alpha), linear in c and
// tan(phi). With c and tan(phi) normal, F is normal: mean a mu_c + b mu_t, variance a^2 s_c^2 + b^2 s_t^2 +
// 2 rho a b s_c s_t, and P(F < 1) = Phi((1 - mean) / sd).
slope::Section block_section(double unit_weight) {
  slope::Section s;
  s.bottom_y = -5.0;
  slope::Material m;
  m.name = "soil";
  m.unit_weight = unit_weight;
  m.cohesion = 10e3;
  m.friction_angle = std::atan(0.4);
  s.materials = {m};
  s.profile_lines = {{0, {{0.0, 10.0}, {20.0, 10.0}, {30.0, 0.0}, {50.0, 0.0}}}};
  return s;
}

}  // namespace

TEST_CASE("probabilistic: a planar block with normal c' and tan(phi') has the closed-form mean, spread, probability "
          "of failure and reliability index",
          "[slope][probabilistic][closed_form]") {
  const double gamma = 20e3, W = 50.0 * gamma, L = std::sqrt(500.0), alpha = std::atan(0.5);
  const double a = L / (W * std::sin(alpha)), b = 1.0 / std::tan(alpha);  // per Pa, per unit of tan(phi)
  const slope::Section section = block_section(gamma);
  slope::ProbabilisticSurface surface;
  surface.kind = slope::ProbabilisticSurface::Kind::fixed_polyline;
  surface.polyline.points = {{10.0, 10.0}, {30.0, 0.0}};
  slope::SearchOptions options;
  for (double rho : {0.0, 0.5}) {
    INFO("rho = " << rho);
    slope::SamplingPlan plan;
    plan.sampling = slope::Sampling::latin_hypercube;
    plan.samples = 20000;
    plan.seed = 3;
    RandomVariable c = variable(Distribution::normal, 10e3, 2e3), t = variable(Distribution::normal, 0.4, 0.05);
    c.quantity = RandomQuantity::cohesion;
    t.quantity = RandomQuantity::friction_coefficient;
    plan.variables = {c, t};
    plan.correlations = {{0, 1, rho}};
    const std::vector<double> values = slope::draw_samples(plan, 0, plan.samples);
    const auto outcomes =
        slope::evaluate_samples(section, plan, surface, slope::Method::janbu, options, values);
    const slope::ProbabilisticStatistics stats = slope::probabilistic_statistics(outcomes);
    const double mean = a * 10e3 + b * 0.4;  // 1.3
    const double sd = std::sqrt(std::pow(a * 2e3, 2) + std::pow(b * 0.05, 2) + 2.0 * rho * a * b * 2e3 * 0.05);
    const double beta = (mean - 1.0) / sd, pf = slope::normal_cdf(-beta);
    REQUIRE(stats.samples == plan.samples);
    CHECK(stats.failed_samples == 0);
    // each sample on the closed form (the slicing is exact for a polygon)
    for (long s = 0; s < 50; ++s)
      CHECK(*outcomes[s].factor_of_safety ==
            Approx(a * values[2 * s] + b * values[2 * s + 1]).epsilon(1e-9));
    CHECK(stats.mean == Approx(mean).epsilon(1e-3));
    CHECK(stats.std_dev == Approx(sd).epsilon(0.02));
    CHECK(*stats.beta_normal == Approx(beta).epsilon(0.03));
    // binomial standard error of the fraction below 1: sqrt(pf (1 - pf) / N), about 1e-3 here
    CHECK(stats.probability_of_failure == Approx(pf).margin(4.0 * std::sqrt(pf * (1.0 - pf) / plan.samples)));
    REQUIRE(!stats.convergence.empty());
    CHECK(stats.convergence.back().samples == plan.samples);
    CHECK(stats.convergence.back().probability_of_failure == stats.probability_of_failure);
  }
}

}  // namespace test_lem_probabilistic
