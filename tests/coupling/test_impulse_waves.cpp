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
#include <stdexcept>

#include "coupling/analyses/impulse_waves.hpp"

namespace test_impulse_waves {

namespace {

// |value / expected - 1| <= tolerance
bool near(double value, double expected, double tolerance) { return std::fabs(value / expected - 1.0) <= tolerance; }

}  // namespace

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
