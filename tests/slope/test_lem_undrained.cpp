// Cohesion increasing with depth (Material::cohesion_rate): an undrained strength Su = Su0 + rate * z for phi = 0
// clays, with z below a horizontal datum or below the material's own top, and an optional cap. A closed form for the
// strength on a circle, the datum and layer-top forms against each other, the cap, the section's checks, and
// Duncan & Wright's Fig. 14.20-b embankment on a clay whose strength grows with depth.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "lem_checks.hpp"
#include "lem_sections.hpp"
#include "slope/methods.hpp"
#include "slope/search.hpp"
#include "slope/slices.hpp"

namespace test_lem_undrained {

using namespace lem_test;

namespace {

// A phi = 0 clay: Su0 kPa at the datum or top, rising by rate kPa/m.
slope::Material clay(double su0_kPa, double rate_kPa_m) {
  slope::Material m = material("clay", 18.0, su0_kPa, 0.0);
  m.cohesion_rate = rate_kPa_m * 1e3;
  return m;
}

}  // namespace

TEST_CASE("Su rising below a datum: the factor of safety on a circle against the strength integrated along the arc",
          "[slope][closed_form][undrained]") {
  // For phi = 0 every method's circle FS is R * (integral of c along the arc) / (driving moment), and the driving
  // moment does not depend on the strength. So FS(rate) / FS(0) = integral of (Su0 + rate (d - y)) ds / (Su0 L):
  // with x = xc + R sin t, y = yc - R cos t along the arc from t1 to t2, the integral of (d - y) ds is
  // R (d - yc) (t2 - t1) + R^2 (sin t2 - sin t1), and L = R (t2 - t1). The slices take c at each base's midpoint
  // on its chord (the midpoint rule on 200 slices: a relative error of about 1e-5 here).
  const slope::Circle circle{30.0, 25.0, 18.0};
  const double datum = 22.0;  // above the whole section: z = datum - y everywhere
  slope::Section s = simple_slope(10.0, 30.0, 20.0, 30.0, 5.0, clay(20.0, 0.0));
  slope::SliceOptions fine;
  fine.slices = 200;
  const auto uniform = slope::slice_circle(s, circle, fine);
  REQUIRE(uniform);
  s.materials[0] = clay(20.0, 3.0);
  s.materials[0].cohesion_datum_y = datum;
  const auto rising = slope::slice_circle(s, circle, fine);
  REQUIRE(rising);
  const double xc = circle.xc, yc = circle.yc, R = circle.radius;
  const double ta = std::asin((std::min(rising->entry.x, rising->exit.x) - xc) / R);
  const double tb = std::asin((std::max(rising->entry.x, rising->exit.x) - xc) / R);
  const double depth_integral = R * (datum - yc) * (tb - ta) + R * R * (std::sin(tb) - std::sin(ta));
  const double expected = 1.0 + 3.0 * depth_integral / (20.0 * R * (tb - ta));
  INFO("expected FS ratio " << expected);
  for (slope::Method m : {slope::Method::ordinary, slope::Method::bishop, slope::Method::spencer}) {
    INFO(slope::method_key(m));
    CHECK(fs_on(*rising, m) / fs_on(*uniform, m) == Approx(expected).epsilon(1e-4));
  }
}

TEST_CASE("Su below the layer's own top equals Su below a datum at that top, and a cap at Su0 gives a uniform clay",
          "[slope][undrained]") {
  // A sand embankment on a clay whose top is level at y = 10: measured from the layer top or from the datum
  // y = 10, every base has the same depth, so the slices and the factors of safety are the same to the last bit.
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials = {material("sand", 19.0, 0.0, 34.0), clay(15.0, 2.0)};
  s.profile_lines.push_back(slope::ProfileLine{0, {{0, 16}, {20, 16}, {32, 10}, {60, 10}}});
  s.profile_lines.push_back(slope::ProfileLine{1, {{0, 10}, {60, 10}}});
  const slope::Circle circle{30.0, 24.0, 19.0};
  const auto from_top = slope::slice_circle(s, circle, slope::SliceOptions{});
  REQUIRE(from_top);
  s.materials[1].cohesion_datum_y = 10.0;
  const auto from_datum = slope::slice_circle(s, circle, slope::SliceOptions{});
  REQUIRE(from_datum);
  bool deeper_is_stronger = false;
  REQUIRE(from_top->slices.size() == from_datum->slices.size());
  for (std::size_t i = 0; i < from_top->slices.size(); ++i) {
    const slope::Slice& a = from_top->slices[i];
    CHECK(a.cohesion == from_datum->slices[i].cohesion);
    if (a.base_material == 1) {
      CHECK(a.cohesion == Approx(15e3 + 2e3 * (10.0 - a.base_y)).epsilon(1e-12));
      deeper_is_stronger = deeper_is_stronger || a.cohesion > 16e3;
    }
  }
  CHECK(deeper_is_stronger);
  for (slope::Method m : {slope::Method::bishop, slope::Method::spencer})
    CHECK(fs_on(*from_top, m) == fs_on(*from_datum, m));

  // Capped at Su0 the clay is uniform: the same as no increase at all.
  s.materials[1].cohesion_max = 15e3;
  const auto capped = slope::slice_circle(s, circle, slope::SliceOptions{});
  s.materials[1] = clay(15.0, 0.0);
  const auto uniform = slope::slice_circle(s, circle, slope::SliceOptions{});
  REQUIRE(capped);
  REQUIRE(uniform);
  CHECK(fs_on(*capped, slope::Method::bishop) == fs_on(*uniform, slope::Method::bishop));
  CHECK(fs_on(*capped, slope::Method::bishop) < fs_on(*from_top, slope::Method::bishop));
}

TEST_CASE("a section with a negative cohesion rate, a cap below the cohesion or a non-finite datum is refused",
          "[slope][undrained]") {
  slope::Section s = simple_slope(10.0, 30.0, 20.0, 30.0, 5.0, clay(20.0, 1.0));
  CHECK(slope::section_error(s).empty());
  s.materials[0].cohesion_rate = -1.0;
  CHECK(slope::section_error(s).find("cohesion rate") != std::string::npos);
  s.materials[0] = clay(20.0, 1.0);
  s.materials[0].cohesion_max = 19e3;
  CHECK(slope::section_error(s).find("maximum cohesion") != std::string::npos);
  s.materials[0] = clay(20.0, 1.0);
  s.materials[0].cohesion_datum_y = std::nan("");
  CHECK(slope::section_error(s).find("datum") != std::string::npos);
}

TEST_CASE("Duncan & Wright Fig. 14.20-b: an embankment on clay with Su = 200 + 15 z psf, and with Su = 300 psf",
          "[slope][published][undrained][validation]") {
  // Duncan & Wright (2005), Soil Strength and Slope Stability, Fig. 14.20-b; Rocscience Slide verification
  // problem #83 (the data as the xslope project transcribed them, benchmarks/rocscience/build_problems.py,
  // _vp083_slope_data). In its own units (ft, pcf, psf): ground (0,40)-(55,40)-(75,30)-(140,30), embankment
  // above y = 30 (c' = 0, phi' = 36 deg, gamma = 123 pcf) on a clay foundation from y = 30 down to the base at
  // y = 0 (phi = 0, gamma = 97 pcf); no water. Profile I: Su = 200 + 15 z psf, z below the foundation's top;
  // profile II: Su = 300 psf. Circular search. Reference values: profile I Slide Bishop 1.313, Spencer 1.285
  // (D&W 1.300, the average of their methods); profile II Slide Bishop 1.335, Spencer 1.330 (D&W 1.312).
  // xslope finds 1.305 / 1.275 and 1.328 / 1.326: tolerances of 1 % against Slide (measured
  // 2026-11-28: 1.306 / 1.277 and 1.330 / 1.328).
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials = {material("embankment", 123.0e-3, 0.0, 36.0), material("foundation", 97.0e-3, 200e-3, 0.0)};
  s.materials[1].cohesion_rate = 15.0;
  s.profile_lines.push_back(slope::ProfileLine{0, {{0, 40}, {55, 40}, {75, 30}, {140, 30}}});
  s.profile_lines.push_back(slope::ProfileLine{1, {{0, 30}, {140, 30}}});
  const std::vector<slope::Method> methods{slope::Method::bishop, slope::Method::spencer};
  const slope::SearchResult rising = slope::search_critical(s, methods, slope::SearchOptions{});
  CHECK(searched(rising, slope::Method::bishop) == Approx(1.313).epsilon(0.01));
  CHECK(searched(rising, slope::Method::spencer) == Approx(1.285).epsilon(0.01));
  s.materials[1] = material("foundation", 97.0e-3, 300e-3, 0.0);
  const slope::SearchResult constant = slope::search_critical(s, methods, slope::SearchOptions{});
  CHECK(searched(constant, slope::Method::bishop) == Approx(1.335).epsilon(0.01));
  CHECK(searched(constant, slope::Method::spencer) == Approx(1.330).epsilon(0.01));
}

}  // namespace test_lem_undrained
