#include "pair_list.hpp"

#include <cmath>

namespace sph::fluid {

namespace {
using Index = std::int64_t;
}  // namespace

void PairList::build(const ParticleSet& p, const CellList& cells, const CubicSplineKernel& kernel) {
  const std::size_t n = p.size();
  const Index nn = static_cast<Index>(n);
  const double support2 = kernel.support() * kernel.support();
  const double* x = p.x.data();
  const double* y = p.y.data();
  start.assign(n + 1, 0);
  // pass 1: count the neighbours of every particle
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < nn; ++k) {
    const auto i = static_cast<std::size_t>(k);
    std::uint32_t c = 0;
    cells.for_each_candidate(i, [&](std::uint32_t jj) {
      const double ddx = x[i] - x[jj], ddy = y[i] - y[jj];
      if (jj != i && ddx * ddx + ddy * ddy < support2) ++c;
    });
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
    cells.for_each_candidate(i, [&](std::uint32_t jj) {
      const double ddx = x[i] - x[jj], ddy = y[i] - y[jj];
      const double rr = ddx * ddx + ddy * ddy;
      if (jj == i || rr >= support2) return;
      const double r = std::sqrt(rr);
      j[at] = jj;
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
