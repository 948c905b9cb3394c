#pragma once
// Quantitative comparison of two slip surfaces given as polylines y(x) (x increasing), e.g. the SPH failure
// surface and the limit-equilibrium critical circle. SI units (m, m^2).
#include <vector>

#include "slope/slices.hpp"

namespace coupling {

using Polyline = std::vector<slope::Point>;

// The lower arc of a circle between x_from and x_to as a polyline of `segments` straight pieces.
Polyline circle_arc(const slope::Circle& circle, double x_from, double x_to, int segments = 200);

// Height of a polyline at x (linear between vertices); x must lie in the polyline's x range.
double polyline_height(const Polyline& line, double x);

// Shortest distance from a point to a polyline.
double distance_to_polyline(const slope::Point& point, const Polyline& line);

struct SurfaceDistances {
  double common_from_x = 0.0;       // m, start of the x span both surfaces cover
  double common_to_x = 0.0;         // m, its end (common_to_x <= common_from_x: no overlap)
  double mean_normal_distance = 0.0;// m, mean over the span of the shortest distance from `a` to `b`
  double max_normal_distance = 0.0; // m
  double area_between = 0.0;        // m^2, integral of |y_a(x) - y_b(x)| over the span
};

// Distances from surface `a` to surface `b` over their common x span, sampled at `samples` points; the area
// between them is integrated exactly for the piecewise-linear curves (crossings included).
SurfaceDistances compare_surfaces(const Polyline& a, const Polyline& b, int samples = 400);

}  // namespace coupling
