// Section geometry and slicing of circular slip masses. Reference values are closed-form geometry.
#include <catch2/catch.hpp>

#include <cmath>

#include "lem_checks.hpp"
#include "lem_sections.hpp"
#include "slope/methods.hpp"
#include "slope/slices.hpp"

namespace test_lem_slicing {

using Catch::Matchers::Contains;
using namespace lem_test;

namespace {

// Area of the circular segment cut off by a chord at distance d from the centre (closed form).
double segment_area(double radius, double d) {
  const double half_angle = std::acos(d / radius);
  return radius * radius * (half_angle - std::sin(half_angle) * std::cos(half_angle));
}

slope::Section flat_ground(double ground_y, double bottom_y) {
  slope::Section s;
  s.bottom_y = bottom_y;
  s.materials.push_back(material("soil", 20.0, 10.0, 25.0));
  s.profile_lines.push_back(slope::ProfileLine{0, {{0, ground_y}, {100, ground_y}}});
  return s;
}

double total(const slope::SlipMass& mass, double slope::Slice::*field) {
  double sum = 0.0;
  for (const slope::Slice& s : mass.slices) sum += s.*field;
  return sum;
}

}  // namespace

TEST_CASE("polyline_y interpolates and is constant beyond the ends, ground_y clamps", "[slope][geometry]") {
  const std::vector<slope::Point> line{{0, 1}, {2, 3}, {4, 3}, {6, 0}};
  CHECK(slope::polyline_y(line, -5) == 1.0);
  CHECK(slope::polyline_y(line, 1) == Approx(2.0));
  CHECK(slope::polyline_y(line, 3) == Approx(3.0));
  CHECK(slope::polyline_y(line, 5) == Approx(1.5));
  CHECK(slope::polyline_y(line, 9) == 0.0);
  const slope::Section s = griffiths_lane_no_foundation();
  CHECK(s.x_min() == 0.0);
  CHECK(s.x_max() == 52.0);
  CHECK(s.ground_y(22.0) == Approx(15.0));
  CHECK(s.ground_y(-3.0) == 20.0);
}

TEST_CASE("section_error names what is wrong with a section", "[slope][geometry]") {
  CHECK(slope::section_error(griffiths_lane_no_foundation()).empty());
  slope::Section s = griffiths_lane_no_foundation();
  s.profile_lines[0].points[2].x = 11.0;  // x no longer increasing
  CHECK_THAT(slope::section_error(s), Contains("increase"));
  s = griffiths_lane_no_foundation();
  s.bottom_y = 15.0;
  CHECK_THAT(slope::section_error(s), Contains("below the rigid base"));
  s = griffiths_lane_no_foundation();
  s.profile_lines.push_back(slope::ProfileLine{0, {{0, 25}, {52, 25}}});
  CHECK_THAT(slope::section_error(s), Contains("above the ground"));
  s = griffiths_lane_no_foundation();
  s.materials[0].unit_weight = 0.0;
  CHECK_THAT(slope::section_error(s), Contains("unit weight"));
}

TEST_CASE("slice weights add up to the closed-form circular-segment area", "[slope][slicing][validation]") {
  // Flat ground at y = 20, circle centre 8 m above it, R = 12: a segment of a circle (closed form). The base is
  // the chord polygon of the arc, so its area falls short of the segment by O(1/n^2): 0.1 % with 50 slices; it
  // equals the chord polygon's area (a sum of trapezoids) to 1e-9.
  const slope::Section s = flat_ground(20.0, 0.0);
  const slope::Circle circle{50.0, 28.0, 12.0};
  const auto mass = slope::slice_circle(s, circle, slope::SliceOptions{50});
  REQUIRE(mass);
  const double area = segment_area(12.0, 8.0);
  CHECK(total(*mass, &slope::Slice::weight) == Approx(20e3 * area).epsilon(1e-3));
  CHECK(total(*mass, &slope::Slice::weight) < 20e3 * area);
  // exactly: the area between the ground and the chords of 50 equal slices, a sum of trapezoids (closed form)
  const double half_chord = std::sqrt(144.0 - 64.0), w = 2.0 * half_chord / 50.0;
  auto arc_y = [](double x) { return 28.0 - std::sqrt(std::max(0.0, 144.0 - (x - 50.0) * (x - 50.0))); };
  double chord_area = 0.0;
  for (int k = 0; k < 50; ++k) {
    const double x0 = 50.0 - half_chord + k * w, x1 = x0 + w;
    chord_area += w * (20.0 - 0.5 * (arc_y(x0) + arc_y(x1)));
  }
  CHECK(total(*mass, &slope::Slice::weight) == Approx(20e3 * chord_area).epsilon(1e-9));
  for (const slope::Slice& sl : mass->slices) CHECK(sl.width == Approx(w).epsilon(1e-12));
  CHECK(mass->slices.size() == 50);
  CHECK(std::min(mass->entry.x, mass->exit.x) == Approx(50.0 - std::sqrt(144.0 - 64.0)).epsilon(1e-12));
  CHECK(mass->exit.y == Approx(20.0));
  double width = 0.0;
  for (const slope::Slice& sl : mass->slices) {
    CHECK(sl.x_right > sl.x_left);
    CHECK(sl.width == Approx(sl.x_right - sl.x_left));
    CHECK(sl.base_length >= sl.width);
    width += sl.width;
  }
  CHECK(width == Approx(2.0 * std::sqrt(80.0)).epsilon(1e-12));

  SECTION("a symmetric mass has no driving moment: every method refuses it instead of returning a number") {
    for (slope::Method method : slope::all_methods()) {
      const slope::FsResult r = slope::factor_of_safety(*mass, method);
      INFO(slope::method_key(method) << ": " << r.error);
      CHECK_FALSE(r.factor_of_safety.has_value());
      CHECK_FALSE(r.error.empty());
    }
  }
}

// Weight of the soil between the ground and the chord of one slice, by a fine midpoint rule over the layers: an
// independent check of the slicer's segment integration (which uses cumulative areas, not sampling).
double sampled_weight(const slope::Section& s, const slope::Slice& sl, double unit_weight_top, double interface_y,
                      double unit_weight_bottom) {
  const int n = 20000;
  const double slope_of_chord = std::tan(sl.base_angle);  // sliding toward +x
  double weight = 0.0;
  for (int k = 0; k < n; ++k) {
    const double x = sl.x_left + (k + 0.5) * sl.width / n;
    // the chord through (base_x, base_y); base_angle is measured against the sliding direction (+x here)
    const double chord = sl.base_y - slope_of_chord * (x - sl.base_x);
    const double ground = s.ground_y(x);
    weight += unit_weight_top * std::max(0.0, ground - std::max(interface_y, chord)) +
              unit_weight_bottom * std::max(0.0, std::min(interface_y, ground) - chord);
  }
  return weight * sl.width / n;
}

TEST_CASE("slice boundaries fall on material changes, vertices inside a slice are integrated exactly",
          "[slope][slicing]") {
  // Two layers: the slope soil above y = 8 (horizontal interface below the toe), a stiffer clay below. The circle
  // crosses the interface at x = xc -+ sqrt(R^2 - (yc - 8)^2); the crest (20) and toe (40) vertices lie inside
  // slices, which integrate the ground across them.
  slope::Section s = griffiths_lane_1999();
  s.materials.push_back(material("lower", 18.0, 30.0, 5.0));
  s.profile_lines.push_back(slope::ProfileLine{1, {{0, 8}, {60, 8}}});
  const slope::Circle circle{36.0, 30.0, 25.0};
  const auto mass = slope::slice_circle(s, circle, slope::SliceOptions{30});
  REQUIRE(mass);
  REQUIRE(mass->direction == 1);
  // 30 slices asked for, the interval split at the two interface crossings: at most one more per interval
  CHECK(mass->slices.size() >= 29);
  CHECK(mass->slices.size() <= 32);
  const double crossing_left = 36.0 - std::sqrt(625.0 - 484.0);
  const double crossing_right = 36.0 + std::sqrt(625.0 - 484.0);
  auto has_boundary = [&](double x) {
    for (const slope::Slice& sl : mass->slices)
      if (std::fabs(sl.x_left - x) < 1e-9 || std::fabs(sl.x_right - x) < 1e-9) return true;
    return false;
  };
  CHECK(has_boundary(crossing_left));
  CHECK(has_boundary(crossing_right));
  int straddling = 0;
  for (const slope::Slice& sl : mass->slices) {
    const bool in_lower = sl.base_x > crossing_left && sl.base_x < crossing_right;
    CHECK(sl.base_material == (in_lower ? 1u : 0u));
    CHECK(sl.cohesion == Approx(in_lower ? 30e3 : 10e3));
    if ((sl.x_left < 20.0 && sl.x_right > 20.0) || (sl.x_left < 40.0 && sl.x_right > 40.0)) ++straddling;
    CHECK(sl.weight == Approx(sampled_weight(s, sl, 20e3, 8.0, 18e3)).epsilon(1e-6));
  }
  CHECK(straddling == 2);
}

TEST_CASE("splitting the ground into collinear pieces changes no slice", "[slope][slicing]") {
  slope::Section coarse = griffiths_lane_1999();
  coarse.water = slope::Water{{{0, 16}, {25, 14}, {60, 11}}, 9810.0};
  slope::Section fine = coarse;
  std::vector<slope::Point> points;
  const auto& ground = coarse.profile_lines.front().points;
  for (std::size_t i = 0; i + 1 < ground.size(); ++i)
    for (int k = 0; k < 997; ++k) {
      const double t = k / 997.0;
      points.push_back({ground[i].x + t * (ground[i + 1].x - ground[i].x), ground[i].y + t * (ground[i + 1].y - ground[i].y)});
    }
  points.push_back(ground.back());
  fine.profile_lines.front().points = points;
  const slope::Circle circle{36.0, 32.0, 22.0};
  const auto a = slope::slice_circle(coarse, circle, {});
  const auto b = slope::slice_circle(fine, circle, {});
  REQUIRE(a);
  REQUIRE(b);
  REQUIRE(a->slices.size() == b->slices.size());
  for (std::size_t i = 0; i < a->slices.size(); ++i) {
    CHECK(b->slices[i].x_left == Approx(a->slices[i].x_left).epsilon(1e-12));
    CHECK(b->slices[i].weight == Approx(a->slices[i].weight).epsilon(1e-9));
    CHECK(b->slices[i].ponded_water_load == Approx(a->slices[i].ponded_water_load).epsilon(1e-9).margin(1e-6));
    CHECK(b->slices[i].water_thrust == Approx(a->slices[i].water_thrust).epsilon(1e-9).margin(1e-6));
  }
}

TEST_CASE("pore pressure, ponded water and its thrust on the slice top follow the piezometric line",
          "[slope][slicing][water]") {
  // Horizontal piezometric line at y = 14 over a 2:1 slope whose toe is at y = 10: 4 m of water stand on the toe.
  slope::Section s = griffiths_lane_1999();
  s.water = slope::Water{{{0, 14}, {60, 14}}, 9810.0};
  const auto mass = slope::slice_circle(s, slope::Circle{36.0, 30.0, 20.0}, slope::SliceOptions{40});
  REQUIRE(mass);
  bool ponded_found = false;
  for (const slope::Slice& sl : mass->slices) {
    CHECK(sl.pore_pressure == Approx(9810.0 * std::max(0.0, 14.0 - sl.base_y)).epsilon(1e-12).margin(1e-9));
    const double depth = std::max(0.0, 14.0 - sl.top_y);
    CHECK(sl.ponded_water_load == Approx(9810.0 * depth * sl.width).epsilon(1e-12).margin(1e-6));
    if (depth > 0.0) {
      ponded_found = true;
      if (sl.x_right <= 40.0) {
        // on the 2:1 face the thrust is p * (dy/dx) * width against the sliding direction (toward +x): -p b / 2
        CHECK(sl.water_thrust == Approx(-0.5 * sl.ponded_water_load).epsilon(1e-9));
      } else {
        CHECK(sl.water_thrust == Approx(0.0).margin(1e-9));  // flat toe ground
      }
    }
  }
  CHECK(ponded_found);
}

TEST_CASE("inadmissible circles are rejected with a reason", "[slope][slicing]") {
  const slope::Section s = griffiths_lane_1999();
  std::string reason;
  CHECK_FALSE(slope::slice_circle(s, slope::Circle{30.0, 25.0, 30.0}, {}, &reason));  // lowest point y = -5
  CHECK_THAT(reason, Contains("rigid base"));
  CHECK_FALSE(slope::slice_circle(s, slope::Circle{30.0, 60.0, 10.0}, {}, &reason));  // in the air
  CHECK_THAT(reason, Contains("does not cut"));
  CHECK_FALSE(slope::slice_circle(s, slope::Circle{5.0, 30.0, 15.0}, {}, &reason));  // beyond the left end
  CHECK_THAT(reason, Contains("beyond"));
  CHECK_FALSE(slope::slice_circle(s, slope::Circle{30.0, 0.0, 1.0}, {}, &reason));  // buried, no closed mass
  CHECK_FALSE(reason.empty());
  CHECK_FALSE(slope::slice_circle(s, slope::Circle{30.0, 30.0, -1.0}, {}, &reason));
  CHECK_THAT(reason, Contains("radius"));

  // a bumpy ground cut four times by one circle: the arc rises 2.9 m above the ground between the cuts (29 % of
  // the 10 m relief), two masses
  slope::Section bumpy = s;
  bumpy.profile_lines[0].points = {{0, 20}, {20, 20}, {26, 17}, {28, 14}, {30, 17}, {40, 10}, {60, 10}};
  CHECK_FALSE(slope::slice_circle(bumpy, slope::Circle{31.0, 30.0, 15.5}, {}, &reason));
  CHECK_THAT(reason, Contains("re-enters"));
}

TEST_CASE("an arc that grazes a survey's roughness above the ground is one mass, the gap slices weigh nothing",
          "[slope][slicing]") {
  // Griffiths & Lane with a dip in the toe ground at x = 44.75-44.85 m. The circle through the crest at x = 15 m
  // and the toe ground at x = 45 m (centre (35, 30), radius sqrt(500) m) runs 0.123 m below the toe ground at
  // x = 44.75 m and 0.074 m at 44.85 m: over a dip 0.13 m deep it leaves the ground and re-enters it, at most
  // 5.6 cm above the dip's bottom (0.56 % of the 10 m relief, under the 1 % limit): one mass.
  slope::Section rough = griffiths_lane_1999();
  auto& ground = rough.profile_lines[0].points;
  const auto with_dip = [](double depth) {
    return std::vector<slope::Point>{{0, 20},  {20, 20}, {40, 10},  {44.7, 10}, {44.75, 10 - depth},
                                     {44.85, 10 - depth}, {44.9, 10}, {60, 10}};
  };
  const slope::Circle circle{35.0, 30.0, std::sqrt(500.0)};
  ground = with_dip(0.13);
  std::string reason;
  const auto mass = slope::slice_circle(rough, circle, {}, &reason);
  INFO(reason);
  REQUIRE(mass);
  CHECK(mass->exit.x == Approx(45.0).epsilon(0).margin(1e-9));
  bool weightless_found = false;
  for (const slope::Slice& sl : mass->slices) {
    if (sl.x_left >= 44.7 && sl.x_right <= 44.9 && sl.weight == 0.0) weightless_found = true;  // crossings on the walls
    CHECK(sl.weight >= 0.0);
  }
  CHECK(weightless_found);
  // A dip 0.25 m deep: the arc is up to 0.18 m above its bottom (1.8 % of the relief): two masses, refused.
  ground = with_dip(0.25);
  CHECK_FALSE(slope::slice_circle(rough, circle, {}, &reason));
  CHECK_THAT(reason, Contains("re-enters"));
}

TEST_CASE("a toe on a firm base may end a mass, an arc under the toe is rejected", "[slope][slicing]") {
  // Griffiths & Lane example 1 stands on a rigid base at toe level (x = 32, y = 10).
  const slope::Section s = griffiths_lane_no_foundation();
  const slope::Circle through_toe{40.0, 30.0, std::hypot(8.0, 20.0)};  // descends at the toe
  const auto mass = slope::slice_circle(s, through_toe, {});
  REQUIRE(mass);
  CHECK(mass->exit.x == Approx(32.0));
  CHECK(mass->exit.y == Approx(10.0));
  std::string reason;
  slope::Circle below = through_toe;
  below.radius += 0.1;
  CHECK_FALSE(slope::slice_circle(s, below, {}, &reason));
  CHECK_THAT(reason, Contains("rigid base"));
}

TEST_CASE("mirroring the section mirrors the slices and keeps every factor of safety", "[slope][slicing]") {
  slope::Section s = griffiths_lane_1999();
  s.water = slope::Water{{{0, 16}, {25, 14}, {60, 11}}, 9810.0};
  s.surcharges.push_back(slope::Surcharge{5.0, 15.0, 20e3});
  s.seismic_coefficient = 0.1;
  const slope::Section m = mirrored(s);
  const slope::Circle circle{36.0, 32.0, 22.0};
  const auto right = slope::slice_circle(s, circle, {});
  const auto left = slope::slice_circle(m, slope::Circle{-36.0, 32.0, 22.0}, {});
  REQUIRE(right);
  REQUIRE(left);
  CHECK(right->direction == 1);
  CHECK(left->direction == -1);
  CHECK(left->entry.x == Approx(-right->entry.x));
  CHECK(left->exit.x == Approx(-right->exit.x));
  REQUIRE(left->slices.size() == right->slices.size());
  const std::size_t n = right->slices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const slope::Slice& a = right->slices[i];
    const slope::Slice& b = left->slices[n - 1 - i];
    CHECK(b.base_angle == Approx(a.base_angle).epsilon(1e-12).margin(1e-12));
    CHECK(b.weight == Approx(a.weight).epsilon(1e-10));  // cumulative-area integrals round differently mirrored
    CHECK(b.water_thrust == Approx(a.water_thrust).epsilon(1e-9).margin(1e-6));
  }
  for (slope::Method method : slope::all_methods()) {
    INFO(slope::method_key(method));
    const slope::FsResult a = slope::factor_of_safety(*right, method);
    const slope::FsResult b = slope::factor_of_safety(*left, method);
    REQUIRE(a.factor_of_safety);
    REQUIRE(b.factor_of_safety);
    CHECK(*b.factor_of_safety == Approx(*a.factor_of_safety).epsilon(1e-9));
    CHECK(b.lambda == Approx(a.lambda).epsilon(1e-7).margin(1e-7));
  }
}

TEST_CASE("a saturated unit weight weighs the soil below the piezometric line", "[slope][slicing][water]") {
  // Level ground at y = 20 over a base at y = 0, the water at y = 12 (ponded nowhere). Every slice's weight is
  // b (gamma (top - 12) + gamma_sat (12 - base)) where its base is below the water, b gamma (top - base) above it
  // (hand calculation on the slice's own mean heights: the ground and the water are level).
  slope::Section s = flat_ground(20.0, 0.0);
  s.water = slope::Water{{{0, 12}, {100, 12}}};
  s.materials[0].saturated_unit_weight = 22e3;
  const slope::Circle circle{50.0, 30.0, 25.0};
  const auto mass = slope::slice_circle(s, circle, slope::SliceOptions{});
  REQUIRE(mass);
  bool some_below = false, some_above = false;
  for (const slope::Slice& slice : mass->slices) {
    // the base's mean height over the slice: the chord's midpoint, as the slicer takes it
    const double base = slice.base_y;
    const double expected = base < 12.0 ? slice.width * (20e3 * (20.0 - 12.0) + 22e3 * (12.0 - base))
                                        : slice.width * 20e3 * (20.0 - base);
    some_below = some_below || base < 12.0;
    some_above = some_above || base > 12.0;
    CHECK(slice.weight == Approx(expected).epsilon(1e-12));
  }
  CHECK(some_below);
  CHECK(some_above);

  s.materials[0].saturated_unit_weight = -1.0;
  CHECK_THAT(slope::section_error(s), Contains("saturated unit weight"));

  // On a slope (crest y = 15 to x = 20, a 30 degree face to the toe at y = 5): with the water along the ground, a
  // saturated weight of 22 is a unit weight of 22 everywhere; with the water below the mass, it changes nothing
  // (every factor of safety equal to 1e-12).
  s = simple_slope(10.0, 30.0, 20.0, 30.0, 5.0, material("soil", 20.0, 10.0, 25.0));
  s.materials[0].saturated_unit_weight = 22e3;
  const slope::Circle on_slope{30.0, 28.0, 22.0};
  const auto expect_same = [&](const slope::Section& a, const slope::Section& b) {
    const auto ma = slope::slice_circle(a, on_slope, slope::SliceOptions{});
    const auto mb = slope::slice_circle(b, on_slope, slope::SliceOptions{});
    REQUIRE(ma);
    REQUIRE(mb);
    for (slope::Method m : {slope::Method::ordinary, slope::Method::bishop, slope::Method::spencer})
      CHECK(fs_on(*ma, m) == Approx(fs_on(*mb, m)).epsilon(1e-12));
  };
  slope::Section at_ground = s;
  at_ground.water = slope::Water{s.profile_lines[0].points};
  slope::Section heavy = at_ground;
  heavy.materials[0].unit_weight = 22e3;
  heavy.materials[0].saturated_unit_weight.reset();
  expect_same(at_ground, heavy);
  slope::Section deep = s;
  deep.water = slope::Water{{{0, 0.5}, {100, 0.5}}};
  slope::Section dry_weight = deep;
  dry_weight.materials[0].saturated_unit_weight.reset();
  expect_same(deep, dry_weight);
}

}  // namespace test_lem_slicing
