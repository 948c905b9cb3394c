// Newmark's rigid-block displacement (newmark.hpp), integrated exactly on a record linear between its samples.
#include "slope/newmark.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slope {

namespace {

constexpr double never = std::numeric_limits<double>::infinity();

// The first u > 0 at which v(u) = v + b u + c u^2 falls back to zero (v >= 0, and v > 0 just after u = 0);
// infinity when it does not.
double first_stop(double v, double b, double c) {
  if (!(v > 0.0)) return c < 0.0 && b >= 0.0 ? -b / c : never;  // v(u) = u (b + c u), just started: b >= 0
  if (c == 0.0) return b < 0.0 ? -v / b : never;
  const double discriminant = b * b - 4.0 * c * v;
  if (discriminant < 0.0) return never;  // (c > 0: v stays positive)
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  double first = never;
  for (double root : {q / c, q != 0.0 ? v / q : never})
    if (root > 0.0 && root < first) first = root;
  return first;
}

}  // namespace

NewmarkResult newmark_displacement(const AccelerationRecord& record, double yield_coefficient, double scale,
                                   double gravity, std::vector<double>* history) {
  NewmarkResult out;
  const double kc = yield_coefficient, h = record.time_step, g = gravity;
  const std::vector<double>& a = record.acceleration;
  double v = 0.0;  // m/s, relative, downslope
  bool sliding = false;
  if (history != nullptr) history->assign(1, 0.0);
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    const double a0 = scale * a[i], slope = (scale * a[i + 1] - a0) / h;  // g and g/s over this interval
    double tau = 0.0;                                                     // s, into the interval
    // At most a start, a stop and a start again (the acceleration is linear here): four parts are enough.
    for (int part = 0; part < 4 && tau < h; ++part) {
      const double a_here = a0 + slope * tau;
      if (!sliding) {
        if (!(a_here > kc)) {
          if (!(slope > 0.0) || !(a0 + slope * h > kc)) break;  // stays below k_c to the interval's end
          tau = (kc - a0) / slope;                               // where it reaches k_c
        }
        sliding = true;
        ++out.sliding_episodes;
        continue;
      }
      // v(u) = v + b u + c u^2 and x(u) = v u + b u^2 / 2 + c u^3 / 3 from tau
      const double b = g * (a_here - kc);
      const double c = 0.5 * g * slope;
      const double rest = h - tau;
      const double stop = first_stop(v, b, c);
      const double u = std::min(stop, rest);
      if (c < 0.0) {  // the largest velocity inside the part
        const double vertex = -b / (2.0 * c);
        if (vertex > 0.0 && vertex < u) out.peak_velocity = std::max(out.peak_velocity, v + b * vertex + c * vertex * vertex);
      }
      out.displacement += u * (v + u * (0.5 * b + u * c / 3.0));
      out.sliding_time += u;
      tau += u;
      if (stop <= rest) {
        v = 0.0;
        sliding = false;
      } else {
        v = std::max(0.0, v + b * u + c * u * u);
        out.peak_velocity = std::max(out.peak_velocity, v);
      }
    }
    if (history != nullptr) history->push_back(out.displacement);
  }
  if (sliding && v > 0.0) {  // the ground at rest after the record: the block stops at k_c g
    out.displacement += v * v / (2.0 * kc * g);
    out.sliding_time += v / (kc * g);
  }
  return out;
}

std::string record_error(const AccelerationRecord& record) {
  if (!(record.time_step > 0.0) || !std::isfinite(record.time_step)) return "the time step must be positive";
  if (record.acceleration.size() < 2) return "an acceleration record needs at least two samples";
  for (std::size_t i = 0; i < record.acceleration.size(); ++i)
    if (!std::isfinite(record.acceleration[i]))
      return "sample " + std::to_string(i + 1) + " is not a finite acceleration";
  return {};
}

}  // namespace slope
