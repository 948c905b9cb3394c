#include "coupling/compare/surface_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coupling {

Polyline circle_arc(const slope::Circle& circle, double x_from, double x_to, int segments) {
  Polyline arc;
  arc.reserve(static_cast<std::size_t>(segments) + 1);
  for (int k = 0; k <= segments; ++k) {
    const double x = x_from + (x_to - x_from) * k / segments;
    const double dx = std::clamp(x - circle.xc, -circle.radius, circle.radius);
    arc.push_back({x, circle.yc - std::sqrt(circle.radius * circle.radius - dx * dx)});
  }
  return arc;
}

double polyline_height(const Polyline& line, double x) {
  if (x <= line.front().x) return line.front().y;
  if (x >= line.back().x) return line.back().y;
  const auto upper = std::upper_bound(line.begin(), line.end(), x,
                                      [](double value, const slope::Point& p) { return value < p.x; });
  const auto lower = upper - 1;
  const double t = (x - lower->x) / (upper->x - lower->x);
  return lower->y + t * (upper->y - lower->y);
}

double distance_to_polyline(const slope::Point& point, const Polyline& line) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const double ax = line[k].x, ay = line[k].y;
    const double ex = line[k + 1].x - ax, ey = line[k + 1].y - ay;
    const double length_sq = ex * ex + ey * ey;
    const double t = length_sq > 0.0 ? std::clamp(((point.x - ax) * ex + (point.y - ay) * ey) / length_sq, 0.0, 1.0)
                                     : 0.0;
    best = std::min(best, std::hypot(point.x - (ax + t * ex), point.y - (ay + t * ey)));
  }
  if (line.size() == 1) best = std::hypot(point.x - line[0].x, point.y - line[0].y);
  return best;
}

SurfaceDistances compare_surfaces(const Polyline& a, const Polyline& b, int samples) {
  SurfaceDistances result;
  if (a.size() < 2 || b.size() < 2) return result;
  result.common_from_x = std::max(a.front().x, b.front().x);
  result.common_to_x = std::min(a.back().x, b.back().x);
  if (result.common_to_x <= result.common_from_x) return result;

  // Normal (shortest) distances from sample points of a to b.
  double sum = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double x = result.common_from_x + (result.common_to_x - result.common_from_x) * k / samples;
    const double d = distance_to_polyline({x, polyline_height(a, x)}, b);
    sum += d;
    result.max_normal_distance = std::max(result.max_normal_distance, d);
  }
  result.mean_normal_distance = sum / (samples + 1);

  // Exact area between the piecewise-linear curves: on every interval between merged vertices the difference
  // is linear, so integrate |d| with the crossing point split out.
  std::vector<double> xs{result.common_from_x, result.common_to_x};
  for (const Polyline* line : {&a, &b})
    for (const auto& p : *line)
      if (p.x > result.common_from_x && p.x < result.common_to_x) xs.push_back(p.x);
  std::sort(xs.begin(), xs.end());
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const double x0 = xs[k], x1 = xs[k + 1];
    if (x1 <= x0) continue;
    const double d0 = polyline_height(a, x0) - polyline_height(b, x0);
    const double d1 = polyline_height(a, x1) - polyline_height(b, x1);
    if (d0 * d1 >= 0.0) {
      result.area_between += 0.5 * (std::abs(d0) + std::abs(d1)) * (x1 - x0);
    } else {
      const double xc = x0 + (x1 - x0) * d0 / (d0 - d1);
      result.area_between += 0.5 * std::abs(d0) * (xc - x0) + 0.5 * std::abs(d1) * (x1 - xc);
    }
  }
  return result;
}

}  // namespace coupling
