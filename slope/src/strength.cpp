// Non-linear strength envelopes (strength.hpp): Hoek-Brown through Balmer's parametric shear-normal form, a power
// curve, a tabulated function.
#include "slope/strength.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slope {

// Hoek-Brown tabulated (tabulated()): for interval j, from normal[j] to normal[j + 1], the shear strength is
// sum_k coefficients[6 j + k] t^k with t = (sigma_n - normal[j]) inverse_width[j].
struct EnvelopeTable {
  std::vector<double> normal;         // Pa, the nodes' normal stresses, increasing
  std::vector<double> inverse_width;  // 1/Pa, one per interval
  std::vector<double> coefficients;   // Pa, six per interval
};

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
  double curvature = 0.0;                                           // d^2 tau / d sigma_n^2
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
  // d slope / d k = (k + 1) / (4 k^(3/2)), by the chain rule through sigma3
  p.curvature = (k + 1.0) / (4.0 * k * std::sqrt(k)) * dk / p.d_normal;
  return p;
}

// The least sigma3 the envelope is evaluated at: where m_b sigma3 / sigma_ci + s = 1e-9, just above the tensile
// strength -s sigma_ci / m_b (where it is 0 and the slope grows without bound). For Hammah et al.'s rock mass
// (sigma_ci 30 MPa, m_b 0.067, a 0.619) the envelope there is 1.2 Pa above the tensile strength, at tau = 7.5 Pa with
// a slope of 5.3.
double least_sigma3(const HoekBrown& hb) { return hb.intact_strength * (1e-9 - hb.s) / hb.mb; }

EnvelopePoint hoek_brown_at(const HoekBrown& hb, double normal_stress, double* hint) {  // hint: sigma3
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

// The envelope from the table where it covers normal_stress: the interval's quintic in t = (sigma_n - start) / width
// and its derivative; false above the last node.
// interval: in, where to look first; out, the interval used.
bool table_at(const EnvelopeTable& table, double normal_stress, std::size_t& interval, EnvelopePoint& out) {
  const std::vector<double>& x = table.normal;
  if (!(normal_stress < x.back())) return false;
  if (!(normal_stress > x.front())) {  // below the least point: its tangent extended, as the root search does
    const double* c = table.coefficients.data();
    const double slope = c[1] * table.inverse_width.front();
    out = {c[0] + slope * (normal_stress - x.front()), slope};
    return true;
  }
  std::size_t j = interval;
  if (!(j + 1 < x.size() && x[j] <= normal_stress && normal_stress < x[j + 1]))
    j = static_cast<std::size_t>(std::upper_bound(x.begin() + 1, x.end(), normal_stress) - x.begin() - 1);
  interval = j;
  const double* c = table.coefficients.data() + 6 * j;
  const double t = (normal_stress - x[j]) * table.inverse_width[j];
  const double value = c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
  const double derivative = c[1] + t * (2.0 * c[2] + t * (3.0 * c[3] + t * (4.0 * c[4] + t * 5.0 * c[5])));
  out = {value, derivative * table.inverse_width[j]};
  return true;
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

EnvelopePoint envelope_at(const StrengthEnvelope& envelope, double normal_stress, EnvelopeHint* hint) {
  switch (envelope.kind) {
    case StrengthEnvelope::Kind::hoek_brown: {
      EnvelopeHint none;
      EnvelopeHint& h = hint != nullptr ? *hint : none;
      EnvelopePoint p;
      if (envelope.table && table_at(*envelope.table, normal_stress, h.interval, p)) return p;
      return hoek_brown_at(envelope.hoek_brown, normal_stress, &h.sigma3);
    }
    case StrengthEnvelope::Kind::power_curve: return power_curve_at(envelope, normal_stress);
    case StrengthEnvelope::Kind::shear_normal: return shear_normal_at(envelope.points, normal_stress);
  }
  return {};
}

StrengthEnvelope tabulated(StrengthEnvelope envelope) {
  if (envelope.kind != StrengthEnvelope::Kind::hoek_brown || !envelope_error(envelope).empty()) return envelope;
  const HoekBrown& hb = envelope.hoek_brown;
  // Nodes geometric in w = m_b sigma3 / sigma_ci + s, from the least point's 1e-9 to sigma3 = 10 sigma_ci: near
  // the tensile strength tau grows as a power of the distance from it, beyond as a power of sigma_n, so that a
  // constant ratio between nodes keeps the relative error even (below 1e-12 at 60 nodes a decade, 530 for
  // Hammah et al.'s rock mass: test_lem_strength.cpp).
  constexpr double nodes_per_decade = 60.0;
  const double w_least = 1e-9, w_top = 10.0 * hb.mb + hb.s;
  const auto intervals = static_cast<std::size_t>(std::ceil(std::log10(w_top / w_least) * nodes_per_decade));
  const double ratio = std::pow(w_top / w_least, 1.0 / static_cast<double>(intervals));
  std::vector<BalmerPoint> nodes;
  for (std::size_t j = 0; j <= intervals; ++j) {
    const double w = j == 0 ? w_least : w_least * std::pow(ratio, static_cast<double>(j));
    nodes.push_back(balmer(hb, j == 0 ? least_sigma3(hb) : hb.intact_strength * (w - hb.s) / hb.mb));
  }
  auto table = std::make_shared<EnvelopeTable>();
  for (std::size_t j = 0; j < intervals; ++j) {
    const BalmerPoint& p = nodes[j];
    const BalmerPoint& q = nodes[j + 1];
    const double h = q.normal - p.normal;
    // quintic Hermite: value, slope times h and curvature times h^2 at both ends
    const double dy = q.shear - p.shear, m0 = p.slope * h, m1 = q.slope * h;
    const double c0 = p.curvature * h * h, c1 = q.curvature * h * h;
    table->normal.push_back(p.normal);
    table->inverse_width.push_back(1.0 / h);
    for (double c : {p.shear, m0, 0.5 * c0, 10.0 * dy - 6.0 * m0 - 4.0 * m1 - 1.5 * c0 + 0.5 * c1,
                     -15.0 * dy + 8.0 * m0 + 7.0 * m1 + 1.5 * c0 - c1, 6.0 * dy - 3.0 * m0 - 3.0 * m1 - 0.5 * c0 + 0.5 * c1})
      table->coefficients.push_back(c);
  }
  table->normal.push_back(nodes.back().normal);
  envelope.table = std::move(table);
  return envelope;
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
