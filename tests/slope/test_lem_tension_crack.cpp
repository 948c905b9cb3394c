// Tension cracks at the upper end of a polyline slip surface: depth, geometry and the effect on the factor of safety
// against hand calculations; the method traps on polylines.
#include <catch2/catch.hpp>

#include <cmath>

#include "lem_sections.hpp"
#include "slope/methods.hpp"
#include "slope/slices.hpp"

namespace test_lem_tension_crack {

using Catch::Matchers::Contains;
using namespace lem_test;

namespace {

// As in test_lem_polyline.cpp: crest at y = 15 from x = 0 to 20, a 45 degree face to the toe at (30, 5), level
// ground to x = 50, rigid base at y = 0; gamma = 18 kN/m^3, c' = 10 kPa, phi' = 25 deg, dry.
slope::Section wedge_slope() { return simple_slope(10.0, 45.0, 20.0, 20.0, 5.0, material("soil", 18.0, 10.0, 25.0)); }

// The plane from (10, 15) on the crest to the toe (30, 5): inclination a = atan(10/20) = 26.565 deg.
slope::SlipPolyline plane_with_crack(std::optional<double> depth, bool water_filled) {
  slope::SlipPolyline surface;
  surface.points = {{10.0, 15.0}, {30.0, 5.0}};
  surface.tension_crack = slope::TensionCrack{depth, water_filled};
  return surface;
}

slope::SlipMass sliced(const slope::SlipPolyline& surface) {
  std::string reason;
  const auto mass = slope::slice_polyline(wedge_slope(), surface, slope::SliceOptions{}, &reason);
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

const std::vector<slope::Method> force_methods{slope::Method::janbu, slope::Method::spencer,
                                               slope::Method::morgenstern_price,
                                               slope::Method::morgenstern_price_constant};

}  // namespace

TEST_CASE("the Rankine tension-crack depth matches the hand calculation", "[validation]") {
  // Hand calculation: c' = 10 kPa, phi' = 25 deg, gamma = 18 kN/m^3: Ka = tan^2(45 - 12.5 deg) = tan^2(32.5 deg)
  // = 0.63707^2 = 0.40586, z_c = 2 c' / (gamma sqrt(Ka)) = 20 / (18 x 0.63707) = 1.7441 m (4 decimals: 1e-4).
  CHECK(slope::rankine_crack_depth(material("soil", 18.0, 10.0, 25.0)) == Approx(1.7441).margin(1e-4));
  // phi' = 0: Ka = 1, z_c = 2 c' / gamma = 20 / 18 = 1.1111 m; c' = 0: no crack.
  CHECK(slope::rankine_crack_depth(material("clay", 18.0, 10.0, 0.0)) == Approx(1.1111).margin(1e-4));
  CHECK(slope::rankine_crack_depth(material("sand", 18.0, 0.0, 30.0)) == 0.0);
  // Asked for by the surface: the crack stands where the plane lies z_c below the crest, x = 10 + 2 z_c.
  const slope::SlipMass mass = sliced(plane_with_crack(std::nullopt, false));
  CHECK(mass.crack_depth == Approx(1.7441).margin(1e-4));
  CHECK(mass.entry.x == Approx(10.0 + 2.0 * 1.7441).margin(2e-4));
  CHECK(mass.entry.y == Approx(15.0));
}

TEST_CASE("a planar wedge with a dry or water-filled tension crack matches the hand calculation", "[validation]") {
  // Hand calculation. Plane from (10, 15) to (30, 5), a = 26.565 deg (sin a = 0.44721, cos a = 0.89443), crack
  // z = 2 m deep: the plane lies 2 m below the crest at x = 14, so the crack runs from (14, 15) to (14, 13).
  //   mass: triangle (10,15)-(20,15)-(30,5) of 50 m^2 less the triangle (10,15)-(14,15)-(14,13) of 4 m^2 = 46 m^2,
  //         W = 18 x 46 = 828 kN/m; base from (14, 13) to (30, 5): L = sqrt(16^2 + 8^2) = 17.889 m.
  //   dry:  F = (c' L + W cos a tan phi') / (W sin a) = (178.89 + 828 x 0.89443 x 0.46631) / (828 x 0.44721)
  //           = (178.89 + 345.34) / 370.29 = 1.4157
  //   water-filled: P = gw z^2 / 2 = 9.81 x 4 / 2 = 19.62 kN/m horizontal toward the toe; along and normal to the
  //         plane S = W sin a + P cos a = 370.29 + 17.549 = 387.84, N = W cos a - P sin a = 740.59 - 8.774 = 731.82;
  //         F = (c' L + N tan phi') / S = (178.89 + 341.25) / 387.84 = 1.3411.
  // The force-equilibrium methods give these exactly (one base inclination; see the wedge test without crack).
  // Tolerance 1e-4 relative: the hand values are rounded to 5 digits.
  const slope::SlipMass dry = sliced(plane_with_crack(2.0, false));
  CHECK(dry.crack_depth == 2.0);
  CHECK(dry.entry.x == Approx(14.0));
  CHECK(dry.crack_water_force == 0.0);
  double weight = 0.0;
  for (const slope::Slice& s : dry.slices) weight += s.weight;
  CHECK(weight == Approx(828e3).epsilon(1e-12));
  const slope::SlipMass wet = sliced(plane_with_crack(2.0, true));
  CHECK(wet.crack_water_force == Approx(19.62e3).epsilon(1e-12));
  CHECK(wet.crack_water_force_y == Approx(13.0 + 2.0 / 3.0).epsilon(1e-12));
  for (slope::Method m : force_methods) {
    INFO(slope::method_key(m));
    CHECK(fs(dry, m) == Approx(1.4157).epsilon(1e-4));
    CHECK(fs(wet, m) == Approx(1.3411).epsilon(1e-4));
  }
  // Bishop and Ordinary take moments: water in the crack lowers their factor of safety too.
  for (slope::Method m : {slope::Method::ordinary, slope::Method::bishop}) {
    INFO(slope::method_key(m));
    CHECK(fs(wet, m) < fs(dry, m));
  }
}

TEST_CASE("a tension crack deeper than the mass is refused with the reason") {
  std::string reason;
  const auto mass = slope::slice_polyline(wedge_slope(), plane_with_crack(12.0, false), {}, &reason);
  CHECK_FALSE(mass.has_value());
  CHECK_THAT(reason, Contains("nowhere that deep"));
}

TEST_CASE("the method traps work on polylines: m_alpha below 0.2 on a steeply rising exit segment") {
  // The exit segment rises at 80 deg to the toe ground: cos a = 0.174, so m_alpha = cos a + sin a tan(phi') / F
  // < 0.2 whatever F (Whitman & Bailey 1967), as on a circle: Bishop and Janbu refuse the surface with the reason.
  slope::SlipPolyline surface;
  const double foot = 31.0 - 4.0 / std::tan(radians(80.0));
  surface.points = {{6.0, 15.0}, {foot, 1.0}, {31.0, 5.0}};
  surface.moment_point = slope::Point{26.0, 30.0};  // downslope of the mass's centre: the weight drives
  std::string reason;
  const auto mass = slope::slice_polyline(wedge_slope(), surface, {}, &reason);
  INFO(reason);
  REQUIRE(mass.has_value());
  for (slope::Method m : {slope::Method::bishop, slope::Method::janbu}) {
    const slope::FsResult r = slope::factor_of_safety(*mass, m);
    CHECK_FALSE(r.factor_of_safety.has_value());
    CHECK_THAT(r.error, Contains("m_alpha") && Contains("below 0.2"));
  }
}

TEST_CASE("a circle carries a tension crack as an inscribed polyline, the crack where the arc lies z below the crest",
          "[validation]") {
  // Griffiths & Lane slope (crest at y = 20 for x <= 20) and the circle (28, 32), R = 22.5. Closed form: the arc
  // lies z = 2 m below the crest where 32 - sqrt(R^2 - (x - 28)^2) = 18, i.e. x = 28 - sqrt(506.25 - 196)
  // = 10.3862 m. The inscribed polygon of 256 chords departs from the arc by its sagitta R dt^2 / 8 < 1e-4 m:
  // tolerance 1e-3 m. Without a crack its factor of safety equals the circle's (1000 slices both) to 1e-4.
  const slope::Section section = griffiths_lane_1999();
  const slope::Circle circle{28.0, 32.0, 22.5};
  std::string reason;
  auto polyline = slope::circle_as_polyline(section, circle, 256, &reason);
  INFO(reason);
  REQUIRE(polyline.has_value());
  const auto plain = slope::slice_polyline(section, *polyline, slope::SliceOptions{1000}, &reason);
  const auto arc = slope::slice_circle(section, circle, slope::SliceOptions{1000}, &reason);
  REQUIRE(plain.has_value());
  REQUIRE(arc.has_value());
  for (slope::Method m : {slope::Method::bishop, slope::Method::spencer}) {
    INFO(slope::method_key(m));
    CHECK(fs(*plain, m) == Approx(fs(*arc, m)).epsilon(1e-4));
  }
  polyline->tension_crack = slope::TensionCrack{2.0, false};
  const auto dry = slope::slice_polyline(section, *polyline, slope::SliceOptions{}, &reason);
  REQUIRE(dry.has_value());
  CHECK(dry->entry.x == Approx(28.0 - std::sqrt(22.5 * 22.5 - 14.0 * 14.0)).margin(1e-3));
  CHECK(dry->crack_depth == 2.0);
  polyline->tension_crack->water_filled = true;
  const auto wet = slope::slice_polyline(section, *polyline, slope::SliceOptions{}, &reason);
  REQUIRE(wet.has_value());
  // Water in the crack pushes the mass toward its exit: a lower factor of safety. (Spencer refuses this surface
  // with the crack: its root needs tension on the base of the steep slice next to the crack.)
  for (slope::Method m : {slope::Method::janbu, slope::Method::bishop}) {
    INFO(slope::method_key(m));
    CHECK(fs(*wet, m) < fs(*dry, m));
  }
  const slope::FsResult spencer = slope::factor_of_safety(*wet, slope::Method::spencer);
  CHECK_FALSE(spencer.factor_of_safety);  // refused, never a number
  CHECK_FALSE(spencer.error.empty());
}

}  // namespace test_lem_tension_crack
