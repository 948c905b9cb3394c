#include "sph/mps/effective_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sph::mps {

namespace {
constexpr long max_strips = 10'000'000;  // 10 km of domain at 1 mm
}  // namespace

std::vector<double> depth_below_surface(const ParticleSet& set, const std::vector<std::uint8_t>& surface,
                                        double strip_half_width) {
  const std::size_t n = set.size();
  if (surface.size() != n) throw std::invalid_argument("depth_below_surface: one surface flag per particle needed");
  if (!(strip_half_width > 0)) throw std::invalid_argument("depth_below_surface: strip_half_width must be > 0 m");
  std::vector<double> depth(n, 0.0);
  if (n == 0) return depth;
  const double x_min = *std::min_element(set.x.begin(), set.x.end());
  auto strip_of = [&](double x) { return static_cast<long>(std::floor((x - x_min) / strip_half_width)); };
  const long strip_count = strip_of(*std::max_element(set.x.begin(), set.x.end())) + 1;
  // a particle thrown far away would make a dense strip table huge: refuse rather than allocate gigabytes
  if (strip_count > max_strips) throw std::invalid_argument("depth_below_surface: the particles span too many strips");
  std::vector<std::vector<std::size_t>> strips(static_cast<std::size_t>(strip_count));
  for (std::size_t j = 0; j < n; ++j)
    if (surface[j]) strips[static_cast<std::size_t>(strip_of(set.x[j]))].push_back(j);
  const long last = static_cast<long>(strips.size()) - 1;
  for (std::size_t i = 0; i < n; ++i) {
    const long s = strip_of(set.x[i]);
    double top = set.y[i];  // depth 0 unless a surface particle lies above
    for (long k = std::max(s - 1, 0L); k <= std::min(s + 1, last); ++k)
      for (const std::size_t j : strips[static_cast<std::size_t>(k)])
        if (std::abs(set.x[j] - set.x[i]) < strip_half_width) top = std::max(top, set.y[j]);
    depth[i] = top - set.y[i];
  }
  return depth;
}

}  // namespace sph::mps
