#include "sph/mps/effective_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sph::mps {

namespace {
constexpr long max_strips = 10'000'000;  // 10 km of domain at 1 mm
}  // namespace

SurfaceStrips::SurfaceStrips(const ParticleSet& set, const std::vector<std::uint8_t>& surface,
                             double strip_half_width)
    : set_(set), half_width_(strip_half_width) {
  const std::size_t n = set.size();
  if (surface.size() != n) throw std::invalid_argument("depth_below_surface: one surface flag per particle needed");
  if (!(strip_half_width > 0)) throw std::invalid_argument("depth_below_surface: strip_half_width must be > 0 m");
  if (n == 0) return;
  x_min_ = *std::min_element(set.x.begin(), set.x.end());
  const long strip_count = strip_of(*std::max_element(set.x.begin(), set.x.end())) + 1;
  // a particle thrown far away would make a dense strip table huge: refuse rather than allocate gigabytes
  if (strip_count > max_strips) throw std::invalid_argument("depth_below_surface: the particles span too many strips");
  strips_.resize(static_cast<std::size_t>(strip_count));
  for (std::size_t j = 0; j < n; ++j)
    if (surface[j]) strips_[static_cast<std::size_t>(strip_of(set.x[j]))].push_back(j);
}

long SurfaceStrips::strip_of(double x) const { return static_cast<long>(std::floor((x - x_min_) / half_width_)); }

double SurfaceStrips::depth(std::size_t i) const {
  const long s = strip_of(set_.x[i]);
  const long last = static_cast<long>(strips_.size()) - 1;
  double top = set_.y[i];  // depth 0 unless a surface particle lies above
  for (long k = std::max(s - 1, 0L); k <= std::min(s + 1, last); ++k)
    for (const std::size_t j : strips_[static_cast<std::size_t>(k)])
      if (std::abs(set_.x[j] - set_.x[i]) < half_width_) top = std::max(top, set_.y[j]);
  return top - set_.y[i];
}

std::vector<double> depth_below_surface(const ParticleSet& set, const std::vector<std::uint8_t>& surface,
                                        double strip_half_width) {
  const SurfaceStrips strips(set, surface, strip_half_width);
  std::vector<double> depth(set.size(), 0.0);
  for (std::size_t i = 0; i < set.size(); ++i) depth[i] = strips.depth(i);
  return depth;
}

}  // namespace sph::mps
