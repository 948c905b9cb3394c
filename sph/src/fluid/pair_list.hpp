#pragma once
// The neighbour pairs of every particle of a cell-sorted set at its current positions, with the pair geometry the
// ISPH equations need (x_ij, r^2, F = W'(r)/r, W). Built twice per step: at r^n (viscous step) and at r*
// (density, free surface, pressure, correction). Self pairs are not listed.
#include <cstdint>
#include <vector>

#include "sph/engine/kernel.hpp"
#include "sph/engine/neighbour_search.hpp"
#include "sph/engine/particle_set.hpp"

namespace sph::fluid {

struct PairList {
  std::vector<std::uint32_t> start;  // pairs of particle i: [start[i], start[i+1])
  std::vector<std::uint32_t> j;
  std::vector<double> dx, dy, r2, F, W;

  void build(const ParticleSet& particles, const CellList& cells, const CubicSplineKernel& kernel);
  std::size_t pair_count() const { return j.size(); }
};

}  // namespace sph::fluid
