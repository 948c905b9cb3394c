#pragma once
// Internal: a polyline y(x) prepared for slicing, so that a slip circle costs what its slices cost, not what the
// polyline's vertices cost (a surveyed ground profile has tens of thousands of them):
//   - heights y(x) and exact integrals of y over [a, b] in O(log n) (cumulative areas at the vertices);
//   - the points where the lower half of a circle cuts the polyline, found by descending a tree of bounding
//     boxes of runs of segments and skipping every box that lies wholly inside or wholly outside the circle.
#include <cstddef>
#include <vector>

#include "slope/section.hpp"
#include "slope/slices.hpp"

namespace slope::detail {

class IndexedPolyline {
 public:
  IndexedPolyline() = default;
  explicit IndexedPolyline(const std::vector<Point>& points);

  const std::vector<Point>& points() const { return points_; }
  // y at x; constant beyond the ends (as polyline_y).
  double y(double x) const;
  // Integral of y(x) dx from a to b (a <= b), exact for the polyline (constant beyond the ends).
  double integral(double a, double b) const;
  // Mean height over [a, b] (b > a).
  double mean(double a, double b) const { return integral(a, b) / (b - a); }
  // Appends, in increasing x, the x of every point where the lower half of the circle (y <= yc) cuts the polyline
  // strictly inside (x_from, x_to).
  void lower_arc_crossings(const Circle& circle, double x_from, double x_to, std::vector<double>& out) const;

 private:
  struct Box {
    double x0, x1, y0, y1;
  };
  static constexpr std::size_t segments_per_leaf = 8;
  // index of the segment [points_[i], points_[i+1]] that holds x (x inside the polyline's x range)
  std::size_t segment_of(double x) const;
  // cumulative integral from points_.front().x to x
  double primitive(double x) const;
  void crossings_in_node(std::size_t node, std::size_t first_leaf, std::size_t leaf_count, const Circle& circle,
                         double x_from, double x_to, std::vector<double>& out) const;
  void crossings_in_segments(std::size_t first, std::size_t last, const Circle& circle, double x_from, double x_to,
                             std::vector<double>& out) const;

  std::vector<Point> points_;
  std::vector<double> area_;  // area_[i] = integral of y from points_[0].x to points_[i].x
  std::vector<Box> boxes_;    // complete binary tree, node 1 is the root; leaves_ leaves from index leaves_
  std::size_t leaves_ = 0;    // a power of two
};

}  // namespace slope::detail
