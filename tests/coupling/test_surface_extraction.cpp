// Failure-surface extraction and surface comparison on synthetic data with known answers.
#include <catch2/catch.hpp>

#include <cmath>

#include "coupling/compare/failure_surface.hpp"
#include "coupling/compare/sliding_mass.hpp"
#include "coupling/compare/surface_comparison.hpp"

namespace test_surface_extraction {

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// A 2:1... lattice of particles filling a 40 m x 20 m block (spacing 0.25 m), with accumulated plastic strain
// 0.5 inside a band of half-width `half_width` around a circle and 0.01 elsewhere.
coupling::ParticleSnapshot block_with_circular_band(const slope::Circle& circle, double half_width) {
  coupling::ParticleSnapshot p;
  p.spacing = 0.25;
  for (int i = 0; i < 160; ++i)
    for (int j = 0; j < 80; ++j) {
      const double x = (i + 0.5) * p.spacing, y = (j + 0.5) * p.spacing;
      const double d = std::abs(std::hypot(x - circle.xc, y - circle.yc) - circle.radius);
      p.x0.push_back(x);
      p.y0.push_back(y);
      p.x.push_back(x + 1.0);  // the current configuration is shifted; the band is read on the initial one
      p.y.push_back(y);
      p.plastic_strain.push_back(d <= half_width && y < circle.yc ? 0.5 : 0.01);
    }
  return p;
}

}  // namespace

TEST_CASE("plastic band extraction recovers a known circular band", "[extraction]") {
  // Closed form: the band is centred on the circle by construction; the fitted circle must recover it to
  // within a quarter of the particle spacing in centre and radius.
  const slope::Circle truth{22.0, 24.0, 16.0};
  const auto particles = block_with_circular_band(truth, 0.6);
  const auto surface = coupling::plastic_band_surface(particles, {});
  REQUIRE(surface.points.size() > 20);
  for (const auto& point : surface.points)
    CHECK(std::abs(std::hypot(point.x - truth.xc, point.y - truth.yc) - truth.radius) < 0.2);
  const auto fit = coupling::fit_circle(surface.points);
  REQUIRE(fit.has_value());
  CHECK_THAT(fit->circle.xc, WithinAbs(truth.xc, 0.0625));
  CHECK_THAT(fit->circle.yc, WithinAbs(truth.yc, 0.0625));
  CHECK_THAT(fit->circle.radius, WithinAbs(truth.radius, 0.0625));
  CHECK(fit->rms_residual < 0.1);
}

TEST_CASE("band extraction keeps the deepest band and ignores strain near the surface", "[extraction]") {
  const slope::Circle truth{20.0, 30.0, 22.0};
  auto particles = block_with_circular_band(truth, 0.6);
  // A second plastic zone in the top metre (a crest tension zone, say) must not pull the centre line up.
  for (std::size_t i = 0; i < particles.y0.size(); ++i)
    if (particles.y0[i] > 19.0) particles.plastic_strain[i] = 1.0;
  const auto surface = coupling::plastic_band_surface(particles, {});
  const auto fit = coupling::fit_circle(surface.points);
  REQUIRE(fit.has_value());
  CHECK_THAT(fit->circle.radius, WithinAbs(truth.radius, 0.1));
}

TEST_CASE("circle fit is exact on points of a circle and refuses collinear points", "[extraction]") {
  std::vector<slope::Point> arc;
  for (int k = 0; k < 30; ++k) {
    const double t = -2.5 + 0.05 * k;
    arc.push_back({3.0 + 7.0 * std::cos(t), -1.0 + 7.0 * std::sin(t)});
  }
  const auto fit = coupling::fit_circle(arc);
  REQUIRE(fit.has_value());
  CHECK_THAT(fit->circle.xc, WithinAbs(3.0, 1e-9));
  CHECK_THAT(fit->circle.yc, WithinAbs(-1.0, 1e-9));
  CHECK_THAT(fit->circle.radius, WithinAbs(7.0, 1e-9));
  CHECK_FALSE(coupling::fit_circle({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).has_value());
}

TEST_CASE("surface comparison: parallel lines and crossing lines give known distances and areas", "[comparison]") {
  // Two parallel lines 1 m apart over x in [0, 10]: distance 1 everywhere, area 10 m^2.
  const coupling::Polyline low{{0, 0}, {10, 0}}, high{{0, 1}, {10, 1}};
  const auto d = coupling::compare_surfaces(high, low);
  CHECK_THAT(d.mean_normal_distance, WithinAbs(1.0, 1e-12));
  CHECK_THAT(d.max_normal_distance, WithinAbs(1.0, 1e-12));
  CHECK_THAT(d.area_between, WithinAbs(10.0, 1e-12));
  // y = x - 5 against y = 0 on [0, 10]: two triangles of area 12.5 each; on the common span [2, 10] of a
  // shorter first curve, the triangles are 4.5 and 12.5.
  const coupling::Polyline diagonal{{0, -5}, {10, 5}}, diagonal_short{{2, -3}, {10, 5}};
  CHECK_THAT(coupling::compare_surfaces(diagonal, low).area_between, WithinAbs(25.0, 1e-12));
  const auto s = coupling::compare_surfaces(diagonal_short, low);
  CHECK_THAT(s.common_from_x, WithinAbs(2.0, 1e-12));
  CHECK_THAT(s.area_between, WithinAbs(17.0, 1e-12));
  // Normal distance from points of y = x - 5 to y = 0 is |y| (the nearest point is straight below).
  CHECK_THAT(s.max_normal_distance, WithinAbs(5.0, 1e-12));
}

TEST_CASE("circle arcs: concentric arcs are the radius difference apart", "[comparison]") {
  const slope::Circle inner{0.0, 10.0, 8.0}, outer{0.0, 10.0, 9.0};
  const auto a = coupling::circle_arc(inner, -5.0, 5.0, 400);
  const auto b = coupling::circle_arc(outer, -6.0, 6.0, 400);
  const auto d = coupling::compare_surfaces(a, b);
  CHECK_THAT(d.mean_normal_distance, WithinAbs(1.0, 2e-3));
  CHECK_THAT(d.max_normal_distance, WithinAbs(1.0, 2e-3));
}


TEST_CASE("sliding-mass polygons and their overlap: squares and a half-disc", "[comparison]") {
  // Two unit squares offset by half a side: intersection 0.5, union 1.5, IoU 1/3 (closed form).
  const coupling::Polyline a{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, b{{0.5, 0}, {1.5, 0}, {1.5, 1}, {0.5, 1}};
  const auto o = coupling::mass_overlap(a, b);
  CHECK_THAT(o.intersection_area, WithinAbs(0.5, 1e-12));
  CHECK_THAT(o.union_area, WithinAbs(1.5, 1e-12));
  CHECK_THAT(o.intersection_over_union, WithinAbs(1.0 / 3.0, 1e-12));
  // Disjoint polygons: IoU 0. The same polygon twice (opposite orientation): IoU 1.
  const coupling::Polyline far{{5, 0}, {6, 0}, {6, 1}};
  CHECK_THAT(coupling::mass_overlap(a, far).intersection_over_union, WithinAbs(0.0, 1e-12));
  const coupling::Polyline reversed(a.rbegin(), a.rend());
  CHECK_THAT(coupling::mass_overlap(a, reversed).intersection_over_union, WithinAbs(1.0, 1e-12));

  // Below flat ground y = 0, the lower half-disc of radius 5 has area pi 25 / 2 (to the polygonisation error).
  const coupling::Polyline ground{{-10, 0}, {10, 0}};
  const auto disc = coupling::sliding_mass_polygon(ground, coupling::circle_arc({0, 0, 5}, -5, 5, 2000));
  CHECK_THAT(coupling::polygon_area(disc), WithinRel(M_PI * 12.5, 1e-4));
}

TEST_CASE("band extraction drops an isolated plastic spot away from the band", "[extraction]") {
  const slope::Circle truth{22.0, 24.0, 16.0};
  auto particles = block_with_circular_band(truth, 0.6);
  // A plastic corner 3 m left of the band's end (as soil rubbing on a wall can give).
  for (std::size_t i = 0; i < particles.x0.size(); ++i)
    if (particles.x0[i] < 1.0 && particles.y0[i] < 1.0) particles.plastic_strain[i] = 0.8;
  const auto surface = coupling::plastic_band_surface(particles, {});
  REQUIRE_FALSE(surface.points.empty());
  CHECK(surface.points.front().x > 5.0);  // the band's left end is at x = 22 - sqrt(16^2 - 4^2) = 6.5 m
  const auto fit = coupling::fit_circle(surface.points);
  REQUIRE(fit.has_value());
  CHECK_THAT(fit->circle.radius, WithinAbs(truth.radius, 0.0625));
}

TEST_CASE("a self-crossing polygon gives no overlap figure rather than zero", "[comparison]") {
  const coupling::Polyline bow_tie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  const coupling::Polyline square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  CHECK(std::isnan(coupling::mass_overlap(bow_tie, square).intersection_over_union));
}

TEST_CASE("the extracted band line is a graph y(x): x increases along it", "[extraction]") {
  const slope::Circle truth{20.0, 21.0, 18.0};  // steep near both ends
  const auto surface = coupling::plastic_band_surface(block_with_circular_band(truth, 1.2), {});
  REQUIRE(surface.points.size() > 10);
  for (std::size_t k = 1; k < surface.points.size(); ++k) CHECK(surface.points[k].x > surface.points[k - 1].x);
}

}  // namespace test_surface_extraction
