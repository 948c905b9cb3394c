#include "pair_list.hpp"

#include <cmath>

#include "sph/engine/neighbours.hpp"

namespace sph::fluid {

namespace {
using Index = std::int64_t;
}  // namespace

void PairList::build(const ParticleSet& p, const CellSortedSet& sorted, const FluidKernel& kernel) {
  const std::size_t n = p.size();
  const Index nn = static_cast<Index>(n);
  const double support = kernel.support();
  start.assign(n + 1, 0);
  // pass 1: count the neighbours of every particle
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < nn; ++k) {
    const auto i = static_cast<std::size_t>(k);
    std::uint32_t c = 0;
    for_each_neighbour(sorted, p, i, support, [&](std::size_t, double, double, double) { ++c; });
    start[i + 1] = c;
  }
  for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  const std::size_t total = start[n];
  j.resize(total);
  dx.resize(total);
  dy.resize(total);
  r2.resize(total);
  F.resize(total);
  W.resize(total);
  // pass 2: fill, in the cell order (the same order for any thread count)
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < nn; ++k) {
    const auto i = static_cast<std::size_t>(k);
    std::size_t at = start[i];
    for_each_neighbour(sorted, p, i, support, [&](std::size_t jj, double ddx, double ddy, double rr) {
      const double r = std::sqrt(rr);
      j[at] = static_cast<std::uint32_t>(jj);
      dx[at] = ddx;
      dy[at] = ddy;
      r2[at] = rr;
      F[at] = kernel.gradient_factor(r);
      W[at] = kernel.value(r);
      ++at;
    });
  }
}

}  // namespace sph::fluid
