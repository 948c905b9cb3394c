// Critical-surface search: chart values, the Griffiths & Lane slope, user limits, mirror symmetry, FS map.
#include <catch2/catch.hpp>

#include <cmath>

#include "lem_sections.hpp"
#include "slope/search.hpp"

namespace test_lem_search {

using Catch::Matchers::Contains;
using namespace lem_test;

namespace {

const slope::CriticalSurface& result_for(const slope::SearchResult& r, slope::Method m) {
  for (const slope::CriticalSurface& c : r.methods)
    if (c.method == m) return c;
  FAIL("method missing from the search result");
  return r.methods.front();
}

double critical_fs(const slope::SearchResult& r, slope::Method m) {
  const slope::CriticalSurface& c = result_for(r, m);
  INFO(slope::method_key(m) << ": " << c.result.error);
  REQUIRE(c.mass.has_value());
  REQUIRE(c.result.factor_of_safety.has_value());
  return *c.result.factor_of_safety;
}

// Taylor's stability number N = c / (gamma H F) of the critical circle for a phi = 0 slope. With phi = 0,
// moment equilibrium alone fixes F on a circle, so any factor of safety Spencer or Morgenstern-Price report on the
// critical circle must be Bishop's; where no (F, lambda) exists they must say so instead (steep toe circles).
// How often Spencer and Morgenstern-Price gave a number on Bishop's critical circle, and how often they refused it.
struct Outcomes {
  int numbers = 0, refusals = 0;
};
Outcomes general_methods_on_taylor_circles;

double taylor_number(double beta_deg, double depth_factor, bool firm_base_at_toe) {
  const double H = 10.0, c = 20e3, gamma = 20e3;
  const double toe_y = firm_base_at_toe ? 0.0 : (depth_factor - 1.0) * H;
  const double angle = std::min(beta_deg, 89.99);  // a vertical face as a 0.002 m wide step
  const double face = H / std::tan(radians(angle));
  const double run = firm_base_at_toe ? 40.0 : 8.0 * depth_factor * H;
  const slope::Section s = simple_slope(H, angle, run, run + face, toe_y, material("clay", 20.0, 20.0, 0.0));
  const slope::SearchResult r = slope::search_critical(s, {slope::Method::bishop}, slope::SearchOptions{});
  const double bishop = critical_fs(r, slope::Method::bishop);
  for (slope::Method m : {slope::Method::spencer, slope::Method::morgenstern_price}) {
    const slope::FsResult other = slope::factor_of_safety(*r.methods[0].mass, m);
    INFO(slope::method_key(m) << " on Bishop's critical circle, beta = " << beta_deg << ": " << other.error);
    if (other.factor_of_safety) {
      ++general_methods_on_taylor_circles.numbers;
      CHECK(*other.factor_of_safety == Approx(bishop).epsilon(1e-8));
    } else {
      ++general_methods_on_taylor_circles.refusals;
      CHECK_FALSE(other.error.empty());
    }
  }
  return c / (gamma * H * bishop);
}

}  // namespace

TEST_CASE("Griffiths & Lane (1999) slope: the Bishop search lands within 2 % of the charts' 1.38",
          "[slope][search][published][validation]") {
  // Griffiths & Lane (1999), Geotechnique 49(3):387-403: Bishop & Morgenstern (1960) charts give F = 1.38 for
  // this slope (finite elements 1.4). Checked with a foundation layer (D = 2) and without one (D = 1, the rigid base
  // at the toe level, the section of cases/griffiths_lane_1999.json).
  for (const slope::Section& s : {griffiths_lane_1999(), griffiths_lane_no_foundation()}) {
    const slope::SearchResult r = slope::search_critical(s, slope::all_methods(), slope::SearchOptions{});
    REQUIRE(r.error.empty());
    const double bishop = critical_fs(r, slope::Method::bishop);
    const double spencer = critical_fs(r, slope::Method::spencer);
    const double mp = critical_fs(r, slope::Method::morgenstern_price);
    CHECK(bishop == Approx(1.38).epsilon(0.02));
    CHECK(mp == Approx(spencer).epsilon(0.01));   // Spencer and Morgenstern-Price agree within 1 %
    CHECK(bishop == Approx(spencer).epsilon(0.02));  // Bishop within 2 % of them on an ordinary slope
    CHECK(critical_fs(r, slope::Method::ordinary) < bishop);
    CHECK(critical_fs(r, slope::Method::morgenstern_price_constant) == Approx(spencer).epsilon(1e-9));
    // a toe circle: the exit is at or just above the toe (x = 40 resp. 32)
    const slope::SlipMass& mass = *result_for(r, slope::Method::bishop).mass;
    CHECK(mass.exit.y == Approx(10.0).margin(0.5));
    CHECK(mass.entry.y == Approx(20.0));
    CHECK(mass.direction == 1);
  }
}

TEST_CASE("phi = 0 toe circles reproduce Taylor's (1937) stability numbers for steep slopes",
          "[slope][search][closed-form][validation]") {
  // Taylor (1937), stability chart for phi = 0: slopes steeper than 53 deg fail on toe circles whatever the depth
  // factor; N = c / (gamma H F) = 0.261 (90 deg, H_c = 3.83 c/gamma), 0.219 (75 deg), 0.191 (60 deg),
  // 0.181 (53 deg). Firm base at the toe level.
  CHECK(taylor_number(90.0, 1.0, true) == Approx(0.261).epsilon(0.02));
  CHECK(taylor_number(75.0, 1.0, true) == Approx(0.219).epsilon(0.02));
  CHECK(taylor_number(60.0, 1.0, true) == Approx(0.191).epsilon(0.02));
  CHECK(taylor_number(53.0, 1.0, true) == Approx(0.181).epsilon(0.02));
  // both branches of the consistency check ran: numbers equal to Bishop's, and refusals with a reason
  INFO("Spencer and M-P on the four circles: " << general_methods_on_taylor_circles.numbers << " numbers, "
                                                << general_methods_on_taylor_circles.refusals << " refusals");
  CHECK(general_methods_on_taylor_circles.numbers >= 4);
  CHECK(general_methods_on_taylor_circles.refusals >= 1);
}

TEST_CASE("phi = 0 base-tangent circles approach Taylor's deep-base limit N = 0.181 from below",
          "[slope][search][closed-form][validation]") {
  // Taylor (1937) / Fellenius: for slopes flatter than 53 deg on a deep stratum the critical circle touches the
  // rigid base and N rises with the depth factor D toward 0.181 (stability factor 5.52) as D -> infinity.
  const double n2 = taylor_number(30.0, 2.0, false);
  const double n4 = taylor_number(30.0, 4.0, false);
  const double n6 = taylor_number(30.0, 6.0, false);
  CHECK(n2 < n4);
  CHECK(n4 < n6);
  CHECK(n6 < 0.181);  // from below
  CHECK(n6 == Approx(0.181).epsilon(0.01));
}

TEST_CASE("a slope facing left gives the same critical surfaces as its mirror image", "[slope][search]") {
  slope::Section s = griffiths_lane_1999();
  s.water = slope::Water{{{0, 17}, {30, 13}, {60, 10}}, 9810.0};
  const std::vector<slope::Method> methods{slope::Method::bishop, slope::Method::spencer};
  const slope::SearchResult right = slope::search_critical(s, methods, slope::SearchOptions{});
  const slope::SearchResult left = slope::search_critical(mirrored(s), methods, slope::SearchOptions{});
  for (slope::Method m : methods) {
    INFO(slope::method_key(m));
    CHECK(critical_fs(left, m) == Approx(critical_fs(right, m)).epsilon(2e-3));
    const slope::SlipMass& a = *result_for(right, m).mass;
    const slope::SlipMass& b = *result_for(left, m).mass;
    CHECK(b.direction == -1);
    CHECK(b.entry.x == Approx(-a.entry.x).margin(0.5));
    CHECK(b.exit.x == Approx(-a.exit.x).margin(0.5));
  }
}

TEST_CASE("user limits are respected, limits admitting no circle give an error", "[slope][search][limits]") {
  const slope::Section s = griffiths_lane_1999();
  const slope::SearchResult free = slope::search_critical(s, {slope::Method::bishop}, slope::SearchOptions{});
  const double free_fs = critical_fs(free, slope::Method::bishop);

  SECTION("entry and exit ranges") {
    slope::SearchOptions o;
    o.limits.entry_x = slope::Range{5.0, 12.0};
    o.limits.exit_x = slope::Range{41.0, 50.0};
    const slope::SearchResult r = slope::search_critical(s, {slope::Method::bishop}, o);
    const slope::SlipMass& m = *result_for(r, slope::Method::bishop).mass;
    CHECK(m.entry.x >= 5.0 - 1e-9);
    CHECK(m.entry.x <= 12.0 + 1e-9);
    CHECK(m.exit.x >= 41.0 - 1e-9);
    CHECK(m.exit.x <= 50.0 + 1e-9);
    CHECK(critical_fs(r, slope::Method::bishop) > free_fs);
  }
  SECTION("centre grid and radius range") {
    slope::SearchOptions o;
    o.limits.centre_grid = slope::CentreGrid{{30.0, 42.0}, {26.0, 40.0}, 8, 8};
    o.limits.radius = slope::Range{15.0, 30.0};
    const slope::SearchResult r = slope::search_critical(s, {slope::Method::bishop}, o);
    const slope::SlipMass& m = *result_for(r, slope::Method::bishop).mass;
    CHECK(m.circle.xc >= 30.0 - 1e-9);
    CHECK(m.circle.xc <= 42.0 + 1e-9);
    CHECK(m.circle.yc >= 26.0 - 1e-9);
    CHECK(m.circle.yc <= 40.0 + 1e-9);
    CHECK(m.circle.radius >= 15.0 - 1e-9);
    CHECK(m.circle.radius <= 30.0 + 1e-9);
    CHECK(critical_fs(r, slope::Method::bishop) == Approx(free_fs).epsilon(0.005));  // the grid holds the optimum
  }
  SECTION("centre grid with automatic radii") {
    slope::SearchOptions o;
    o.limits.centre_grid = slope::CentreGrid{{25.0, 45.0}, {22.0, 45.0}, 6, 6};
    const slope::SearchResult r = slope::search_critical(s, {slope::Method::bishop}, o);
    CHECK(critical_fs(r, slope::Method::bishop) == Approx(free_fs).epsilon(0.005));
  }
  SECTION("limits that admit no circle") {
    slope::SearchOptions o;
    o.limits.entry_x = slope::Range{45.0, 55.0};  // on the level toe ground ...
    o.limits.exit_x = slope::Range{2.0, 8.0};     // ... and the exit on the crest: no slip mass can do that
    const slope::SearchResult r = slope::search_critical(s, {slope::Method::bishop, slope::Method::spencer}, o);
    CHECK_THAT(r.error, Contains("no admissible slip circle"));
    REQUIRE(r.methods.size() == 2);
    for (const slope::CriticalSurface& c : r.methods) {
      CHECK_FALSE(c.mass.has_value());
      CHECK_FALSE(c.result.factor_of_safety.has_value());
      CHECK_FALSE(c.result.error.empty());
    }
  }
}

TEST_CASE("the search reports its FS map, the number of trials and its time", "[slope][search]") {
  const slope::SearchResult r = slope::search_critical(
      griffiths_lane_1999(), {slope::Method::spencer, slope::Method::bishop}, slope::SearchOptions{});
  REQUIRE(r.methods.size() == 2);
  CHECK(r.methods[0].method == slope::Method::spencer);  // in the order asked for
  CHECK(r.fs_map.size() > 500);
  CHECK(r.trial_surfaces > static_cast<long>(2 * r.fs_map.size()));
  CHECK(r.seconds > 0.0);
  const double spencer = critical_fs(r, slope::Method::spencer);
  for (const slope::FsMapEntry& e : r.fs_map) {
    CHECK(e.factor_of_safety >= spencer - 1e-9);  // the map is Spencer's (the first method); refinement only lowers
    CHECK(e.entry.y > e.exit.y);
  }
  // the critical surface comes with its slices and forces
  const slope::CriticalSurface& c = result_for(r, slope::Method::spencer);
  REQUIRE(c.mass);
  CHECK(c.result.forces.size() == c.mass->slices.size());
  CHECK(c.mass->slices.size() >= 45);
  CHECK(c.result.lambda > 0.0);
}

TEST_CASE("a cohesionless slope: the search stops at the minimum depth near the infinite-slope value",
          "[slope][search][validation]") {
  // c' = 0: the most critical surfaces are the shallowest (F -> tan(phi')/tan(beta), infinite slope); the
  // search keeps masses at least 2 % of the relief deep, so F lies just above that limit.
  const slope::Section s = simple_slope(10.0, 30.0, 20.0, 20.0, 5.0, material("sand", 19.0, 0.0, 35.0));
  const slope::SearchResult r = slope::search_critical(s, {slope::Method::bishop}, slope::SearchOptions{});
  const double limit = std::tan(radians(35.0)) / std::tan(radians(30.0));
  const double f = critical_fs(r, slope::Method::bishop);
  CHECK(f >= limit * 0.995);
  CHECK(f == Approx(limit).epsilon(0.03));
  CHECK(result_for(r, slope::Method::bishop).mass->slices.size() >= 45);
}

}  // namespace test_lem_search
