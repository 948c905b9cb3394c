// Non-linear strength envelopes (strength.hpp): Hoek-Brown through Balmer's parametric shear-normal form, a power
// curve, a tabulated function.
#include "slope/strength.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slope {

HoekBrown hoek_brown_from_gsi(double intact_strength, double gsi, double mi, double disturbance) {
  HoekBrown hb;
  hb.intact_strength = intact_strength;
  hb.mb = mi * std::exp((gsi - 100.0) / (28.0 - 14.0 * disturbance));
  hb.s = std::exp((gsi - 100.0) / (9.0 - 3.0 * disturbance));
  hb.a = 0.5 + (std::exp(-gsi / 15.0) - std::exp(-20.0 / 3.0)) / 6.0;
  return hb;
}

namespace {

// Balmer (1952): on the Mohr circle of (sigma1, sigma3) on the criterion, the envelope touches at
// sigma_n = sigma3 + (sigma1 - sigma3) / (k + 1), tau = (sigma1 - sigma3) sqrt(k) / (k + 1), with
// k = d sigma1 / d sigma3; its slope there is tan(phi_i) = (k - 1) / (2 sqrt(k)) (sin(phi_i) = (k - 1) / (k + 1)).
struct BalmerPoint {
  double normal = 0.0, shear = 0.0, slope = 0.0, d_normal = 0.0;  // d_normal: d sigma_n / d sigma3
};

BalmerPoint balmer(const HoekBrown& hb, double sigma3) {
  const double w = hb.mb * sigma3 / hb.intact_strength + hb.s;
  const double w_a = std::pow(w, hb.a);  // one pow: w^(a-1) and w^(a-2) follow by division (w > 0 here)
  const double deviator = hb.intact_strength * w_a;
  const double k = 1.0 + hb.a * hb.mb * w_a / w;
  const double dk = hb.a * (hb.a - 1.0) * hb.mb * hb.mb / hb.intact_strength * w_a / (w * w);
  BalmerPoint p;
  p.normal = sigma3 + deviator / (k + 1.0);
  p.shear = deviator * std::sqrt(k) / (k + 1.0);
  p.slope = (k - 1.0) / (2.0 * std::sqrt(k));
  p.d_normal = 1.0 + (k - 1.0) / (k + 1.0) - deviator * dk / ((k + 1.0) * (k + 1.0));
  return p;
}

// The least sigma3 the envelope is evaluated at: where m_b sigma3 / sigma_ci + s = 1e-9, just above the tensile
// strength -s sigma_ci / m_b (where it is 0 and the slope grows without bound). For Hammah et al.'s rock mass
// (sigma_ci 30 MPa, m_b 0.067, a 0.619) the envelope there is 1.2 Pa above the tensile strength, at tau = 7.5 Pa with
// a slope of 5.3.
double least_sigma3(const HoekBrown& hb) { return hb.intact_strength * (1e-9 - hb.s) / hb.mb; }

EnvelopePoint hoek_brown_at(const HoekBrown& hb, double normal_stress, double* hint) {
  // The root sigma3 of sigma_n(sigma3) = normal_stress. sigma_n increases (d_normal > 1) and sigma_n >= sigma3: the
  // root lies in [least, normal_stress] unless normal_stress is below sigma_n(least), where the tangent there is
  // extended. Newton's method from the hint (or the upper end), kept inside the bracket and bisecting when a step
  // leaves it; the least point is evaluated only when a step would fall below it.
  const double least = least_sigma3(hb);
  const auto extended = [&](const BalmerPoint& q) {
    return EnvelopePoint{q.shear + q.slope * (normal_stress - q.normal), q.slope};
  };
  double lo = least, hi = normal_stress;
  if (!(hi > lo)) return extended(balmer(hb, least));
  double x = (hint != nullptr && *hint > lo && *hint < hi) ? *hint : hi;
  BalmerPoint p = balmer(hb, x);
  // Within the tolerance the point found is on the envelope beside the target: its tangent covers the difference
  // (an error of the order of the curvature times the difference squared).
  const double tolerance = 1e-9 * (std::fabs(normal_stress) + 1e-3 * hb.intact_strength);
  double f = p.normal - normal_stress;
  for (int iteration = 0; iteration < 200 && std::fabs(f) > tolerance; ++iteration) {
    (f < 0.0 ? lo : hi) = x;
    double next = x - f / p.d_normal;
    if (!(next > lo) && lo == least) {
      const BalmerPoint q = balmer(hb, least);
      if (!(normal_stress > q.normal)) return extended(q);
    }
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    x = next;
    p = balmer(hb, x);
    f = p.normal - normal_stress;
  }
  if (hint != nullptr) *hint = x;
  return {p.shear - p.slope * f, p.slope};
}

EnvelopePoint power_curve_at(const StrengthEnvelope& e, double normal_stress) {
  const double least = 1.0;  // Pa of sigma' + d
  const double t = std::max(normal_stress + e.power_d, least);
  const double slope = e.power_a * e.power_b * std::pow(t, e.power_b - 1.0);
  const double shear = e.power_a * std::pow(t, e.power_b) + e.power_c;
  return {shear + slope * (normal_stress + e.power_d - t), slope};
}

EnvelopePoint shear_normal_at(const std::vector<StressPoint>& points, double normal_stress) {
  // the segment holding normal_stress; the first or the last beyond the ends
  auto upper = std::upper_bound(points.begin() + 1, points.end() - 1, normal_stress,
                                [](double v, const StressPoint& p) { return v < p.normal; });
  const StressPoint& b = *upper;
  const StressPoint& a = *(upper - 1);
  const double slope = (b.shear - a.shear) / (b.normal - a.normal);
  return {a.shear + slope * (normal_stress - a.normal), slope};
}

bool finite_all(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

EnvelopePoint envelope_at(const StrengthEnvelope& envelope, double normal_stress, double* hint) {
  switch (envelope.kind) {
    case StrengthEnvelope::Kind::hoek_brown: return hoek_brown_at(envelope.hoek_brown, normal_stress, hint);
    case StrengthEnvelope::Kind::power_curve: return power_curve_at(envelope, normal_stress);
    case StrengthEnvelope::Kind::shear_normal: return shear_normal_at(envelope.points, normal_stress);
  }
  return {};
}

std::string envelope_error(const StrengthEnvelope& e) {
  switch (e.kind) {
    case StrengthEnvelope::Kind::hoek_brown: {
      const HoekBrown& hb = e.hoek_brown;
      if (!finite_all({hb.intact_strength, hb.mb, hb.s, hb.a}) || !(hb.intact_strength > 0.0) || !(hb.mb > 0.0) ||
          !(hb.s >= 0.0 && hb.s <= 1.0) || !(hb.a > 0.0 && hb.a < 1.0))
        return "Hoek-Brown needs sigma_ci > 0, m_b > 0, 0 <= s <= 1 and 0 < a < 1";
      return {};
    }
    case StrengthEnvelope::Kind::power_curve:
      if (!finite_all({e.power_a, e.power_b, e.power_c, e.power_d}) || !(e.power_a > 0.0) ||
          !(e.power_b > 0.0 && e.power_b <= 1.0) || !(e.power_c >= 0.0) || !(e.power_d >= 0.0))
        return "the power curve tau = A (sigma' + d)^b + c needs A > 0, 0 < b <= 1, c >= 0 and d >= 0";
      return {};
    case StrengthEnvelope::Kind::shear_normal: {
      if (e.points.size() < 2) return "a shear-normal function needs at least two points";
      for (std::size_t i = 0; i < e.points.size(); ++i) {
        const StressPoint& p = e.points[i];
        if (!finite_all({p.normal, p.shear}) || !(p.shear >= 0.0))
          return "a shear-normal function needs finite points with shear >= 0 (point " + std::to_string(i + 1) + ")";
        if (i > 0 && !(p.normal > e.points[i - 1].normal && p.shear >= e.points[i - 1].shear))
          return "a shear-normal function needs the normal stress strictly increasing and the shear not decreasing "
                 "(point " + std::to_string(i + 1) + ")";
      }
      return {};
    }
  }
  return "unknown strength envelope";
}

std::string describe_envelope(const StrengthEnvelope& e) {
  std::ostringstream out;
  out.precision(3);
  switch (e.kind) {
    case StrengthEnvelope::Kind::hoek_brown:
      out << "Hoek-Brown (sigma_ci " << e.hoek_brown.intact_strength / 1e6 << " MPa, m_b " << e.hoek_brown.mb
          << ", s " << e.hoek_brown.s << ", a " << e.hoek_brown.a << ")";
      break;
    case StrengthEnvelope::Kind::power_curve:
      out << "power curve (tau = " << e.power_a * std::pow(1e3, e.power_b - 1.0) << " (sigma' + " << e.power_d / 1e3
          << ")^" << e.power_b << " + " << e.power_c / 1e3 << ", kPa)";
      break;
    case StrengthEnvelope::Kind::shear_normal:
      out << "shear-normal function (" << e.points.size() << " points, sigma' " << e.points.front().normal / 1e3
          << " to " << e.points.back().normal / 1e3 << " kPa)";
      break;
  }
  return out.str();
}

}  // namespace slope
