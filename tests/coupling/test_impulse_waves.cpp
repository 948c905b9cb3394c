// Heller & Hager (2010) impact parameters and near-field wave (coupling/analyses/impulse_waves.hpp) against the two
// worked examples of ../shared/references/landslide-waves.md (section 1a and O2), each recomputed by hand here:
//  - Lake Askja 2014, the VAW manual's section 4.2.1 (2nd ed.): m_s = 2e10 kg over b = 550 m, s = 35.5 m, alpha =
//    10.4 deg, v_s = 30.1 m/s, h = 138 m. The manual prints F = 0.82, S = 0.26, M = 1.91, P = 0.49, H_M = 43.3 m,
//    x_M = 531 m (from P rounded to 0.49: by hand P = 0.4848, H_M = 42.96 m, x_M = 528.4 m). Outside the 2-D ranges
//    (alpha < 30 deg, F < 0.86).
//  - a laboratory channel: h = 0.30 m, alpha = 45 deg, v_s = 3.0 m/s, s = 0.10 m, 0.06 m^2 of 1620 kg/m^3 granulate:
//    F = 1.749, S = 0.333, M = 1.08, P = 0.910, a_M = 0.124 m, H_M = 0.155 m, x_M = 1.57 m, T_M = 1.50 s (by hand
//    P = 0.9101, a_M = 0.1236 m, x_M = 1.574 m, T_M = 1.502 s). Inside the ranges.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "coupling/analyses/coupled_impact.hpp"
#include "coupling/analyses/impulse_waves.hpp"

namespace test_impulse_waves {

namespace {

// |value / expected - 1| <= tolerance
bool near(double value, double expected, double tolerance) { return std::fabs(value / expected - 1.0) <= tolerance; }

// slide.csv of a slide whose centroid falls at 1 m/s from y0 and speeds up at 3 m/s^2, its thickness 0.1 + 0.1 t,
// in rows of 0.1 s to 1 s.
std::string slide_csv(double y0) {
  std::string csv = std::string("time_s,centroid_y_m,centroid_speed_m_s,") + coupling::slide_thickness_column + "\n";
  char row[128];
  for (int k = 0; k <= 10; ++k) {
    const double t = 0.1 * k;
    std::snprintf(row, sizeof row, "%.1f,%.6f,%.6f,%.6f\n", t, y0 - t, 3.0 * t, 0.1 + 0.1 * t);
    csv += row;
  }
  return csv;
}

// monitors.csv of two gauges that read 0.31 m at rest (the discretised surface) and a crest of 0.05 m at 1 s (g1)
// and 0.04 m at 2 s (g2), each a Gaussian of 0.1 s, in rows of 0.01 s to 3 s.
std::string gauges_csv() {
  std::string csv = "time_s,g1_m,g2_m\n";
  char row[128];
  for (int k = 0; k <= 300; ++k) {
    const double t = 0.01 * k;
    std::snprintf(row, sizeof row, "%.2f,%.6f,%.6f\n", t, 0.31 + 0.05 * std::exp(-std::pow((t - 1.0) / 0.1, 2)),
                  0.31 + 0.04 * std::exp(-std::pow((t - 2.0) / 0.1, 2)));
    csv += row;
  }
  return csv;
}

coupling::CoupledImpact impact_of(double y0) {
  coupling::TankMonitors gauges;
  gauges.gauges = {{"g1", 2.0}, {"g2", 4.0}};
  gauges.still_water = 0.3;
  const coupling::Tank tank{0.0, 6.0, 0.0, 1.0};
  return coupling::coupled_impact(coupling::parse_monitors_csv(slide_csv(y0)),
                                  coupling::parse_monitors_csv(gauges_csv()), {45.0, 1.0}, gauges, tank, 97.2, 9.81,
                                  1000);
}

}  // namespace

TEST_CASE("impact: the slide at the still water and the gauges' crests, from records built by hand", "[impulse]") {
  // the centroid (0.75 - t) reaches the still water at 0.45 s, half-way between two rows: v_s and s linear there
  const coupling::CoupledImpact impact = impact_of(0.75);
  REQUIRE(impact.missing.empty());
  CHECK(impact.time == Approx(0.45).margin(1e-12));
  CHECK(impact.slide.speed == Approx(1.35).margin(1e-9));
  CHECK(impact.slide.thickness == Approx(0.145).margin(1e-9));
  CHECK(impact.slide.depth == Approx(0.3).margin(1e-12));
  CHECK(impact.slide.angle_deg == 45.0);
  CHECK(impact.slide.mass_per_width == 97.2);
  const coupling::ImpulseWave expected = coupling::heller_hager_impulse_wave({1.35, 0.145, 97.2, 45, 0.3}, 9.81, 1000);
  CHECK(impact.predicted.P == Approx(expected.P).epsilon(1e-8));
  CHECK(impact.predicted.crest_amplitude == Approx(expected.crest_amplitude).epsilon(1e-8));
  // the largest crest is g1's 0.05 m above its reading at rest, 1 m from the shoreline
  CHECK(impact.largest_crest_gauge == "g1");
  CHECK(impact.largest_crest == Approx(0.05).margin(1e-6));
  CHECK(impact.largest_crest_at == Approx(1.0).margin(1e-12));
  CHECK(impact.largest_crest_distance == Approx(1.0).margin(1e-12));
  // the leading crest from g1 to g2: 2 m in 1 s, against sqrt(g (h + a)) with a the mean crest 0.045 m
  REQUIRE(impact.celerity.size() == 1);
  CHECK(impact.celerity[0].from == "g1");
  CHECK(impact.celerity[0].to == "g2");
  CHECK(impact.celerity[0].speed == Approx(2.0).margin(1e-9));
  CHECK(impact.celerity[0].expected == Approx(std::sqrt(9.81 * 0.345)).epsilon(1e-5));
}

TEST_CASE("impact: none for a slide that starts under the still water or never reaches it", "[impulse]") {
  CHECK(impact_of(0.3).missing.find("starts at or below the still water") != std::string::npos);
  CHECK(impact_of(1.5).missing.find("never reached the still water") != std::string::npos);
}

TEST_CASE("impulse wave: Lake Askja as the VAW manual computes it", "[impulse]") {
  const coupling::ImpulseWave w = coupling::heller_hager_impulse_wave({30.1, 35.5, 2e10 / 550, 10.4, 138}, 9.81, 1000);
  // the manual's two-digit groups and its figures from P = 0.49 (1.5 %: their rounding)
  CHECK(near(w.F, 0.82, 0.01));
  CHECK(near(w.S, 0.26, 0.015));
  CHECK(near(w.M, 1.91, 0.005));
  CHECK(near(w.P, 0.49, 0.015));
  CHECK(near(w.wave_height, 43.3, 0.015));
  CHECK(near(w.crest_position, 531, 0.015));
  // by hand, unrounded
  CHECK(near(w.P, 0.4848, 0.0005));
  CHECK(near(w.wave_height, 42.96, 0.001));
  CHECK(near(w.crest_position, 528.4, 0.001));
  CHECK_FALSE(w.inside_ranges());
  int outside = 0;
  for (const auto& g : w.groups) outside += g.inside() ? 0 : 1;
  CHECK(outside == 2);  // alpha and F
}

TEST_CASE("impulse wave: a laboratory channel inside the 2-D ranges", "[impulse]") {
  const coupling::ImpulseWave w = coupling::heller_hager_impulse_wave({3.0, 0.10, 0.06 * 1620, 45, 0.30}, 9.81, 1000);
  CHECK(near(w.F, 1.749, 0.001));
  CHECK(near(w.S, 0.3333, 0.001));
  CHECK(near(w.M, 1.08, 0.001));
  CHECK(near(w.P, 0.9101, 0.0005));
  CHECK(near(w.crest_amplitude, 0.1236, 0.002));
  CHECK(near(w.wave_height, 0.155, 0.005));
  CHECK(near(w.crest_position, 1.574, 0.001));
  CHECK(near(w.period, 1.502, 0.001));
  CHECK(w.celerity == Approx(std::sqrt(9.81 * (0.30 + w.crest_amplitude))));
  CHECK(w.inside_ranges());
}

TEST_CASE("impulse wave: a slide with no speed or an angle past vertical is refused", "[impulse]") {
  CHECK_THROWS_AS(coupling::heller_hager_impulse_wave({0, 0.1, 97, 45, 0.3}, 9.81, 1000), std::invalid_argument);
  CHECK_THROWS_AS(coupling::heller_hager_impulse_wave({3, 0.1, 97, 95, 0.3}, 9.81, 1000), std::invalid_argument);
}

}  // namespace test_impulse_waves
