#include "sph/engine/fill.hpp"

#include <algorithm>
#include <limits>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace sph {

std::vector<Point> lattice_points_in_region(double x_min, double y_min, double x_max, double y_max, double dx,
                                            const std::function<bool(double, double)>& inside, Point anchor) {
  if (!(dx > 0)) throw std::invalid_argument("lattice fill: dx must be > 0");
  std::vector<Point> out;
  const auto i0 = static_cast<long long>(std::floor((x_min - anchor.x) / dx - 0.5)) - 1;
  const auto i1 = static_cast<long long>(std::ceil((x_max - anchor.x) / dx - 0.5)) + 1;
  const auto j0 = static_cast<long long>(std::floor((y_min - anchor.y) / dx - 0.5)) - 1;
  const auto j1 = static_cast<long long>(std::ceil((y_max - anchor.y) / dx - 0.5)) + 1;
  for (long long j = j0; j <= j1; ++j) {
    const double y = anchor.y + (static_cast<double>(j) + 0.5) * dx;
    if (y < y_min || y > y_max) continue;
    for (long long i = i0; i <= i1; ++i) {
      const double x = anchor.x + (static_cast<double>(i) + 0.5) * dx;
      if (x < x_min || x > x_max) continue;
      if (inside(x, y)) out.push_back({x, y});
    }
  }
  return out;
}

bool point_in_polygon(const std::vector<Point>& poly, double x, double y) {
  bool in = false;
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = poly[i];
    const Point& b = poly[j];
    if ((a.y > y) != (b.y > y)) {
      const double xc = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (x < xc) in = !in;
    }
  }
  return in;
}

double distance_to_polygon_edges(const std::vector<Point>& poly, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const double ex = poly[i].x - poly[j].x, ey = poly[i].y - poly[j].y, len2 = ex * ex + ey * ey;
    double t = len2 > 0 ? ((x - poly[j].x) * ex + (y - poly[j].y) * ey) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    best = std::min(best, std::hypot(x - poly[j].x - t * ex, y - poly[j].y - t * ey));
  }
  return best;
}

double polygon_area(const std::vector<Point>& poly) {
  double twice = 0;
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) twice += poly[j].x * poly[i].y - poly[i].x * poly[j].y;
  return 0.5 * std::abs(twice);
}

namespace {

// Row k of edge a -> b of a counter-clockwise polygon: the points spaced about dx on the edge moved inward (to the
// left) by (k + 1/2) dx, over the edge's length (the ends are settled by the keep rules of boundary_layer_points).
void edge_row(const Point& a, const Point& b, double offset, double dx, std::vector<Point>& out) {
  const double ex = b.x - a.x, ey = b.y - a.y, len = std::hypot(ex, ey);
  if (!(len > 0)) return;
  const double tx = ex / len, ty = ey / len, nx = -ty, ny = tx;  // inward normal of a counter-clockwise polygon
  const auto count = static_cast<int>(std::max(1.0, std::round(len / dx)));
  const double step = len / count;
  for (int m = 0; m < count; ++m) {
    const double s = (m + 0.5) * step;
    out.push_back({a.x + s * tx + offset * nx, a.y + s * ty + offset * ny});
  }
}

std::int64_t cell_key(std::int64_t a, std::int64_t b) { return (a << 32) ^ (b & 0xffffffffLL); }

}  // namespace

std::vector<Point> boundary_layer_points(const std::vector<Point>& polygon, double dx, int layers) {
  if (polygon.size() < 3) throw std::invalid_argument("boundary layer fill: a polygon needs at least 3 vertices");
  if (!(dx > 0) || layers < 1) throw std::invalid_argument("boundary layer fill: dx > 0 and layers >= 1 needed");
  std::vector<Point> poly = polygon;
  double twice = 0;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    twice += poly[j].x * poly[i].y - poly[i].x * poly[j].y;
  if (twice < 0) std::reverse(poly.begin(), poly.end());  // counter-clockwise: the inside is on the left
  std::vector<Point> kept;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> grid;  // kept points by cell of side dx
  const double too_close2 = 0.36 * dx * dx;
  const double tolerance = 1e-9 * dx;
  for (int k = 0; k < layers; ++k) {
    const double offset = (k + 0.5) * dx;
    std::vector<Point> row;
    for (std::size_t i = 0; i < poly.size(); ++i) edge_row(poly[i], poly[(i + 1) % poly.size()], offset, dx, row);
    std::size_t added = 0;
    for (const Point& q : row) {
      if (!point_in_polygon(poly, q.x, q.y)) continue;
      if (distance_to_polygon_edges(poly, q.x, q.y) < offset - tolerance) continue;
      const std::int64_t cx = static_cast<std::int64_t>(std::floor(q.x / dx));
      const std::int64_t cy = static_cast<std::int64_t>(std::floor(q.y / dx));
      bool crowded = false;
      for (std::int64_t a = cx - 1; a <= cx + 1 && !crowded; ++a)
        for (std::int64_t b = cy - 1; b <= cy + 1 && !crowded; ++b) {
          const auto cell = grid.find(cell_key(a, b));
          if (cell == grid.end()) continue;
          for (const std::size_t o : cell->second)
            if ((kept[o].x - q.x) * (kept[o].x - q.x) + (kept[o].y - q.y) * (kept[o].y - q.y) < too_close2) {
              crowded = true;
              break;
            }
        }
      if (crowded) continue;
      grid[cell_key(cx, cy)].push_back(kept.size());
      kept.push_back(q);
      ++added;
    }
    if (added == 0) break;  // the rows have met in the middle: the polygon is full
  }
  return kept;
}

std::vector<Point> lattice_points_in_polygon(const std::vector<Point>& polygon, double dx, Point anchor) {
  if (polygon.size() < 3) throw std::invalid_argument("lattice fill: a polygon needs at least 3 vertices");
  double x0 = polygon[0].x, x1 = x0, y0 = polygon[0].y, y1 = y0;
  for (const auto& p : polygon) {
    x0 = std::min(x0, p.x); x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y); y1 = std::max(y1, p.y);
  }
  return lattice_points_in_region(
      x0, y0, x1, y1, dx, [&](double x, double y) { return point_in_polygon(polygon, x, y); }, anchor);
}

std::size_t add_soil(ParticleSet& particles, const std::vector<Point>& points, double dx, std::uint16_t material,
                     double density) {
  if (!(dx > 0) || !(density > 0)) throw std::invalid_argument("add_soil: dx and density must be > 0");
  particles.reserve(particles.size() + points.size());
  for (const auto& p : points) particles.add(p.x, p.y, density * dx * dx, density, material, ParticleKind::material);
  return points.size();
}

int wall_layers_for(double dx, double h) { return static_cast<int>(std::ceil(2.0 * h / dx - 1e-9)); }

std::size_t add_box_walls(ParticleSet& particles, const BoxWalls& box, double dx, double h, std::uint16_t material,
                          double density) {
  if (!(dx > 0) || !(h > 0) || !(density > 0)) throw std::invalid_argument("add_box_walls: dx, h, density must be > 0");
  if (!(box.x_max > box.x_min) || !(box.height > 0)) throw std::invalid_argument("add_box_walls: empty box");
  const int needed = wall_layers_for(dx, h);
  if (box.layers < 0 || (box.layers > 0 && box.layers < needed))
    throw std::invalid_argument("add_box_walls: " + std::to_string(box.layers) +
                                " wall layers do not cover the kernel support 2h = " + std::to_string(2.0 * h) +
                                " m; at least " + std::to_string(needed) + " are needed");
  const int layers = box.layers > 0 ? box.layers : needed;
  const double m = density * dx * dx;
  const double s = 1.0 / std::sqrt(2.0);
  std::size_t count = 0;
  const auto nx = static_cast<long long>(std::llround((box.x_max - box.x_min) / dx));
  const auto ny = static_cast<long long>(std::llround(box.height / dx));
  // Inward unit normals: a field of the wall particles (the same spec as the soil model's registration).
  const FieldId normal_x = particles.add_field({"wall_normal_x", true, false});
  const FieldId normal_y = particles.add_field({"wall_normal_y", true, false});
  auto put = [&](double x, double y, double nxv, double nyv) {
    const std::size_t i = particles.add(x, y, m, density, material, ParticleKind::wall);
    particles.field(normal_x)[i] = nxv;
    particles.field(normal_y)[i] = nyv;
    ++count;
  };
  if (box.bottom) {
    const long long i_lo = box.left ? -layers : 0;
    const long long i_hi = box.right ? nx + layers : nx;
    for (int k = 0; k < layers; ++k) {
      const double y = box.y_min - (k + 0.5) * dx;
      for (long long i = i_lo; i < i_hi; ++i) {
        const double x = box.x_min + (static_cast<double>(i) + 0.5) * dx;
        double nxv = 0, nyv = 1;
        if (i < 0) { nxv = s; nyv = s; }
        if (i >= nx) { nxv = -s; nyv = s; }
        put(x, y, nxv, nyv);
      }
    }
  }
  for (long long j = 0; j < ny; ++j) {
    const double y = box.y_min + (static_cast<double>(j) + 0.5) * dx;
    for (int k = 0; k < layers; ++k) {
      if (box.left) put(box.x_min - (k + 0.5) * dx, y, 1.0, 0.0);
      if (box.right) put(box.x_max + (k + 0.5) * dx, y, -1.0, 0.0);
    }
  }
  return count;
}

namespace {

// The point of the polygon's edges nearest to (x, y).
Point nearest_on_edges(const std::vector<Point>& poly, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  Point at{x, y};
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const double ex = poly[i].x - poly[j].x, ey = poly[i].y - poly[j].y, len2 = ex * ex + ey * ey;
    const double t = std::clamp(len2 > 0 ? ((x - poly[j].x) * ex + (y - poly[j].y) * ey) / len2 : 0.0, 0.0, 1.0);
    const Point q{poly[j].x + t * ex, poly[j].y + t * ey};
    const double d = std::hypot(x - q.x, y - q.y);
    if (d < best) {
      best = d;
      at = q;
    }
  }
  return at;
}

}  // namespace

std::size_t add_polygon_walls(ParticleSet& particles, const std::vector<Point>& polygon, double dx, double h,
                              int layers, std::uint16_t material, double density) {
  if (!(dx > 0) || !(h > 0) || !(density > 0))
    throw std::invalid_argument("add_polygon_walls: dx, h, density must be > 0");
  const int needed = wall_layers_for(dx, h);
  if (layers < 0 || (layers > 0 && layers < needed))
    throw std::invalid_argument("add_polygon_walls: " + std::to_string(layers) +
                                " wall layers do not cover the kernel support 2h = " + std::to_string(2.0 * h) +
                                " m; at least " + std::to_string(needed) + " are needed");
  const std::vector<Point> points = boundary_layer_points(polygon, dx, layers > 0 ? layers : needed);
  const FieldId normal_x = particles.add_field({"wall_normal_x", true, false});
  const FieldId normal_y = particles.add_field({"wall_normal_y", true, false});
  const double m = density * dx * dx;
  particles.reserve(particles.size() + points.size());
  for (const Point& q : points) {
    const Point b = nearest_on_edges(polygon, q.x, q.y);
    const double d = std::hypot(b.x - q.x, b.y - q.y);  // at least dx/2: the rows lie inside
    const std::size_t i = particles.add(q.x, q.y, m, density, material, ParticleKind::wall);
    particles.field(normal_x)[i] = (b.x - q.x) / d;
    particles.field(normal_y)[i] = (b.y - q.y) / d;
  }
  return points.size();
}

}  // namespace sph
