#pragma once
// The neighbour iteration every physics uses: the particles within a radius of a particle of the same set, or of a
// point that belongs to another set (the soil -> reservoir chain: a soil particle's neighbours among the water's).
// Both sets must be sorted by their CellSortedSet with a cell size >= the radius. The callback gets the neighbour's
// index j and the separation (dx, dy) = (x_i - x_j, y_i - y_j) with r2 = dx^2 + dy^2 < radius^2.
#include <cstddef>
#include <cstdint>

#include "sph/engine/cell_sort.hpp"
#include "sph/engine/particle_set.hpp"

namespace sph {

// Every particle j != i of `set` within `radius` of its particle i.
template <class F>
void for_each_neighbour(const CellSortedSet& sorted, const ParticleSet& set, std::size_t i, double radius, F&& f) {
  const double r2_max = radius * radius, xi = set.x[i], yi = set.y[i];
  IndexRange ranges[3];
  const int n = sorted.cells().candidate_ranges(i, ranges);
  for (int k = 0; k < n; ++k)
    for (std::uint32_t j = ranges[k].begin; j < ranges[k].end; ++j) {
      if (j == i) continue;
      const double dx = xi - set.x[j], dy = yi - set.y[j], r2 = dx * dx + dy * dy;
      if (r2 < r2_max) f(std::size_t{j}, dx, dy, r2);
    }
}

// Every particle j of `other` within `radius` of the point (x, y), e.g. a particle of another set.
template <class F>
void for_each_neighbour_at(const CellSortedSet& other_sorted, const ParticleSet& other, double x, double y,
                           double radius, F&& f) {
  const double r2_max = radius * radius;
  IndexRange ranges[3];
  const int n = other_sorted.cells().candidate_ranges_at(x, y, ranges);
  for (int k = 0; k < n; ++k)
    for (std::uint32_t j = ranges[k].begin; j < ranges[k].end; ++j) {
      const double dx = x - other.x[j], dy = y - other.y[j], r2 = dx * dx + dy * dy;
      if (r2 < r2_max) f(std::size_t{j}, dx, dy, r2);
    }
}

}  // namespace sph
