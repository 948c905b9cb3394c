#include "pair_list.hpp"

#include <cmath>

#include "sph/engine/neighbours.hpp"

namespace sph::fluid {

namespace {
using Index = std::int64_t;

// start[i + 1] holds particle i's count on entry; the running sums on exit.
void running_sums(std::vector<std::uint32_t>& start) {
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
}
}  // namespace

void CandidateList::list(const ParticleSet& p, const CellSortedSet& sorted, double r) {
  const Index n = static_cast<Index>(p.size());
  radius = r;
  start.assign(p.size() + 1, 0);
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    std::uint32_t c = 0;
    for_each_neighbour(sorted, p, i, r, [&](std::size_t, double, double, double) { ++c; });
    start[i + 1] = c;
  }
  running_sums(start);
  j.resize(start.back());
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    std::uint32_t at = start[i];
    for_each_neighbour(sorted, p, i, r, [&](std::size_t jj, double, double, double) {
      j[at++] = static_cast<std::uint32_t>(jj);
    });
  }
}

void PairList::build(const ParticleSet& p, const CandidateList& c, const FluidKernel& kernel) {
  const std::size_t n = p.size();
  const Index nn = static_cast<Index>(n);
  const double support = kernel.support(), r2_max = support * support;
  const double* x = p.x.data();
  const double* y = p.y.data();
  start.assign(n + 1, 0);
  // pass 1: count the candidates within the support
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < nn; ++k) {
    const auto i = static_cast<std::size_t>(k);
    std::uint32_t count = 0;
    for (std::uint32_t q = c.start[i]; q < c.start[i + 1]; ++q) {
      const double ddx = x[i] - x[c.j[q]], ddy = y[i] - y[c.j[q]];
      count += ddx * ddx + ddy * ddy < r2_max;
    }
    start[i + 1] = count;
  }
  running_sums(start);
  const std::size_t total = start[n];
  j.resize(total);
  dx.resize(total);
  dy.resize(total);
  r2.resize(total);
  F.resize(total);
  W.resize(total);
  // pass 2: fill, in the candidates' order (the same order for any thread count)
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < nn; ++k) {
    const auto i = static_cast<std::size_t>(k);
    std::size_t at = start[i];
    for (std::uint32_t q = c.start[i]; q < c.start[i + 1]; ++q) {
      const std::uint32_t jj = c.j[q];
      const double ddx = x[i] - x[jj], ddy = y[i] - y[jj], rr = ddx * ddx + ddy * ddy;
      if (!(rr < r2_max)) continue;
      const double r = std::sqrt(rr);
      j[at] = jj;
      dx[at] = ddx;
      dy[at] = ddy;
      r2[at] = rr;
      F[at] = kernel.gradient_factor(r);
      W[at] = kernel.value(r);
      ++at;
    }
  }
}

}  // namespace sph::fluid
