#include "coupling/compare/sliding_mass.hpp"

// g++ 12 with -fsanitize=address,undefined reports a false "may be used uninitialized" in std::pair (stl_pair.h)
// when CGAL's boolean operations are inlined here; the warning is silenced for this file only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <list>

namespace coupling {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

Polygon to_cgal(const Polyline& points) {
  Polygon polygon;
  for (const auto& p : points) {
    const Kernel::Point_2 q(p.x, p.y);
    if (polygon.is_empty() || polygon.vertex(polygon.size() - 1) != q) polygon.push_back(q);
  }
  while (polygon.size() > 1 && polygon.vertex(0) == polygon.vertex(polygon.size() - 1))
    polygon.erase(std::prev(polygon.vertices_end()));
  if (polygon.size() >= 3 && polygon.is_clockwise_oriented()) polygon.reverse_orientation();
  return polygon;
}

double area_of(const PolygonWithHoles& region) {
  double area = CGAL::to_double(region.outer_boundary().area());
  for (auto hole = region.holes_begin(); hole != region.holes_end(); ++hole) area += CGAL::to_double(hole->area());
  return std::abs(area) > 0.0 ? area : 0.0;  // holes are clockwise: their areas are negative
}

}  // namespace

Polyline sliding_mass_polygon(const Polyline& ground, const Polyline& slip_surface) {
  Polyline polygon;
  if (slip_surface.size() < 2) return polygon;
  for (const auto& p : slip_surface) polygon.push_back({p.x, std::min(p.y, polyline_height(ground, p.x))});
  const double x_from = slip_surface.front().x, x_to = slip_surface.back().x;
  polygon.push_back({x_to, polyline_height(ground, x_to)});
  for (auto it = ground.rbegin(); it != ground.rend(); ++it)
    if (it->x < x_to && it->x > x_from) polygon.push_back(*it);
  polygon.push_back({x_from, polyline_height(ground, x_from)});
  return polygon;
}

double polygon_area(const Polyline& polygon) {
  double twice = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const auto& p = polygon[k];
    const auto& q = polygon[(k + 1) % polygon.size()];
    twice += p.x * q.y - q.x * p.y;
  }
  return 0.5 * std::abs(twice);
}

MassOverlap mass_overlap(const Polyline& a, const Polyline& b) {
  MassOverlap overlap;
  const Polygon pa = to_cgal(a), pb = to_cgal(b);
  if (pa.size() < 3 || pb.size() < 3 || !pa.is_simple() || !pb.is_simple()) {
    // Not a region: say so (NaN is written as null in the report) rather than report no overlap.
    overlap.intersection_over_union = overlap.intersection_area = overlap.union_area = std::nan("");
    return overlap;
  }
  overlap.area_a = std::abs(CGAL::to_double(pa.area()));
  overlap.area_b = std::abs(CGAL::to_double(pb.area()));
  std::list<PolygonWithHoles> pieces;
  CGAL::intersection(pa, pb, std::back_inserter(pieces));
  for (const auto& piece : pieces) overlap.intersection_area += area_of(piece);
  PolygonWithHoles joined;
  if (CGAL::join(pa, pb, joined)) {
    overlap.union_area = area_of(joined);
  } else {
    overlap.union_area = overlap.area_a + overlap.area_b;  // disjoint
  }
  overlap.intersection_over_union = overlap.union_area > 0.0 ? overlap.intersection_area / overlap.union_area : 0.0;
  return overlap;
}

}  // namespace coupling
