#pragma once
// Cell-list neighbour search with particles sorted by cell (row-major), rebuilt every step.
//
// build() bins the points into square cells of side `cell_size` (>= the kernel support) over their
// bounding box and computes a *stable* counting-sort permutation. The caller reorders its particle
// arrays with order() (new position k holds old particle order()[k]); afterwards the neighbours of a
// sorted particle i lie in three contiguous index ranges (the rows cy-1, cy, cy+1, columns cx-1..cx+1).
// Work arrays grow geometrically and are reused, so a steady run does not allocate.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sph {

struct IndexRange {
  std::uint32_t begin = 0, end = 0;
};

class CellList {
 public:
  void build(const double* x, const double* y, std::size_t n, double cell_size);

  // old index of the particle that goes to sorted position k
  const std::vector<std::uint32_t>& order() const { return order_; }

  // The (at most 3) contiguous ranges of sorted indices that can hold neighbours of sorted particle i.
  int candidate_ranges(std::size_t i, IndexRange out[3]) const {
    const std::int64_t c = sorted_cell_[i];
    const std::int64_t cy = c / nx_, cx = c - cy * nx_;
    const std::int64_t x_lo = cx > 0 ? cx - 1 : 0, x_hi = cx + 1 < nx_ ? cx + 1 : nx_ - 1;
    int k = 0;
    for (std::int64_t yy = (cy > 0 ? cy - 1 : 0); yy <= (cy + 1 < ny_ ? cy + 1 : ny_ - 1); ++yy) {
      out[k].begin = cell_start_[static_cast<std::size_t>(yy * nx_ + x_lo)];
      out[k].end = cell_start_[static_cast<std::size_t>(yy * nx_ + x_hi + 1)];
      ++k;
    }
    return k;
  }

  // Calls f(j) for every sorted particle j (including i itself) in the 3x3 cells around sorted particle i.
  template <class F>
  void for_each_candidate(std::size_t i, F&& f) const {
    IndexRange r[3];
    const int nr = candidate_ranges(i, r);
    for (int k = 0; k < nr; ++k)
      for (std::uint32_t j = r[k].begin; j < r[k].end; ++j) f(j);
  }

  // The (at most 3) ranges of sorted indices of this list that can hold neighbours of the point (x, y), which need
  // not belong to the list (a particle of another set: soil next to water). None when the point lies more than one
  // cell outside the list's grid.
  int candidate_ranges_at(double x, double y, IndexRange out[3]) const {
    const double fx = std::floor((x - x_min_) * inv_cell_), fy = std::floor((y - y_min_) * inv_cell_);
    if (!(fx >= -1.0 && fx <= static_cast<double>(nx_) && fy >= -1.0 && fy <= static_cast<double>(ny_))) return 0;
    const auto cx = static_cast<std::int64_t>(fx), cy = static_cast<std::int64_t>(fy);
    const std::int64_t x_lo = cx > 0 ? cx - 1 : 0, x_hi = cx + 1 < nx_ ? cx + 1 : nx_ - 1;
    const std::int64_t y_lo = cy > 0 ? cy - 1 : 0, y_hi = cy + 1 < ny_ ? cy + 1 : ny_ - 1;
    if (x_lo > x_hi) return 0;
    int k = 0;
    for (std::int64_t yy = y_lo; yy <= y_hi; ++yy) {
      out[k].begin = cell_start_[static_cast<std::size_t>(yy * nx_ + x_lo)];
      out[k].end = cell_start_[static_cast<std::size_t>(yy * nx_ + x_hi + 1)];
      ++k;
    }
    return k;
  }

  std::int64_t cells_x() const { return nx_; }
  std::int64_t cells_y() const { return ny_; }
  std::size_t memory_bytes() const;

  // Bytes used by the search for n particles (upper estimate for memory checks).
  static std::size_t estimate_bytes(std::size_t n);

 private:
  double x_min_ = 0, y_min_ = 0, inv_cell_ = 1;
  std::int64_t nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> cell_of_;      // cell of old particle i
  std::vector<std::uint32_t> sorted_cell_;  // cell of sorted particle k
  std::vector<std::uint32_t> cell_start_;   // size ncells + 1
  std::vector<std::uint32_t> order_;
};

// Reference O(N^2) search, for tests only: indices j with |x_j - x_i| < radius (j != i), ascending.
std::vector<std::uint32_t> brute_force_neighbours(const double* x, const double* y, std::size_t n, std::size_t i,
                                                  double radius);

}  // namespace sph
