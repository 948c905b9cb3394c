#pragma once
// Building particle bodies: lattice fills of regions/polygons and box walls.
// Lattice convention: cell-centred, particles at ((i+1/2) dx, (j+1/2) dx) relative to the anchor (default origin),
// so bodies filled separately on the same anchor line up.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "sph/engine/particle_set.hpp"

namespace sph {

struct Point {
  double x = 0, y = 0;
};

// Lattice points inside the axis-aligned box [x_min, x_max] x [y_min, y_max] for which inside(x, y) is true.
std::vector<Point> lattice_points_in_region(double x_min, double y_min, double x_max, double y_max, double dx,
                                            const std::function<bool(double, double)>& inside,
                                            Point anchor = {});

// Lattice points inside a simple polygon (vertex list, either orientation; even-odd rule).
std::vector<Point> lattice_points_in_polygon(const std::vector<Point>& polygon, double dx, Point anchor = {});

bool point_in_polygon(const std::vector<Point>& polygon, double x, double y);

// The shortest distance from (x, y) to the polygon's edges (closed; either orientation) [m].
double distance_to_polygon_edges(const std::vector<Point>& polygon, double x, double y);

// The area of a simple polygon (either orientation) [m^2].
double polygon_area(const std::vector<Point>& polygon);

// Points in rows parallel to the edges of a simple polygon, inside it: row k (k = 0 .. layers - 1) at the distance
// (k + 1/2) dx from its edge, spaced about dx along it, so that a slanted face is smooth (a lattice fill would
// make it a staircase). A point is kept where it is inside the polygon, no closer than (k + 1/2) dx to any other
// edge (it belongs to row k) and further than 0.6 dx from the points already kept (where rows of two edges meet).
// For walls and rigid bodies of any shape; `layers` large enough fills the polygon.
std::vector<Point> boundary_layer_points(const std::vector<Point>& polygon, double dx, int layers);

// Appends soil particles at the given points: mass = density dx^2 (per metre width). Returns the count.
std::size_t add_soil(ParticleSet& particles, const std::vector<Point>& points, double dx, std::uint16_t material,
                     double density);

// Fixed wall particles around the inner box [x_min, x_max] x [y_min, y_min + height]:
// `layers` rows (0 = ceil(2h/dx), the kernel support) below the bottom and outside the sides. Fewer layers than
// the kernel support needs are refused (std::invalid_argument): soil next to a thin wall would miss part of its
// neighbourhood and could leak through.
struct BoxWalls {
  double x_min = 0, x_max = 1, y_min = 0, height = 1;
  bool left = true, right = true, bottom = true;
  int layers = 0;
};

// Appends the wall particles (kind wall, mass density dx^2, inward unit normals). Returns the count.
std::size_t add_box_walls(ParticleSet& particles, const BoxWalls& box, double dx, double h, std::uint16_t material,
                          double density);

// Fixed wall particles filling a solid polygon (a slope, a plane, an obstacle) in rows parallel to its faces
// (boundary_layer_points: `layers` rows, 0 = ceil(2h/dx), the kernel support), kind wall, mass density dx^2, each
// with the unit normal pointing out of the solid from its nearest point on the polygon's edges (on a flat face, the
// face's outward normal). Fewer layers than the kernel support needs are refused (std::invalid_argument). Returns the
// count.
std::size_t add_polygon_walls(ParticleSet& particles, const std::vector<Point>& polygon, double dx, double h,
                              int layers, std::uint16_t material, double density);

// Wall layer count that covers the kernel support 2h.
int wall_layers_for(double dx, double h);

}  // namespace sph
