// Slip surfaces given as polylines: slicing, admissibility, every method, closed forms and the circle as a limit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lem_sections.hpp"
#include "slope/methods.hpp"
#include "slope/slices.hpp"

namespace test_lem_polyline {

using Catch::Matchers::Contains;
using namespace lem_test;

namespace {

// Homogeneous c-phi slope: crest at y = 15 from x = 0 to 20, a 45 degree face down to the toe at (30, 5), level
// ground to x = 50; rigid base at y = 0. gamma = 18 kN/m^3, c' = 10 kPa, phi' = 25 deg, dry.
slope::Section wedge_slope() { return simple_slope(10.0, 45.0, 20.0, 20.0, 5.0, material("soil", 18.0, 10.0, 25.0)); }

slope::SlipMass sliced(const slope::Section& section, const slope::SlipPolyline& surface, int slices = 50) {
  std::string reason;
  const auto mass = slope::slice_polyline(section, surface, slope::SliceOptions{slices}, &reason);
  INFO(reason);
  REQUIRE(mass.has_value());
  return *mass;
}

double fs(const slope::SlipMass& mass, slope::Method method) {
  const slope::FsResult r = slope::factor_of_safety(mass, method);
  INFO(slope::method_key(method) << ": " << r.error);
  REQUIRE(r.factor_of_safety.has_value());
  return *r.factor_of_safety;
}

// Area of a polygon (shoelace), m^2.
double polygon_area(const std::vector<slope::Point>& p) {
  double twice = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const slope::Point& a = p[k];
    const slope::Point& b = p[(k + 1) % p.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * std::fabs(twice);
}

const std::vector<slope::Method> force_methods{slope::Method::janbu, slope::Method::spencer,
                                               slope::Method::morgenstern_price,
                                               slope::Method::morgenstern_price_constant};

}  // namespace

TEST_CASE("a polyline surface is sliced with boundaries at its vertices and weighs the soil above it") {
  const slope::Section section = wedge_slope();
  slope::SlipPolyline surface;
  surface.points = {{8.0, 15.0}, {18.0, 8.0}, {26.0, 4.0}, {34.0, 5.0}};
  const slope::SlipMass mass = sliced(section, surface, 40);
  for (const slope::Point& p : {surface.points[1], surface.points[2]}) {
    bool found = false;
    for (const slope::Slice& s : mass.slices) found = found || std::fabs(s.x_right - p.x) < 1e-12;
    INFO("vertex at x = " << p.x);
    CHECK(found);
  }
  // The mass is the polygon of the ground (8,15)-(20,15)-(30,5)-(34,5) over the surface: shoelace formula.
  const double area = polygon_area({{8, 15}, {20, 15}, {30, 5}, {34, 5}, {26, 4}, {18, 8}});
  double weight = 0.0;
  for (const slope::Slice& s : mass.slices) weight += s.weight;
  CHECK(weight == Approx(18e3 * area).epsilon(1e-12));
  CHECK(mass.direction == 1);
  CHECK(mass.entry.x == 8.0);
  CHECK(mass.exit.x == 34.0);
  CHECK(mass.surface.size() == 4);
}

TEST_CASE("a polyline that is not an admissible slip surface is refused with the reason") {
  const slope::Section section = wedge_slope();
  const std::vector<std::pair<std::vector<slope::Point>, std::string>> cases{
      {{{8.0, 15.0}}, "at least two points"},
      {{{8.0, 15.0}, {8.0, 10.0}, {30.0, 5.0}}, "increase strictly"},
      {{{8.0, 14.0}, {20.0, 8.0}, {30.0, 5.0}}, "not on the ground surface"},
      {{{8.0, 15.0}, {20.0, 16.0}, {30.0, 5.0}}, "not below the ground"},
      {{{8.0, 15.0}, {20.0, -1.0}, {34.0, 5.0}}, "below the rigid base"},
      {{{8.0, 15.0}, {14.0, 13.0}, {22.0, 4.5}, {34.0, 5.0}}, "convex"},
      {{{-1.0, 15.0}, {30.0, 5.0}}, "beyond the section"},
      {{{10.0, 15.0}, {31.0, 4.9}, {40.0, 5.0}}, "dips below the slip surface"},
  };
  for (const auto& [points, expected] : cases) {
    slope::SlipPolyline surface;
    surface.points = points;
    std::string reason;
    const auto mass = slope::slice_polyline(section, surface, slope::SliceOptions{}, &reason);
    INFO("expected: " << expected);
    CHECK_FALSE(mass.has_value());
    CHECK_THAT(reason, Contains(expected));
  }
}

TEST_CASE("Spencer and Morgenstern-Price on a polyline do not depend on the moment point") {
  // Both satisfy force and moment equilibrium: the moment of a system of forces in equilibrium vanishes about any
  // point, so their factor of safety is the same whatever point the moments are taken about (Fredlund & Krahn 1977).
  // Bishop satisfies moment equilibrium only and does depend on it.
  const slope::Section section = wedge_slope();
  slope::SlipPolyline surface;
  surface.points = {{8.0, 15.0}, {18.0, 8.0}, {26.0, 4.0}, {34.0, 5.0}};
  const slope::SlipMass automatic = sliced(section, surface);
  surface.moment_point = slope::Point{40.0, 40.0};
  const slope::SlipMass far = sliced(section, surface);
  for (slope::Method m : {slope::Method::spencer, slope::Method::morgenstern_price}) {
    INFO(slope::method_key(m));
    CHECK(fs(far, m) == Approx(fs(automatic, m)).epsilon(1e-8));
  }
  CHECK(std::fabs(fs(far, slope::Method::bishop) - fs(automatic, slope::Method::bishop)) > 1e-4);
}

TEST_CASE("a mirrored section and surface give the same factor of safety with every method") {
  const slope::Section section = wedge_slope();
  slope::SlipPolyline surface;
  surface.points = {{8.0, 15.0}, {18.0, 8.0}, {26.0, 4.0}, {34.0, 5.0}};
  slope::SlipPolyline mirror;
  for (auto it = surface.points.rbegin(); it != surface.points.rend(); ++it) mirror.points.push_back({-it->x, it->y});
  const slope::SlipMass a = sliced(section, surface);
  const slope::SlipMass b = sliced(mirrored(section), mirror);
  CHECK(b.direction == -1);
  for (slope::Method m : slope::all_methods()) {
    INFO(slope::method_key(m));
    CHECK(fs(b, m) == Approx(fs(a, m)).epsilon(1e-9));
  }
}

TEST_CASE("a planar surface: every force-equilibrium method gives the sliding-wedge formula", "[validation]") {
  // Reference: the rigid wedge on a plane (e.g. Duncan & Wright 2005, Soil Strength and Slope Stability, the
  // single-plane analysis). Whole-mass equilibrium along and normal to the plane of inclination a and length L:
  // S = W sin a, N = W cos a, and with S = (c' L + N tan phi') / F,
  //     F = (c' L + W cos a tan phi') / (W sin a).
  // Janbu (zero interslice shear) and Spencer / Morgenstern-Price (any interslice inclination) satisfy the
  // horizontal and vertical equilibrium of every slice, hence of the wedge; with one base inclination these give F
  // exactly, whatever the interslice forces. Tolerance 1e-7 relative: the solvers stop at residuals of 1e-10.
  const slope::Section section = wedge_slope();
  double worst = 0.0;
  for (const double entry_x : {4.0, 10.0, 16.0}) {
    for (const int vertices : {2, 5}) {
      slope::SlipPolyline surface;
      for (int k = 0; k < vertices; ++k) {
        const double f = static_cast<double>(k) / (vertices - 1);
        surface.points.push_back({entry_x + f * (30.0 - entry_x), 15.0 - f * 10.0});
      }
      const slope::SlipMass mass = sliced(section, surface);
      const double W = 18e3 * polygon_area({{entry_x, 15.0}, {20.0, 15.0}, {30.0, 5.0}});
      const double L = std::hypot(30.0 - entry_x, 10.0);
      const double a = std::atan2(10.0, 30.0 - entry_x);
      const double expected = (10e3 * L + W * std::cos(a) * std::tan(radians(25.0))) / (W * std::sin(a));
      for (slope::Method m : force_methods) {
        INFO(slope::method_key(m) << " entry x = " << entry_x << ", " << vertices << " vertices");
        const double value = fs(mass, m);
        worst = std::max(worst, std::fabs(value / expected - 1.0));
        CHECK(value == Approx(expected).epsilon(1e-7));
      }
    }
  }
  std::printf("planar surface: largest relative difference from the wedge formula %.2e\n", worst);
}

TEST_CASE("a polyline inscribed in a circle converges to the circle's factor of safety", "[validation]") {
  // Reference: the circle itself (slice_circle), sliced finely (1000 slices) on both sides so that only the shape
  // of the surface differs. The inscribed polygon departs from the arc by its sagitta R (1 - cos(dt/2)) ~ R dt^2/8,
  // so the error should fall about fourfold per doubling of the vertices; required: it falls at every doubling and
  // is below 0.5 % at 64 vertices. Moments of the polyline are about its default point, the centre of the circle
  // through the entry, the exit and the deepest vertex: the circle's own centre.
  const slope::Section section = griffiths_lane_1999();
  const slope::Circle circle{28.0, 32.0, 22.5};
  std::string reason;
  const auto circle_mass = slope::slice_circle(section, circle, slope::SliceOptions{1000}, &reason);
  INFO(reason);
  REQUIRE(circle_mass.has_value());
  const double t0 = std::atan2(circle_mass->entry.x - circle.xc, circle.yc - circle_mass->entry.y);
  const double t1 = std::atan2(circle_mass->exit.x - circle.xc, circle.yc - circle_mass->exit.y);
  for (slope::Method m : slope::all_methods()) {
    const double reference = fs(*circle_mass, m);
    double previous = 1.0;
    for (const int n : {8, 16, 32, 64}) {
      slope::SlipPolyline surface;
      for (int k = 0; k <= n; ++k) {
        const double t = t0 + (t1 - t0) * k / n;
        surface.points.push_back({circle.xc + circle.radius * std::sin(t), circle.yc - circle.radius * std::cos(t)});
      }
      surface.points.front() = circle_mass->entry;
      surface.points.back() = circle_mass->exit;
      const double error = std::fabs(fs(sliced(section, surface, 1000), m) / reference - 1.0);
      std::printf("inscribed polyline: %-27s %2d segments: relative error %.3e\n",
                  std::string(slope::method_key(m)).c_str(), n, error);
      INFO(slope::method_key(m) << ", " << n << " segments: relative error " << error);
      CHECK(error < previous);
      previous = error;
    }
    CHECK(previous < 0.005);
  }
}

}  // namespace test_lem_polyline
