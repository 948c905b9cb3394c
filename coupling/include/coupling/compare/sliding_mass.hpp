#pragma once
// Sliding-mass polygons (between the ground surface and a slip surface) and their overlap, computed with
// CGAL's exact polygon booleans. SI units (m, m^2).
#include <vector>

#include "coupling/compare/surface_comparison.hpp"

namespace coupling {

// The region between `ground` (above) and `slip_surface` (below) over the slip surface's x range: the slip
// surface from left to right, then the ground back from right to left. Where the slip surface rises above
// the ground it is clipped to the ground.
Polyline sliding_mass_polygon(const Polyline& ground, const Polyline& slip_surface);

// Signed-area magnitude of a simple polygon (shoelace), m^2.
double polygon_area(const Polyline& polygon);

struct MassOverlap {
  double area_a = 0.0;             // m^2
  double area_b = 0.0;             // m^2
  double intersection_area = 0.0;  // m^2
  double union_area = 0.0;         // m^2
  double intersection_over_union = 0.0;
};

// Overlap of two polygons (each simple, any orientation) by exact boolean operations. When either is not a
// simple polygon, the intersection, union and their ratio are NaN.
MassOverlap mass_overlap(const Polyline& a, const Polyline& b);

}  // namespace coupling
