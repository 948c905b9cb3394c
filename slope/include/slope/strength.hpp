#pragma once
// Non-linear shear strength envelopes tau(sigma_n') for limit equilibrium: the generalized Hoek-Brown criterion
// (rock masses), a power curve and a tabulated shear-normal function. A material with an envelope takes, on each
// slice base, the strength of the envelope at the base's effective normal stress; the methods of slices see it as
// an instantaneous cohesion and friction angle (the tangent to the envelope there), found by iteration with the
// normal stresses of the method's own solution (methods.hpp). SI units: Pa.
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace slope {

// Generalized Hoek-Brown criterion (Hoek, Carranza-Torres & Corkum 2002):
//   sigma1' = sigma3' + sigma_ci (m_b sigma3' / sigma_ci + s)^a.
struct HoekBrown {
  double intact_strength = 0.0;  // Pa, sigma_ci: uniaxial compressive strength of the intact rock
  double mb = 0.0;               // -, m_b > 0
  double s = 0.0;                // -, 0 <= s <= 1
  double a = 0.5;                // -, 0 < a < 1
};

// m_b, s and a from the geological strength index GSI (0..100), the intact rock's m_i and the disturbance factor
// D (0..1): m_b = m_i exp((GSI - 100) / (28 - 14 D)), s = exp((GSI - 100) / (9 - 3 D)),
// a = 1/2 + (exp(-GSI / 15) - exp(-20 / 3)) / 6 (Hoek, Carranza-Torres & Corkum 2002, eqs. 2-4).
HoekBrown hoek_brown_from_gsi(double intact_strength, double gsi, double mi, double disturbance);

// A point of a shear-normal function: effective normal stress and shear strength, Pa.
struct StressPoint {
  double normal = 0.0;
  double shear = 0.0;
};

struct EnvelopeTable;  // strength.cpp

struct StrengthEnvelope {
  enum class Kind {
    hoek_brown,    // `hoek_brown`
    power_curve,   // tau = power_a (sigma' + power_d)^power_b + power_c
    shear_normal,  // `points`, linear between them, the end segments extended beyond
  };
  Kind kind = Kind::hoek_brown;
  HoekBrown hoek_brown;
  // Power curve (Slide2's form), SI: power_a in Pa^(1 - power_b), power_c and power_d in Pa. A curve given with
  // stresses in kPa, tau = A (sigma' + d)^b + c, has power_a = A 1000^(1 - b).
  double power_a = 0.0, power_b = 1.0, power_c = 0.0, power_d = 0.0;
  std::vector<StressPoint> points;  // shear_normal: normal stress strictly increasing, shear >= 0 non-decreasing
  // Hoek-Brown: the envelope tabulated by tabulated() for a fast envelope_at (none: each point by a root search).
  std::shared_ptr<const EnvelopeTable> table;
};

// The envelope with its table: Hoek-Brown's tau(sigma_n') is found once, at nodes of sigma3' from just above the
// tensile strength to sigma3' = 10 sigma_ci, and envelope_at then interpolates it (quintic Hermite in sigma_n' on
// each interval, from the exact strength, slope and curvature at both ends) in place of a root search for each
// point; beyond the last node it searches as before. The same strength to 1e-12 relative (test_lem_strength.cpp).
StrengthEnvelope tabulated(StrengthEnvelope envelope);

// The strength at an effective normal stress and the envelope's slope there (the instantaneous tan(phi)); the
// instantaneous cohesion is shear - normal * slope.
struct EnvelopePoint {
  double shear = 0.0;  // Pa
  double slope = 0.0;  // d tau / d sigma_n' (-)
};

// Below the envelope's least normal stress (Hoek-Brown: just above the tensile strength -s sigma_ci / m_b; power curve:
// sigma' + d below 1 Pa, where the slope would grow without bound; a shear-normal function: its first point) the
// tangent there is extended (the strength may fall to zero or below: the methods then refuse the surface).
// hint (Hoek-Brown; optional): in, where the evaluation for a nearby normal stress ended, to start there; out,
// where this one ended. The result does not depend on it beyond the root search's tolerance (sigma_n found within
// 1e-9 of |sigma_n| + 1e-3 sigma_ci, the tangent covering the difference); a table's result not at all.
struct EnvelopeHint {
  std::size_t interval = 0;  // the table's interval
  double sigma3 = std::numeric_limits<double>::quiet_NaN();  // Pa, the root search's minor principal stress
};
EnvelopePoint envelope_at(const StrengthEnvelope& envelope, double normal_stress, EnvelopeHint* hint = nullptr);

// Empty when the envelope can be used; otherwise what is wrong with its parameters.
std::string envelope_error(const StrengthEnvelope& envelope);

// A short text for reports: "Hoek-Brown (sigma_ci 30 MPa, m_b 0.0672, s 2.6e-05, a 0.619)" and the like.
std::string describe_envelope(const StrengthEnvelope& envelope);

}  // namespace slope
