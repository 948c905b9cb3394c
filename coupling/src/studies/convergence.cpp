#include "coupling/studies/convergence.hpp"

#include <cmath>

namespace coupling {

std::optional<double> observed_order(const std::vector<double>& spacings, const std::vector<double>& errors) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < spacings.size() && k < errors.size(); ++k) {
    if (!(errors[k] > 0.0) || !std::isfinite(errors[k]) || !(spacings[k] > 0.0)) continue;
    const double x = std::log(spacings[k]), y = std::log(errors[k]);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  if (n < 2) return std::nullopt;
  const double denominator = n * sxx - sx * sx;
  if (!(std::fabs(denominator) > 1e-12 * std::max(1.0, n * sxx))) return std::nullopt;
  return (n * sxy - sx * sy) / denominator;
}

std::optional<SelfConvergence> self_convergence(double h1, double f1, double h2, double f2, double h3, double f3) {
  if (!(h1 > h2 && h2 > h3 && h3 > 0.0)) return std::nullopt;
  const double d12 = f1 - f2, d23 = f2 - f3;
  if (!std::isfinite(d12) || !std::isfinite(d23) || d12 == 0.0 || d23 == 0.0 || (d12 > 0) != (d23 > 0))
    return std::nullopt;
  const double target = d12 / d23;
  // g(p) = (h1^p - h2^p)/(h2^p - h3^p) rises monotonically with p for h1 > h2 > h3.
  auto g = [&](double p) { return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p)); };
  double lo = 0.05, hi = 12.0;
  if (!(g(lo) <= target && target <= g(hi))) return std::nullopt;
  for (int it = 0; it < 200 && hi - lo > 1e-10; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < target ? lo : hi) = mid;
  }
  SelfConvergence out;
  out.order = 0.5 * (lo + hi);
  const double a2 = std::pow(h2, out.order), a3 = std::pow(h3, out.order);
  out.extrapolated = f3 + (f3 - f2) * a3 / (a2 - a3);
  return out;
}

}  // namespace coupling
