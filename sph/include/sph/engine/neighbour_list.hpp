#pragma once
// The neighbours of every particle of a set within a radius, gathered once and read by the passes that follow,
// with one value per pair computed at the gathering (e.g. the kernel weight of the pair's distance). Gathered from
// the cells after a sort (build), each particle's list holds its neighbours j != i in the order for_each_neighbour
// visits them, so a sum over the list equals the sum over the cells bit for bit; a pass over a list reads the ~50
// neighbours of a particle and their stored values instead of testing the ~144 candidates of its 3 x 3 cells.
// Gathered from a wider list (build_from: candidates within radius + a skin, listed at earlier positions), the
// list keeps the candidates' order and needs no sort while no particle has moved half the skin.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/engine/cell_sort.hpp"
#include "sph/engine/neighbours.hpp"
#include "sph/engine/particle_set.hpp"

namespace sph {

class NeighbourList {
 public:
  // with_values false: the list keeps the indices only (a list of candidates, see build_from).
  explicit NeighbourList(bool with_values = true) : with_values_(with_values) {}

  // Every pair of `set` closer than `radius` (the set sorted by `sorted`, cells of side >= radius), with the value
  // pair_value(r2) of each pair (r2 its squared distance [m^2]). One OpenMP pass over the candidates; a second one
  // only when a particle has more neighbours than the room per particle (which then grows and stays).
  template <class PairValue>
  void build(const CellSortedSet& sorted, const ParticleSet& set, double radius, PairValue&& pair_value) {
    fill(set.size(), radius, pair_value, [&](std::size_t i, auto&& emit) {
      for_each_neighbour(sorted, set, i, radius, [&](std::size_t j, double, double, double r2) { emit(j, r2); });
    });
  }

  // The pairs of `wider` (a list of a larger radius, built at earlier positions of the same set in the same order)
  // that lie closer than `radius` at the set's current positions, in the wider list's order, with pair_value(r2).
  // Complete while no particle has moved more than half the difference of the two radii since `wider` was built.
  // With value_sums, value_sums[i] = the sum of particle i's pair values added in list order from 0 (e.g. the MPS
  // number density, summed while the values are in cache).
  template <class PairValue>
  void build_from(const NeighbourList& wider, const ParticleSet& set, double radius, PairValue&& pair_value,
                  double* value_sums = nullptr);

  double radius() const { return radius_; }
  std::size_t particles() const { return count_.size(); }
  std::size_t count(std::size_t i) const { return count_[i]; }
  const std::uint32_t* neighbours(std::size_t i) const { return j_.data() + i * stride_; }
  const double* values(std::size_t i) const { return value_.data() + i * stride_; }
  std::size_t memory_bytes() const {
    return (j_.capacity() + count_.capacity()) * sizeof(std::uint32_t) + value_.capacity() * sizeof(double);
  }

 private:
  static constexpr std::size_t initial_stride = 64;  // radius 4 dx on a square lattice: 48 neighbours
  static constexpr std::size_t stride_margin = 16;

  // candidates(i, emit) calls emit(j, r2) for every neighbour j of particle i within `radius`, in list order.
  template <class PairValue, class Candidates>
  void fill(std::size_t n, double radius, PairValue& pair_value, Candidates&& candidates) {
    radius_ = radius;
    if (stride_ == 0) stride_ = initial_stride;
    count_.resize(n);
    for (;;) {
      j_.resize(n * stride_);
      value_.resize(with_values_ ? n * stride_ : 0);
      const std::size_t most = gather(n, pair_value, candidates);
      if (most <= stride_) return;
      stride_ = most + stride_margin;
    }
  }

  // Fills the lists that fit; returns the largest neighbour count.
  template <class PairValue, class Candidates>
  std::size_t gather(std::size_t particles, PairValue& pair_value, Candidates& candidates) {
    const auto n = static_cast<std::int64_t>(particles);
    const std::size_t room = stride_;
    const bool values = with_values_;
    std::size_t most = 0;
#pragma omp parallel for schedule(static) reduction(max : most)
    for (std::int64_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(k);
      std::uint32_t* out = j_.data() + i * room;
      double* value = values ? value_.data() + i * room : nullptr;
      std::size_t c = 0;
      candidates(i, [&](std::size_t j, double r2) {
        if (c < room) {
          out[c] = static_cast<std::uint32_t>(j);
          if (values) value[c] = pair_value(r2);
        }
        ++c;
      });
      count_[i] = static_cast<std::uint32_t>(std::min(c, room));
      most = std::max(most, c);
    }
    return most;
  }

  bool with_values_ = true;
  double radius_ = 0;
  std::size_t stride_ = 0;  // room per particle
  std::vector<std::uint32_t> j_;  // particle i's neighbours in [i * stride_, i * stride_ + count_[i])
  std::vector<double> value_;  // the pair values, in the same slots (empty without values)
  std::vector<std::uint32_t> count_;
};

// Every listed neighbour j of particle i while the positions are those of the build: f(j, dx, dy, r2, value) with
// (dx, dy) = (x_i - x_j, y_i - y_j), r2 = dx^2 + dy^2 recomputed from the positions, and the pair's stored value.
template <class F>
void for_each_listed_pair(const NeighbourList& list, const ParticleSet& set, std::size_t i, F&& f) {
  const double xi = set.x[i], yi = set.y[i];
  const double* x = set.x.data();
  const double* y = set.y.data();
  const std::uint32_t* j = list.neighbours(i);
  const double* value = list.values(i);
  const std::size_t n = list.count(i);
  for (std::size_t k = 0; k < n; ++k) {
    const double dx = xi - x[j[k]], dy = yi - y[j[k]];
    f(std::size_t{j[k]}, dx, dy, dx * dx + dy * dy, value[k]);
  }
}

// Every listed neighbour j of particle i closer than `radius` (<= the list's radius) at the current positions,
// f(j, dx, dy, r2) as for_each_neighbour. A pair that came closer than `radius` after the build but was not within
// the list's radius then is not visited: the caller keeps the positions' change since the build below the
// difference of the two radii.
template <class F>
void for_each_listed_neighbour(const NeighbourList& list, const ParticleSet& set, std::size_t i, double radius,
                               F&& f) {
  const double r2_max = radius * radius, xi = set.x[i], yi = set.y[i];
  const double* x = set.x.data();
  const double* y = set.y.data();
  const std::uint32_t* j = list.neighbours(i);
  const std::size_t n = list.count(i);
  for (std::size_t k = 0; k < n; ++k) {
    const double dx = xi - x[j[k]], dy = yi - y[j[k]], r2 = dx * dx + dy * dy;
    if (r2 < r2_max) f(std::size_t{j[k]}, dx, dy, r2);
  }
}

// One OpenMP pass: each particle's candidates are compacted without a branch (every candidate is written, the count
// advances for those within `radius`), their squared distances kept in the value slots, and then turned into the
// pairs' values by a second, branch-free loop over the slots that the compiler can vectorise (pair_value should then
// be branch-free too: every r2 it sees is below radius^2). The room per particle is at least the wider list's, so
// every candidate fits.
template <class PairValue>
void NeighbourList::build_from(const NeighbourList& wider, const ParticleSet& set, double radius,
                               PairValue&& pair_value, double* value_sums) {
  radius_ = radius;
  stride_ = std::max({stride_, wider.stride_, initial_stride});
  const std::size_t particles = set.size();
  count_.resize(particles);
  j_.resize(particles * stride_);
  value_.resize(with_values_ ? particles * stride_ : 0);
  const std::size_t room = stride_;
  const bool values = with_values_;
  const double r2_max = radius * radius;
  const double* x = set.x.data();
  const double* y = set.y.data();
  const auto n = static_cast<std::int64_t>(particles);
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const std::uint32_t* candidate = wider.neighbours(i);
    const std::size_t m = wider.count(i);
    std::uint32_t* out = j_.data() + i * room;
    double* value = values ? value_.data() + i * room : nullptr;
    const double xi = x[i], yi = y[i];
    std::size_t c = 0;
    for (std::size_t q = 0; q < m; ++q) {
      const std::uint32_t j = candidate[q];
      const double dx = xi - x[j], dy = yi - y[j], r2 = dx * dx + dy * dy;
      out[c] = j;
      if (values) value[c] = r2;
      c += r2 < r2_max ? 1 : 0;
    }
    count_[i] = static_cast<std::uint32_t>(c);
    if (!values) continue;
    for (std::size_t q = 0; q < c; ++q) value[q] = pair_value(value[q]);
    if (!value_sums) continue;
    double sum = 0;
    for (std::size_t q = 0; q < c; ++q) sum += value[q];
    value_sums[i] = sum;
  }
}

}  // namespace sph
