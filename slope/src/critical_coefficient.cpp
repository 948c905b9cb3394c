// The critical seismic coefficient k_c (search.hpp): the k_h at which the circular search's least factor of safety
// is 1.
#include <chrono>
#include <cmath>

#include "slope/search.hpp"

namespace slope {

namespace {

constexpr double largest_coefficient = 0.99;
constexpr double coefficient_tolerance = 1e-4;

struct Trial {
  double k = 0.0;
  double excess = 0.0;  // FS_min - 1
  std::optional<CriticalSurface> surface;
};

}  // namespace

CriticalCoefficient critical_seismic_coefficient(const Section& section, Method method, const SearchOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  CriticalCoefficient out;
  Section shaken = section;
  bool failed = false;
  auto at = [&](double k) {
    shaken.seismic_coefficient = k;
    const SearchResult r = search_critical(shaken, {method}, options);
    ++out.searches;
    Trial t{k, 0.0, std::nullopt};
    if (r.methods.empty() || !r.methods.front().result.factor_of_safety) {
      failed = true;
      out.why = "the search found no surface at k_h = " + std::to_string(k) + ": " +
                (r.methods.empty() ? r.error : r.methods.front().result.error);
      return t;
    }
    t.excess = *r.methods.front().result.factor_of_safety - 1.0;
    t.surface = r.methods.front();
    return t;
  };
  auto finish = [&]() {
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return out;
  };
  Trial lo = at(0.0);
  if (failed) return finish();
  out.factor_of_safety_without = lo.excess + 1.0;
  if (lo.excess <= 0.0) {
    out.why = "the least factor of safety is at most 1 without any seismic coefficient";
    return finish();
  }
  // Bracket: k_h = 0.1, doubling (then 0.99) until FS_min < 1.
  Trial hi{0.0, 0.0, std::nullopt};
  for (double k = 0.1;; k = std::min(2.0 * k, largest_coefficient)) {
    hi = at(k);
    if (failed) return finish();
    if (hi.excess <= 0.0) break;
    lo = hi;
    if (k >= largest_coefficient) {
      out.why = "the least factor of safety stays above 1 up to k_h = 0.99";
      return finish();
    }
  }
  // Illinois false position on [lo, hi]: lo.excess > 0 >= hi.excess.
  int side = 0;
  while (hi.k - lo.k > coefficient_tolerance && out.searches < 60) {
    const double k = hi.k - hi.excess * (hi.k - lo.k) / (hi.excess - lo.excess);
    Trial mid = at(std::isfinite(k) && k > lo.k && k < hi.k ? k : 0.5 * (lo.k + hi.k));
    if (failed) return finish();
    if (mid.excess > 0.0) {
      lo = std::move(mid);
      if (side == -1) hi.excess *= 0.5;
      side = -1;
    } else {
      hi = std::move(mid);
      if (side == 1) lo.excess *= 0.5;
      side = 1;
    }
  }
  // The end nearer FS = 1 (both within the tolerance in k_h).
  Trial& best = std::fabs(lo.surface->result.factor_of_safety.value_or(1e9) - 1.0) <
                        std::fabs(hi.surface->result.factor_of_safety.value_or(1e9) - 1.0)
                    ? lo
                    : hi;
  out.coefficient = best.k;
  out.surface = std::move(best.surface);
  return finish();
}

}  // namespace slope
