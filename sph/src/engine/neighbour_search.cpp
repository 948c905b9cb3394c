#include "sph/engine/neighbour_search.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sph {

void CellList::build(const double* x, const double* y, std::size_t n, double cell_size) {
  if (!(cell_size > 0)) throw std::invalid_argument("CellList: cell_size must be > 0");
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  if (n > 0) {
    xmin = xmax = x[0];
    ymin = ymax = y[0];
  }
  // min/max are exact in any order, so the parallel reduction is deterministic.
  const std::int64_t nn = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) reduction(min : xmin, ymin) reduction(max : xmax, ymax)
  for (std::int64_t i = 0; i < nn; ++i) {
    xmin = std::min(xmin, x[i]);
    xmax = std::max(xmax, x[i]);
    ymin = std::min(ymin, y[i]);
    ymax = std::max(ymax, y[i]);
  }
  if (!std::isfinite(xmin) || !std::isfinite(xmax) || !std::isfinite(ymin) || !std::isfinite(ymax))
    throw std::runtime_error("CellList: non-finite particle position");
  x_min_ = xmin;
  y_min_ = ymin;
  inv_cell_ = 1.0 / cell_size;
  nx_ = static_cast<std::int64_t>((xmax - xmin) * inv_cell_) + 1;
  ny_ = static_cast<std::int64_t>((ymax - ymin) * inv_cell_) + 1;
  const std::int64_t ncells = nx_ * ny_;
  if (ncells > (std::int64_t{1} << 28))
    throw std::runtime_error("CellList: particles spread over " + std::to_string(ncells) +
                             " cells (domain exploded?)");
  cell_of_.resize(n);
  sorted_cell_.resize(n);
  order_.resize(n);
  cell_start_.assign(static_cast<std::size_t>(ncells) + 1, 0u);

#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < nn; ++i) {
    auto cx = static_cast<std::int64_t>((x[i] - x_min_) * inv_cell_);
    auto cy = static_cast<std::int64_t>((y[i] - y_min_) * inv_cell_);
    cx = std::clamp<std::int64_t>(cx, 0, nx_ - 1);
    cy = std::clamp<std::int64_t>(cy, 0, ny_ - 1);
    cell_of_[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(cy * nx_ + cx);
  }
  // Stable counting sort (serial: O(N), deterministic).
  for (std::size_t i = 0; i < n; ++i) ++cell_start_[cell_of_[i] + 1];
  for (std::size_t c = 0; c < static_cast<std::size_t>(ncells); ++c) cell_start_[c + 1] += cell_start_[c];
  // use sorted_cell_ temporarily as the running insertion cursor per cell is not possible (size n);
  // walk particles in order and place them: cursor = copy of cell_start_.
  {
    // cell_start_ is restored afterwards by shifting.
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t c = cell_of_[i];
      const std::uint32_t k = cell_start_[c]++;
      order_[k] = static_cast<std::uint32_t>(i);
      sorted_cell_[k] = c;
    }
    for (std::size_t c = static_cast<std::size_t>(ncells); c > 0; --c) cell_start_[c] = cell_start_[c - 1];
    cell_start_[0] = 0;
  }
}

std::size_t CellList::memory_bytes() const {
  return (cell_of_.capacity() + sorted_cell_.capacity() + cell_start_.capacity() + order_.capacity()) *
         sizeof(std::uint32_t);
}

std::size_t CellList::estimate_bytes(std::size_t n) {
  // 3 per-particle arrays plus at most ~4 cells per particle for a spread-out domain.
  return n * 3 * sizeof(std::uint32_t) + (4 * n + 16) * sizeof(std::uint32_t);
}

std::vector<std::uint32_t> brute_force_neighbours(const double* x, const double* y, std::size_t n, std::size_t i,
                                                  double radius) {
  std::vector<std::uint32_t> out;
  for (std::size_t j = 0; j < n; ++j) {
    if (j == i) continue;
    const double dx = x[i] - x[j], dy = y[i] - y[j];
    if (dx * dx + dy * dy < radius * radius) out.push_back(static_cast<std::uint32_t>(j));
  }
  return out;
}

}  // namespace sph
