// Safety map of the search (Baker & Leshchinsky 2001): each cell holds the lowest factor of safety of the trial
// circles through it.
#include <catch2/catch.hpp>

#include <cmath>

#include "lem_sections.hpp"
#include "slope/safety_map.hpp"
#include "slope/slices.hpp"

namespace test_safety_map {

using namespace lem_test;

namespace {

// A trial circle on the section as the search records it (entry and exit from the slicer), with a given factor.
slope::FsMapEntry trial(double xc, double yc, double radius, double fs, const slope::Section& s) {
  const slope::SearchOptions options;
  const auto mass = slope::slice_circle(s, slope::Circle{xc, yc, radius}, options.slicing);
  REQUIRE(mass);
  return slope::FsMapEntry{mass->circle, mass->entry, mass->exit, fs};
}

int column(const slope::SafetyMap& m, double x) { return static_cast<int>(std::floor((x - m.x0) / m.cell)); }
int row(const slope::SafetyMap& m, double y) { return static_cast<int>(std::floor((y - m.y0) / m.cell)); }

}  // namespace

TEST_CASE("the safety map marks the arc of each trial with its factor and keeps the lowest", "[slope][safety_map]") {
  const slope::Section s = griffiths_lane_1999();
  const slope::FsMapEntry a = trial(40.0, 35.0, 28.0, 1.6, s);
  const slope::FsMapEntry b = trial(38.0, 30.0, 22.0, 1.3, s);
  const slope::SafetyMap one = slope::safety_map(s, {a}, 100);
  CHECK(one.nx == 100);
  CHECK(one.cell == Approx((s.x_max() - s.x_min()) / 100));
  // the lowest point of circle a (40, 7) lies in a marked cell; a cell 2 m above it is not crossed
  CHECK(one.at(column(one, 40.0), row(one, 7.0)) == 1.6);
  CHECK(std::isnan(one.at(column(one, 40.0), row(one, 9.0))));
  CHECK(one.lowest() == 1.6);
  // the entry and exit cells are marked
  CHECK(one.at(column(one, a.entry.x), row(one, a.entry.y - 1e-6)) == 1.6);
  CHECK(one.at(column(one, a.exit.x), row(one, a.exit.y + 1e-6)) == 1.6);

  const slope::SafetyMap two = slope::safety_map(s, {a, b}, 100);
  CHECK(two.lowest() == 1.3);
  int lower = 0, from_a = 0;
  for (double f : two.fs) {
    lower += f == 1.3 ? 1 : 0;
    from_a += f == 1.6 ? 1 : 0;
  }
  CHECK(lower > 0);
  CHECK(from_a > 0);
  // in either order the cells the two arcs share keep 1.3
  const slope::SafetyMap swapped = slope::safety_map(s, {b, a}, 100);
  CHECK(swapped.fs.size() == two.fs.size());
  for (std::size_t k = 0; k < two.fs.size(); ++k)
    CHECK((std::isnan(two.fs[k]) ? std::isnan(swapped.fs[k]) : two.fs[k] == swapped.fs[k]));
}

TEST_CASE("the safety map of the Griffiths & Lane search: Bishop's factors, lowest on the critical circle",
          "[slope][safety_map][search]") {
  const slope::Section s = griffiths_lane_1999();
  slope::SearchOptions options;
  options.fs_map_method = slope::Method::bishop;
  const slope::SearchResult r = slope::search_critical(s, {slope::Method::spencer, slope::Method::bishop}, options);
  REQUIRE(r.fs_map.size() > 500);
  // the map holds the chosen method's factors, not the first method's
  for (std::size_t k = 0; k < r.fs_map.size(); k += r.fs_map.size() / 7) {
    const slope::FsMapEntry& e = r.fs_map[k];
    const auto mass = slope::slice_circle(s, e.circle, options.slicing);
    REQUIRE(mass);
    const auto bishop = slope::factor_of_safety(*mass, slope::Method::bishop).factor_of_safety;
    REQUIRE(bishop);
    CHECK(e.factor_of_safety == Approx(*bishop).epsilon(1e-9));
  }
  double lowest_trial = r.fs_map.front().factor_of_safety;
  for (const slope::FsMapEntry& e : r.fs_map) lowest_trial = std::min(lowest_trial, e.factor_of_safety);
  const slope::SafetyMap map = slope::safety_map(s, r.fs_map);
  CHECK(map.lowest() == lowest_trial);
  // The refined critical circle lies in the map's lowest band: the cell under its deepest point is within 5 % of
  // the critical factor (1.376 here; the coarse trials are a few per cent above it).
  const slope::CriticalSurface& bishop = r.methods[1];
  REQUIRE(bishop.mass);
  const double critical = *bishop.result.factor_of_safety;
  const slope::Circle& c = bishop.mass->circle;
  const double deepest = std::max(c.yc - c.radius, s.bottom_y + 1e-6);
  const double at_bottom = map.at(column(map, c.xc), row(map, deepest));
  CHECK(at_bottom >= critical - 1e-9);
  CHECK(at_bottom <= 1.05 * critical);
}

}  // namespace test_safety_map
