// Polyline heights, exact integrals and lower-arc crossings in time independent of the number of vertices.
#include "indexed_polyline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slope::detail {

IndexedPolyline::IndexedPolyline(const std::vector<Point>& points) : points_(points) {
  const std::size_t n = points_.size();
  area_.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i)
    area_[i] = area_[i - 1] + 0.5 * (points_[i - 1].y + points_[i].y) * (points_[i].x - points_[i - 1].x);
  if (n < 2) return;
  const std::size_t segments = n - 1;
  const std::size_t used_leaves = (segments + segments_per_leaf - 1) / segments_per_leaf;
  leaves_ = 1;
  while (leaves_ < used_leaves) leaves_ *= 2;
  constexpr double inf = std::numeric_limits<double>::infinity();
  boxes_.assign(2 * leaves_, Box{inf, -inf, inf, -inf});  // an empty box meets nothing
  for (std::size_t leaf = 0; leaf < used_leaves; ++leaf) {
    Box& box = boxes_[leaves_ + leaf];
    const std::size_t last = std::min(n - 1, (leaf + 1) * segments_per_leaf);
    for (std::size_t i = leaf * segments_per_leaf; i <= last; ++i) {
      box.x0 = std::min(box.x0, points_[i].x);
      box.x1 = std::max(box.x1, points_[i].x);
      box.y0 = std::min(box.y0, points_[i].y);
      box.y1 = std::max(box.y1, points_[i].y);
    }
  }
  for (std::size_t node = leaves_ - 1; node >= 1; --node) {
    const Box& a = boxes_[2 * node];
    const Box& b = boxes_[2 * node + 1];
    boxes_[node] = Box{std::min(a.x0, b.x0), std::max(a.x1, b.x1), std::min(a.y0, b.y0), std::max(a.y1, b.y1)};
  }
}

std::size_t IndexedPolyline::segment_of(double x) const {
  const auto upper = std::upper_bound(points_.begin(), points_.end(), x,
                                      [](double value, const Point& p) { return value < p.x; });
  const std::size_t i = upper == points_.begin() ? 0 : static_cast<std::size_t>(upper - points_.begin()) - 1;
  return std::min(i, points_.size() - 2);
}

double IndexedPolyline::y(double x) const {
  if (points_.empty()) return 0.0;
  if (x <= points_.front().x) return points_.front().y;
  if (x >= points_.back().x) return points_.back().y;
  const std::size_t i = segment_of(x);
  const Point& a = points_[i];
  const Point& b = points_[i + 1];
  return a.y + (x - a.x) * (b.y - a.y) / (b.x - a.x);
}

double IndexedPolyline::primitive(double x) const {
  const Point& first = points_.front();
  const Point& last = points_.back();
  if (x <= first.x) return (x - first.x) * first.y;
  if (x >= last.x) return area_.back() + (x - last.x) * last.y;
  const std::size_t i = segment_of(x);
  const Point& a = points_[i];
  const Point& b = points_[i + 1];
  const double yx = a.y + (x - a.x) * (b.y - a.y) / (b.x - a.x);
  return area_[i] + 0.5 * (a.y + yx) * (x - a.x);
}

double IndexedPolyline::integral(double a, double b) const {
  if (points_.empty()) return 0.0;
  return primitive(b) - primitive(a);
}

void IndexedPolyline::lower_arc_crossings(const Circle& circle, double x_from, double x_to,
                                          std::vector<double>& out) const {
  if (leaves_ == 0 || !(x_to > x_from)) return;
  crossings_in_node(1, 0, leaves_, circle, x_from, x_to, out);
}

void IndexedPolyline::crossings_in_node(std::size_t node, std::size_t first_leaf, std::size_t leaf_count,
                                        const Circle& circle, double x_from, double x_to,
                                        std::vector<double>& out) const {
  const Box& box = boxes_[node];
  if (box.x1 <= x_from || box.x0 >= x_to) return;
  const double r2 = circle.radius * circle.radius;
  // only points at or below the centre belong to the lower arc
  if (box.y0 > circle.yc + 1e-12 * circle.radius) return;
  // nearest and farthest points of the box from the centre: a box wholly inside or outside the circle holds no
  // crossing (a relative margin keeps rounding from hiding a crossing on the box's edge)
  const double nx = std::max({box.x0 - circle.xc, 0.0, circle.xc - box.x1});
  const double ny = std::max({box.y0 - circle.yc, 0.0, circle.yc - box.y1});
  const double fx = std::max(std::fabs(circle.xc - box.x0), std::fabs(circle.xc - box.x1));
  const double fy = std::max(std::fabs(circle.yc - box.y0), std::fabs(circle.yc - box.y1));
  const double margin = 1e-9 * r2;
  if (nx * nx + ny * ny > r2 + margin || fx * fx + fy * fy < r2 - margin) return;
  if (leaf_count == 1) {
    const std::size_t first = first_leaf * segments_per_leaf;
    const std::size_t last = std::min(points_.size() - 1, first + segments_per_leaf);
    crossings_in_segments(first, last, circle, x_from, x_to, out);
    return;
  }
  const std::size_t half = leaf_count / 2;
  crossings_in_node(2 * node, first_leaf, half, circle, x_from, x_to, out);
  crossings_in_node(2 * node + 1, first_leaf + half, half, circle, x_from, x_to, out);
}

// Segments first .. last-1 (segment i joins points i and i+1).
void IndexedPolyline::crossings_in_segments(std::size_t first, std::size_t last, const Circle& circle,
                                            double x_from, double x_to, std::vector<double>& out) const {
  const double r2 = circle.radius * circle.radius;
  const double y_limit = circle.yc + 1e-12 * circle.radius;
  for (std::size_t i = first; i < last; ++i) {
    const Point& p0 = points_[i];
    const Point& p1 = points_[i + 1];
    if (p0.x >= x_to) break;
    if (p1.x <= x_from) continue;
    const double dx = p1.x - p0.x;
    const double dy = p1.y - p0.y;
    const double fx = p0.x - circle.xc;
    const double fy = p0.y - circle.yc;
    const double a = dx * dx + dy * dy;
    const double b = 2.0 * (fx * dx + fy * dy);
    const double c = fx * fx + fy * fy - r2;
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0 || a <= 0.0) continue;
    const double sq = std::sqrt(disc);
    const double q = -0.5 * (b + (b >= 0.0 ? sq : -sq));
    double ts[2] = {q / a, q != 0.0 ? c / q : q / a};
    if (ts[0] > ts[1]) std::swap(ts[0], ts[1]);
    for (double t : ts) {
      if (t < -1e-12 || t > 1.0 + 1e-12) continue;
      t = std::clamp(t, 0.0, 1.0);
      const double x = p0.x + t * dx;
      const double y = p0.y + t * dy;
      if (y > y_limit) continue;
      if (x > x_from && x < x_to) out.push_back(x);
    }
  }
}

}  // namespace slope::detail
