// The engine's neighbour iteration (sph/engine/neighbours.hpp) within one particle set and across two, and its
// neighbour lists (sph/engine/neighbour_list.hpp), against an O(N^2) search: every pair closer than the radius is
// visited exactly once, with the right separation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "sph/engine/cell_sort.hpp"
#include "sph/engine/neighbour_list.hpp"
#include "sph/engine/neighbours.hpp"

namespace test_neighbours {

namespace {

sph::ParticleSet scattered(std::size_t n, double x_lo, double x_hi, double y_lo, double y_hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(x_lo, x_hi), uy(y_lo, y_hi);
  sph::ParticleSet set;
  for (std::size_t i = 0; i < n; ++i) set.add(ux(rng), uy(rng), 1.0, 1000.0, 0, sph::ParticleKind::material);
  return set;
}

std::vector<std::size_t> brute(const sph::ParticleSet& s, double x, double y, double radius, std::size_t skip) {
  std::vector<std::size_t> out;
  for (std::size_t j = 0; j < s.size(); ++j)
    if (j != skip && std::hypot(x - s.x[j], y - s.y[j]) < radius) out.push_back(j);
  return out;
}

}  // namespace

TEST_CASE("neighbour iteration within one set visits every pair closer than the radius once", "[sph][neighbours]") {
  sph::ParticleSet set = scattered(600, 0.0, 1.0, 0.0, 0.5, 7);
  const double radius = 0.06;
  sph::CellSortedSet sorted;
  sorted.reserve(set);
  sorted.sort(set, radius);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    std::vector<std::size_t> found;
    sph::for_each_neighbour(sorted, set, i, radius, [&](std::size_t j, double dx, double dy, double r2) {
      found.push_back(j);
      CHECK(dx == set.x[i] - set.x[j]);
      CHECK(dy == set.y[i] - set.y[j]);
      CHECK(r2 < radius * radius);
    });
    std::sort(found.begin(), found.end());
    REQUIRE(found == brute(set, set.x[i], set.y[i], radius, i));
    pairs += found.size();
  }
  CHECK(pairs > 600);  // the set is dense enough that the test sees many pairs
}

TEST_CASE("neighbour iteration across two sets finds the other set's particles near each point", "[sph][neighbours]") {
  // Water to the right of the soil, overlapping over [0.8, 1.0]; some soil lies beyond the water's grid.
  sph::ParticleSet soil = scattered(400, 0.0, 1.0, 0.0, 0.5, 11);
  sph::ParticleSet water = scattered(500, 0.8, 2.0, -0.1, 0.7, 13);
  const double radius = 0.05;
  sph::CellSortedSet sorted_water;
  sorted_water.reserve(water);
  sorted_water.sort(water, radius);
  std::size_t pairs = 0;
  const std::size_t none = water.size();
  for (std::size_t i = 0; i < soil.size(); ++i) {
    std::vector<std::size_t> found;
    sph::for_each_neighbour_at(sorted_water, water, soil.x[i], soil.y[i], radius,
                               [&](std::size_t j, double, double, double) { found.push_back(j); });
    std::sort(found.begin(), found.end());
    REQUIRE(found == brute(water, soil.x[i], soil.y[i], radius, none));
    pairs += found.size();
  }
  CHECK(pairs > 50);
  // Points far outside the other set's grid, on every side, have no neighbours and do not read out of range.
  for (auto [x, y] : {std::pair{-5.0, 0.3}, {9.0, 0.3}, {1.4, -4.0}, {1.4, 6.0}}) {
    std::size_t n = 0;
    sph::for_each_neighbour_at(sorted_water, water, x, y, radius, [&](std::size_t, double, double, double) { ++n; });
    CHECK(n == 0);
  }
}

TEST_CASE("a neighbour list drawn from wider candidates holds every pair within the radius after a move less than "
          "half the margin, in the candidates' order, with its pair values",
          "[sph][neighbours]") {
  sph::ParticleSet set = scattered(800, 0.0, 1.0, 0.0, 0.5, 17);
  const double radius = 0.05, margin = 0.02;
  sph::CellSortedSet sorted;
  sorted.reserve(set);
  sorted.sort(set, radius + margin);
  sph::NeighbourList candidates(false);
  candidates.build(sorted, set, radius + margin, [](double) { return 0.0; });
  // every particle moves by just under margin / 2 in a random direction
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  for (std::size_t i = 0; i < set.size(); ++i) {
    const double a = angle(rng);
    set.x[i] += 0.499 * margin * std::cos(a);
    set.y[i] += 0.499 * margin * std::sin(a);
  }
  sph::NeighbourList list;
  list.build_from(candidates, set, radius, [](double r2) { return 2.0 * r2; });
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    std::vector<std::size_t> found;
    sph::for_each_listed_pair(list, set, i, [&](std::size_t j, double, double, double r2, double value) {
      found.push_back(j);
      CHECK(value == 2.0 * r2);
    });
    CHECK(std::is_sorted(found.begin(), found.end()));  // the candidates' order: the sort's cells, row-major
    REQUIRE(found == brute(set, set.x[i], set.y[i], radius, i));
    pairs += found.size();
  }
  CHECK(pairs > 1000);
  // moved by more than the margin, the candidates miss pairs: the bound above is what the caller must keep
  for (std::size_t i = 0; i < set.size(); ++i) set.x[i] += (i % 2 == 0 ? 1.5 : -1.5) * margin;
  list.build_from(candidates, set, radius, [](double r2) { return r2; });
  std::size_t missing = 0, extra = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    const std::size_t truth = brute(set, set.x[i], set.y[i], radius, i).size(), listed = list.count(i);
    missing += truth > listed ? truth - listed : 0;
    extra += listed > truth ? listed - truth : 0;
  }
  CHECK(missing > 0);
  CHECK(extra == 0);  // the candidates hold no pair beyond the radius, moved or not
}

}  // namespace test_neighbours
