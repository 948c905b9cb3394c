#pragma once
// Orders of convergence from runs at several resolutions (pure functions, unit-tested).
#include <optional>
#include <vector>

namespace coupling {

// Observed order p of error ~ C h^p: the least-squares slope of log(error) against log(h) over the runs with a
// positive, finite error. Empty with fewer than two such runs or a single distinct h.
std::optional<double> observed_order(const std::vector<double>& spacings, const std::vector<double>& errors);

// Self-convergence (no reference needed): the order p of f(h) = f* + C h^p from three runs h1 > h2 > h3, the
// root of (f1 - f2) / (f2 - f3) = (h1^p - h2^p) / (h2^p - h3^p) for p in (0.05, 12). Empty when the differences
// change sign (non-monotone: not in the asymptotic range) or vanish, or no root lies in that interval.
struct SelfConvergence {
  double order = 0.0;
  double extrapolated = 0.0;  // Richardson: f3 + (f3 - f2) h3^p / (h2^p - h3^p)
};
std::optional<SelfConvergence> self_convergence(double h1, double f1, double h2, double f2, double h3, double f3);

}  // namespace coupling
