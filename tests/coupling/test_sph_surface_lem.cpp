// The SPH failure surface as a limit-equilibrium slip surface (coupling/compare/sph_surface_lem.hpp).
#include <catch2/catch.hpp>

#include <cmath>

#include "coupling/compare/sph_surface_lem.hpp"
#include "slope/methods.hpp"

namespace test_sph_surface_lem {

namespace {

constexpr double degree = M_PI / 180.0;

// Crest at y = 15 from x = 0 to 20, a 45 degree face to the toe at (30, 5), level ground to x = 50, rigid base at
// y = 0; gamma = 18 kN/m^3, c' = 10 kPa, phi' = 25 deg.
slope::Section wedge_slope() {
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials.push_back(slope::Material{"soil", 18e3, 10e3, 25.0 * degree});
  s.profile_lines.push_back(slope::ProfileLine{0, {{0, 15}, {20, 15}, {30, 5}, {50, 5}}});
  return s;
}

// A band read out of an SPH run that lies on the plane from (6, 15) to the toe (30, 5), one point per 2 m bin from
// x = 8 to 30; its upper end carried vertically up to the crest at x = 8 (an open scarp 0.833 m deep).
coupling::SphFailure planar_band() {
  coupling::SphFailure sph;
  auto plane = [](double x) { return 15.0 - (x - 6.0) * 10.0 / 24.0; };
  for (double x = 8.0; x <= 30.0 + 1e-9; x += 2.0) sph.band.points.push_back({x, plane(x)});
  sph.band.bin_width = 2.0;
  sph.entry = slope::Point{8.0, 15.0};
  sph.exit = slope::Point{30.0, 5.0};
  return sph;
}

}  // namespace

TEST_CASE("the SPH band as an LE surface: its scarp is a tension crack and a planar band gives the wedge formula",
          "[validation]") {
  // Reference: the sliding wedge with a tension crack (tests/slope/test_lem_tension_crack.cpp). The band's vertical
  // step at x = 8 becomes a dry crack of depth z = 15 - (15 - 2 x 10/24) = 0.8333 m; below it the mass slides on the
  // plane a = atan(10/24) from (8, 14.1667) to the toe (30, 5): L = sqrt(22^2 + 9.1667^2) = 23.833 m, and the mass
  // is the polygon (8,15)-(20,15)-(30,5)-(8,14.1667) (shoelace below). The force-equilibrium methods give
  // F = (c' L + W cos a tan phi') / (W sin a) to their solver tolerance (1e-7 relative).
  const slope::Section section = wedge_slope();
  const coupling::SphSurfaceForLem surface = coupling::sph_surface_for_lem(section, planar_band());
  INFO(surface.reason);
  REQUIRE(surface.mass.has_value());
  const slope::SlipMass& mass = *surface.mass;
  const double z = 20.0 / 24.0;
  CHECK(mass.crack_depth == Approx(z).epsilon(1e-12));
  CHECK(mass.entry.x == Approx(8.0).epsilon(1e-9));
  CHECK(mass.exit.x == 30.0);
  CHECK(surface.scarp_angle == Approx((45.0 + 12.5) * degree));
  const std::vector<slope::Point> polygon{{8, 15}, {20, 15}, {30, 5}, {8, 15 - z}};
  double twice = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const slope::Point& a = polygon[k];
    const slope::Point& b = polygon[(k + 1) % polygon.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  const double W = 18e3 * 0.5 * std::fabs(twice);
  const double L = std::hypot(22.0, 10.0 - z);
  const double a = std::atan2(10.0, 24.0);
  const double expected = (10e3 * L + W * std::cos(a) * std::tan(25.0 * degree)) / (W * std::sin(a));
  for (slope::Method m : {slope::Method::janbu, slope::Method::spencer, slope::Method::morgenstern_price}) {
    const slope::FsResult r = slope::factor_of_safety(mass, m);
    INFO(slope::method_key(m) << ": " << r.error);
    REQUIRE(r.factor_of_safety.has_value());
    CHECK(*r.factor_of_safety == Approx(expected).epsilon(1e-7));
  }
}

TEST_CASE("the SPH band as an LE surface: no band ends, no surface, with the reason") {
  coupling::SphFailure sph = planar_band();
  sph.entry.reset();
  const coupling::SphSurfaceForLem surface = coupling::sph_surface_for_lem(wedge_slope(), sph);
  CHECK_FALSE(surface.mass.has_value());
  CHECK(surface.reason.find("no entry and exit") != std::string::npos);
}

TEST_CASE("the SPH band as an LE surface: a spike of the band that turns it back on itself is dropped",
          "[compare]") {
  // The planar band with its x = 20 point 8 m too low (1.17 m): the surface would fall at 77 deg, rise at 74 deg and
  // fall again, a turn of 97 deg at x = 22 that no mass of rigid slices can follow (the slicer accepts up to 90).
  // The spike goes; what is left lies on the plane, so every method gives what it gives on the clean band.
  const slope::Section section = wedge_slope();
  coupling::SphFailure spiked = planar_band();
  for (slope::Point& p : spiked.band.points)
    if (std::fabs(p.x - 20.0) < 1e-9) p.y -= 8.0;
  const coupling::SphSurfaceForLem clean = coupling::sph_surface_for_lem(section, planar_band());
  const coupling::SphSurfaceForLem fixed = coupling::sph_surface_for_lem(section, spiked);
  INFO(fixed.reason);
  REQUIRE(clean.mass.has_value());
  REQUIRE(fixed.mass.has_value());
  CHECK(clean.dropped_vertices == 0);
  CHECK(fixed.dropped_vertices == 1);
  for (slope::Method m : {slope::Method::spencer, slope::Method::janbu, slope::Method::morgenstern_price}) {
    INFO(slope::method_key(m));
    const auto a = slope::factor_of_safety(*clean.mass, m).factor_of_safety;
    const auto b = slope::factor_of_safety(*fixed.mass, m).factor_of_safety;
    REQUIRE(a);
    REQUIRE(b);
    CHECK(*b == Approx(*a).epsilon(1e-9));
  }
  // A milder dip (3 m: turns of at most 70 deg) is a convex kink the methods accept: kept, as the SPH model found it.
  coupling::SphFailure dipped = planar_band();
  for (slope::Point& p : dipped.band.points)
    if (std::fabs(p.x - 20.0) < 1e-9) p.y -= 3.0;
  const coupling::SphSurfaceForLem kept = coupling::sph_surface_for_lem(section, dipped);
  INFO(kept.reason);
  REQUIRE(kept.mass.has_value());
  CHECK(kept.dropped_vertices == 0);
}

}  // namespace test_sph_surface_lem
