// Non-linear strength envelopes (slope/strength.hpp) in limit equilibrium: the Hoek-Brown envelope against its
// own criterion, envelopes that are straight lines against the Mohr-Coulomb material they equal, the fixed point
// of the iteration (every base carries its envelope's strength at its own normal stress), the section's checks,
// and Hammah et al.'s (2005) Hoek-Brown rock slope.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "lem_checks.hpp"
#include "lem_sections.hpp"
#include "slope/methods.hpp"
#include "slope/search.hpp"
#include "slope/slices.hpp"
#include "slope/strength.hpp"

namespace test_lem_strength {

using namespace lem_test;

namespace {

const std::vector<slope::Method> every_method{slope::Method::ordinary,          slope::Method::bishop,
                                              slope::Method::janbu,             slope::Method::janbu_corrected,
                                              slope::Method::spencer,           slope::Method::morgenstern_price,
                                              slope::Method::morgenstern_price_constant};

slope::StrengthEnvelope hoek_brown(double sigma_ci_MPa, double gsi, double mi, double d) {
  slope::StrengthEnvelope e;
  e.kind = slope::StrengthEnvelope::Kind::hoek_brown;
  e.hoek_brown = slope::hoek_brown_from_gsi(sigma_ci_MPa * 1e6, gsi, mi, d);
  return e;
}

// A rock mass of Hammah et al. (2005), Example 1: sigma_ci = 30 MPa, GSI = 5, m_i = 2, D = 0, 25 kN/m^3.
slope::Material hammah_rock() {
  slope::Material m = material("rock mass", 25.0, 0.0, 0.0);
  m.envelope = hoek_brown(30.0, 5.0, 2.0, 0.0);
  return m;
}

}  // namespace

TEST_CASE("Hoek-Brown: m_b, s, a from GSI, and each envelope point lies on a Mohr circle of the criterion",
          "[slope][strength][closed_form]") {
  // Hoek, Carranza-Torres & Corkum (2002), eqs. 2-4, for GSI 5, m_i 2, D 0: m_b = 2 exp(-95/28) = 0.06725,
  // s = exp(-95/9) = 2.6048e-5, a = 1/2 + (exp(-1/3) - exp(-20/3)) / 6 = 0.61921 (Hammah et al. 2005 quote 0.067,
  // 2.5e-5 and 0.619).
  const slope::HoekBrown hb = slope::hoek_brown_from_gsi(30e6, 5.0, 2.0, 0.0);
  CHECK(hb.mb == Approx(2.0 * std::exp(-95.0 / 28.0)).epsilon(1e-14));
  CHECK(hb.mb == Approx(0.06725).epsilon(1e-3));
  CHECK(hb.s == Approx(2.6048e-5).epsilon(1e-4));
  CHECK(hb.a == Approx(0.61921).epsilon(1e-5));
  slope::StrengthEnvelope e;
  e.hoek_brown = hb;
  // The Mohr circle tangent to the envelope at (sigma_n, tau) with slope tan(phi) has its centre at
  // sigma_n + tau tan(phi) and radius tau / cos(phi): its extreme stresses must satisfy the criterion
  // sigma1 = sigma3 + sigma_ci (m_b sigma3 / sigma_ci + s)^a, and the slope must be the envelope's derivative.
  for (double sigma_kPa : {-5.0, 0.0, 10.0, 100.0, 1000.0, 1e4}) {
    INFO("sigma_n = " << sigma_kPa << " kPa");
    const double sigma = sigma_kPa * 1e3;
    const slope::EnvelopePoint p = slope::envelope_at(e, sigma);
    REQUIRE(p.shear > 0.0);
    const double phi = std::atan(p.slope);
    const double centre = sigma + p.shear * p.slope;
    const double radius = p.shear / std::cos(phi);
    const double s1 = centre + radius, s3 = centre - radius;
    CHECK(s1 == Approx(s3 + hb.intact_strength * std::pow(hb.mb * s3 / hb.intact_strength + hb.s, hb.a))
                    .epsilon(1e-9));
    const double h = 1e-4 * (std::fabs(sigma) + 1e3);
    const double derivative = (slope::envelope_at(e, sigma + h).shear - slope::envelope_at(e, sigma - h).shear) / (2 * h);
    CHECK(p.slope == Approx(derivative).epsilon(1e-6));
  }
  // The envelope falls to (nearly) no strength at the tensile strength -s sigma_ci / m_b (it is evaluated from just
  // above it, where its slope is finite, and that tangent extended below).
  const double tensile = -hb.s * hb.intact_strength / hb.mb;
  CHECK(std::fabs(slope::envelope_at(e, tensile).shear) < 1e-3 * slope::envelope_at(e, 0.0).shear);
  CHECK(slope::envelope_at(e, tensile - 1e3).shear < 0.0);
}

TEST_CASE("a tabulated Hoek-Brown envelope gives the root search's strength and slope", "[slope][strength]") {
  // tabulated() (strength.hpp) in place of a root search for each point: the same strength to 1e-11 of
  // |tau| + tau(0) from the tensile strength to 20 sigma_ci (the table ends at sigma3' = 10 sigma_ci, the root search
  // goes on beyond; measured 2026-12-02: below 1e-12, and against a long-double bisection the table is the more
  // accurate of the two next to the tensile strength), the slope to 1e-6 relative away from the tensile strength
  // (measured: 3e-7; the slope only steers the iteration, the strength at its fixed point is the envelope's).
  // Rock masses from very poor (Hammah et al.'s GSI 5) to intact (GSI 100), disturbed and not.
  struct Rock {
    double sigma_ci_MPa, gsi, mi, d;
  };
  for (const Rock& rock : {Rock{30, 5, 2, 0}, Rock{30, 50, 10, 0}, Rock{100, 80, 25, 0.5}, Rock{1, 20, 7, 1},
                           Rock{50, 100, 32, 0}}) {
    const slope::StrengthEnvelope root = hoek_brown(rock.sigma_ci_MPa, rock.gsi, rock.mi, rock.d);
    const slope::StrengthEnvelope table = slope::tabulated(root);
    REQUIRE(table.table != nullptr);
    const slope::HoekBrown& hb = root.hoek_brown;
    const double tensile = -hb.s * hb.intact_strength / hb.mb;
    const double tau0 = slope::envelope_at(root, 0.0).shear;
    double worst_shear = 0.0, worst_slope = 0.0;
    for (int i = 0; i <= 4000; ++i) {
      // from 1e-6 of |tensile| + 1 Pa above the tensile strength to 20 sigma_ci, evenly in the logarithm
      const double span = 20.0 * hb.intact_strength - tensile;
      const double offset = (std::fabs(tensile) + 1.0) * 1e-6;
      const double sigma = tensile + offset * std::pow(span / offset, i / 4000.0);
      const slope::EnvelopePoint a = slope::envelope_at(root, sigma);
      const slope::EnvelopePoint b = slope::envelope_at(table, sigma);
      worst_shear = std::max(worst_shear, std::fabs(a.shear - b.shear) / (std::fabs(a.shear) + tau0));
      if (sigma > tensile + 0.01 * std::fabs(tensile))
        worst_slope = std::max(worst_slope, std::fabs(a.slope - b.slope) / a.slope);
    }
    INFO("sigma_ci " << rock.sigma_ci_MPa << " MPa, GSI " << rock.gsi << ", m_i " << rock.mi << ", D " << rock.d);
    CHECK(worst_shear < 1e-11);
    CHECK(worst_slope < 1e-6);
    // below the least point the tangent there, extended, as the root search does
    CHECK(slope::envelope_at(table, tensile - 1e3).shear ==
          Approx(slope::envelope_at(root, tensile - 1e3).shear).epsilon(1e-6));
  }
  // the other envelopes need no table
  slope::StrengthEnvelope power;
  power.kind = slope::StrengthEnvelope::Kind::power_curve;
  power.power_a = 10.0;
  power.power_b = 0.8;
  CHECK(slope::tabulated(power).table == nullptr);
}

TEST_CASE("straight envelopes (a two-point shear-normal function, a power curve with b = 1) give the Mohr-Coulomb "
          "factors of safety", "[slope][strength]") {
  // tau = 12 kPa + sigma' tan(25 deg) three ways: every method, a circle with water, the same factor of safety.
  slope::Section mc = simple_slope(10.0, 35.0, 20.0, 25.0, 5.0, material("soil", 19.0, 12.0, 25.0));
  mc.water = slope::Water{{{0, 12}, {20, 11}, {34.28, 6}, {60, 6}}};
  const double tan_phi = std::tan(radians(25.0));
  slope::StrengthEnvelope table;
  table.kind = slope::StrengthEnvelope::Kind::shear_normal;
  table.points = {{0.0, 12e3}, {300e3, 12e3 + 300e3 * tan_phi}};
  slope::StrengthEnvelope power;
  power.kind = slope::StrengthEnvelope::Kind::power_curve;
  power.power_a = tan_phi;
  power.power_b = 1.0;
  power.power_c = 12e3;
  const slope::Circle circle{30.0, 26.0, 21.0};
  const auto reference = slope::slice_circle(mc, circle, slope::SliceOptions{});
  REQUIRE(reference);
  for (const slope::StrengthEnvelope& envelope : {table, power}) {
    slope::Section s = mc;
    s.materials[0] = material("soil", 19.0, 0.0, 0.0);  // the envelope, not these, gives the strength
    s.materials[0].envelope = envelope;
    REQUIRE(slope::section_error(s).empty());
    const auto mass = slope::slice_circle(s, circle, slope::SliceOptions{});
    REQUIRE(mass);
    for (slope::Method m : every_method) {
      INFO(slope::describe_envelope(envelope) << ", " << slope::method_key(m));
      CHECK(fs_on(*mass, m) == Approx(fs_on(*reference, m)).epsilon(1e-9));
    }
  }
}

TEST_CASE("at the converged factor of safety every base carries its envelope's strength at its normal stress",
          "[slope][strength]") {
  // The fixed point of the iteration: shear force x F / base length = tau(sigma_n') of the Hoek-Brown envelope
  // at each base's own effective normal stress, for the moment, force and general methods.
  slope::Section s = simple_slope(10.0, 45.0, 20.0, 20.0, 5.0, hammah_rock());
  const auto mass = slope::slice_circle(s, slope::Circle{26.0, 22.0, 17.5}, slope::SliceOptions{});
  REQUIRE(mass);
  REQUIRE(mass->envelopes.size() == 1);
  for (slope::Method m : {slope::Method::ordinary, slope::Method::bishop, slope::Method::janbu,
                          slope::Method::spencer, slope::Method::morgenstern_price}) {
    INFO(slope::method_key(m));
    const slope::FsResult r = slope::factor_of_safety(*mass, m, true);
    REQUIRE(r.factor_of_safety);
    REQUIRE(r.forces.size() == mass->slices.size());
    double largest_error = 0.0;
    for (std::size_t i = 0; i < mass->slices.size(); ++i) {
      const slope::Slice& slice = mass->slices[i];
      REQUIRE(slice.envelope == 0);
      const double sigma = (r.forces[i].normal - r.forces[i].pore_force) / slice.base_length;
      const double tau = slope::envelope_at(mass->envelopes[0], sigma).shear;
      const double carried = r.forces[i].shear * *r.factor_of_safety / slice.base_length;
      largest_error = std::max(largest_error, std::fabs(carried - tau) / tau);
    }
    CHECK(largest_error < 1e-6);
  }
}

TEST_CASE("a section with an invalid envelope, or an envelope and a cohesion rising with depth, is refused",
          "[slope][strength]") {
  slope::Section s = simple_slope(10.0, 45.0, 20.0, 20.0, 5.0, hammah_rock());
  CHECK(slope::section_error(s).empty());
  s.materials[0].envelope->hoek_brown.a = 1.2;
  CHECK(slope::section_error(s).find("Hoek-Brown needs") != std::string::npos);
  s.materials[0] = hammah_rock();
  s.materials[0].cohesion_rate = 1e3;
  CHECK(slope::section_error(s).find("one or the other") != std::string::npos);
  s.materials[0].cohesion_rate = 0.0;
  s.materials[0].envelope->kind = slope::StrengthEnvelope::Kind::shear_normal;
  s.materials[0].envelope->points = {{0.0, 10e3}, {100e3, 5e3}};
  CHECK(slope::section_error(s).find("not decreasing") != std::string::npos);
  s.materials[0].envelope->kind = slope::StrengthEnvelope::Kind::power_curve;
  s.materials[0].envelope->power_a = 0.0;
  CHECK(slope::section_error(s).find("power curve") != std::string::npos);
}

TEST_CASE("Hammah et al. (2005) Example 1: a Hoek-Brown rock slope, 10 m high at 45 degrees",
          "[slope][published][strength][validation]") {
  // Hammah, Yacoub, Corkum & Curran (2005), "The shear strength reduction method for the generalized Hoek-Brown
  // criterion", ARMA/USRMS 05-810, Example 1: a homogeneous slope 10 m high at 45 degrees, sigma_ci = 30 MPa,
  // GSI = 5, m_i = 2, D = 0, gamma = 25 kN/m^3; limit equilibrium (Slide) Bishop 1.153, Spencer 1.152. The paper
  // gives neither the foundation depth nor the lateral extent: 5 m of foundation and 20 m of level ground on each
  // side here (the xslope project's verification, with 5 m, finds Bishop 1.150 and Spencer 1.152). 1 % against the
  // paper (measured 2026-11-29: 1.155, 1.156).
  slope::Section s = simple_slope(10.0, 45.0, 20.0, 20.0, 5.0, hammah_rock());
  const std::vector<slope::Method> methods{slope::Method::bishop, slope::Method::spencer};
  const slope::SearchResult r = slope::search_critical(s, methods, slope::SearchOptions{});
  CHECK(searched(r, slope::Method::bishop) == Approx(1.153).epsilon(0.01));
  CHECK(searched(r, slope::Method::spencer) == Approx(1.152).epsilon(0.01));
  // With the paper's rounded m_b = 0.067, s = 2.5e-5, a = 0.619 in place of those from GSI (0.0672, 2.60e-5, 0.6192).
  s.materials[0].envelope->hoek_brown = slope::HoekBrown{30e6, 0.067, 2.5e-5, 0.619};
  const slope::SearchResult rounded = slope::search_critical(s, methods, slope::SearchOptions{});
  CHECK(searched(rounded, slope::Method::bishop) == Approx(1.153).epsilon(0.01));
  CHECK(searched(rounded, slope::Method::spencer) == Approx(1.152).epsilon(0.01));
}

TEST_CASE("a Rankine tension crack in a material with an envelope takes the envelope's tangent at zero normal stress",
          "[slope][strength]") {
  // Rankine's depth 2 c / (gamma sqrt(Ka)), Ka = tan^2(45 deg - phi/2), with c and phi the tangent to the
  // Hoek-Brown envelope at sigma_n' = 0 (strength.hpp), on a planar surface from the crest to the toe.
  const slope::Section s = simple_slope(10.0, 45.0, 20.0, 20.0, 5.0, hammah_rock());
  const slope::EnvelopePoint at_zero = slope::envelope_at(slope::tabulated(*s.materials[0].envelope), 0.0);
  const double c = at_zero.shear, phi = std::atan(at_zero.slope);
  const double expected = 2.0 * c / (25e3 * std::tan(M_PI / 4.0 - phi / 2.0));
  REQUIRE(expected > 0.5);
  slope::SlipPolyline surface;
  surface.points = {{10.0, 15.0}, {30.0, 5.0}};
  surface.tension_crack = slope::TensionCrack{std::nullopt, false};
  std::string reason;
  const auto mass = slope::slice_polyline(s, surface, slope::SliceOptions{}, &reason);
  INFO(reason);
  REQUIRE(mass);
  CHECK(mass->crack_depth == Approx(expected).epsilon(1e-12));
}

TEST_CASE("Charles & Soares / Jiang, Baker & Yamagami: a power-curve soil, tau = 1.4 sigma'^0.8 kPa, with r_u = 0.3",
          "[slope][published][strength][validation]") {
  // Jiang, Baker & Yamagami (2003), Rocscience Slide verification problem #41 (after Charles & Soares 1984):
  // ground (0,30)-(5,30)-(85,10)-(93,10) m, base y = 0, c' = 0 with tau = 1.4 sigma'^0.8 (kPa), r_u = 0.3. The
  // unit weight, 20 kN/m^3, is the xslope project's input (benchmarks/rocscience/build_problems.py, vp041), not
  // checked against the manual. Reference: Charles & Soares Bishop 1.66; Slide 1.656 (a non-circular path search);
  // the published values spread over 1.56-1.67; xslope's circular Bishop 1.668 on the same input. 2 % against
  // 1.66 (the unit weight is second-hand; for c' = 0 the factor of safety goes as gamma^-0.2), 0.5 % against xslope
  // (measured 2026-11-29: 1.6685).
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials.push_back(material("clay", 20.0, 0.0, 0.0));
  s.materials[0].pore_pressure_ratio = 0.3;
  slope::StrengthEnvelope power;
  power.kind = slope::StrengthEnvelope::Kind::power_curve;
  power.power_a = 1.4 * std::pow(1e3, 0.2);  // kPa^0.2 to Pa^0.2
  power.power_b = 0.8;
  s.materials[0].envelope = power;
  s.profile_lines.push_back(slope::ProfileLine{0, {{0, 30}, {5, 30}, {85, 10}, {93, 10}}});
  const slope::SearchResult r = slope::search_critical(s, {slope::Method::bishop}, slope::SearchOptions{});
  CHECK(searched(r, slope::Method::bishop) == Approx(1.66).epsilon(0.02));
  CHECK(searched(r, slope::Method::bishop) == Approx(1.668).epsilon(0.005));
}

}  // namespace test_lem_strength
