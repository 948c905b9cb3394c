// Critical-circle search, step 1: the coarse trial circles (no user settings needed).
//  - entry-exit (default, or with entry/exit ranges and/or a radius range): points on the ground surface (an even
//    grid over the whole section plus the vertices that shape the ground, at most as many as the grid); for every
//    pair where one point is higher than the other, circles through both with the centre above the chord:
//    half-angles from a near-chord circle to a near-semicircle, plus the circle through both points tangent to the
//    rigid base (the deepest admissible one); with a radius range, radii from that range instead;
//  - grid-and-radius (when a centre grid is given): every grid centre with radii from the range, or automatic radii
//    from the one that just reaches the ground to the one tangent to the rigid base.
#include "search_internal.hpp"
#include "sphslope/units.hpp"

namespace slope::detail {

namespace {

// Circle through p and q with the given radius and its centre above the chord (the arc between them below it).
std::optional<Circle> circle_through(const Point& p, const Point& q, double radius) {
  const double ux = q.x - p.x;
  const double uy = q.y - p.y;
  const double length = std::sqrt(ux * ux + uy * uy);
  if (!(length > 0.0) || radius < 0.5 * length) return std::nullopt;
  double nx = -uy / length, ny = ux / length;
  if (ny < 0.0) {
    nx = -nx;
    ny = -ny;
  }
  const double h = std::sqrt(std::max(0.0, radius * radius - 0.25 * length * length));
  return Circle{0.5 * (p.x + q.x) + nx * h, 0.5 * (p.y + q.y) + ny * h, radius};
}

// Circles through p and q tangent to the horizontal line y = base (both points above it).
void circles_tangent_to_base(const Point& p, const Point& q, double base, std::vector<Circle>& out) {
  const double ap = p.y - base;
  const double aq = q.y - base;
  if (!(ap > 0.0) || !(aq > 0.0)) return;
  // yc = ((xp - xc)^2 + yp^2 - base^2) / (2 ap), the same with q; equate -> a xc^2 + b xc + c = 0
  const double kp = p.x * p.x + p.y * p.y - base * base;
  const double kq = q.x * q.x + q.y * q.y - base * base;
  const double a = aq - ap;
  const double b = -2.0 * (p.x * aq - q.x * ap);
  const double c = kp * aq - kq * ap;
  double roots[2];
  int count = 0;
  if (std::fabs(a) < 1e-12 * (std::fabs(b) + 1e-300)) {
    if (b != 0.0) roots[count++] = -c / b;
  } else {
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return;
    const double sq = std::sqrt(disc);
    roots[count++] = (-b + sq) / (2.0 * a);
    roots[count++] = (-b - sq) / (2.0 * a);
  }
  for (int i = 0; i < count; ++i) {
    const double xc = roots[i];
    const double yc = ((p.x - xc) * (p.x - xc) + p.y * p.y - base * base) / (2.0 * ap);
    const double radius = yc - base;
    if (radius > 0.0 && std::isfinite(radius)) out.push_back(Circle{xc, yc, radius});
  }
}

double distance_to_polyline(const std::vector<Point>& line, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const double dx = line[i + 1].x - line[i].x;
    const double dy = line[i + 1].y - line[i].y;
    const double t = std::clamp(((x - line[i].x) * dx + (y - line[i].y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    const double ex = line[i].x + t * dx - x;
    const double ey = line[i].y + t * dy - y;
    best = std::min(best, std::sqrt(ex * ex + ey * ey));
  }
  return best;
}


// Indices of the ground vertices that shape the profile: the Douglas-Peucker simplification of the ground to
// within `tolerance` (m), ends excluded. Collinear vertices are never kept, so splitting a segment changes nothing.
std::vector<std::size_t> shape_vertices(const std::vector<Point>& ground, double tolerance) {
  std::vector<std::size_t> kept;
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, ground.size() - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    if (b <= a + 1) continue;
    const double ux = ground[b].x - ground[a].x;
    const double uy = ground[b].y - ground[a].y;
    const double length = std::hypot(ux, uy);
    double farthest = -1.0;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = std::fabs((ground[i].x - ground[a].x) * uy - (ground[i].y - ground[a].y) * ux) / length;
      if (d > farthest) {
        farthest = d;
        at = i;
      }
    }
    if (!(farthest > tolerance)) continue;
    kept.push_back(at);
    stack.push_back({a, at});
    stack.push_back({at, b});
  }
  return kept;
}

// The ground vertices offered as entry and exit points besides the even grid: those that shape the profile (its
// crest, toe and breaks of slope), at most `count` of them. The tolerance starts at 0.1 % of the relief and is
// doubled until few enough remain, so a hand-drawn section keeps all its corners and a surveyed profile of tens
// of thousands of vertices offers its main breaks only (the refinement then moves freely between vertices).
std::vector<double> shape_vertex_xs(const PreparedSection& ps, std::size_t count) {
  const double relief = ps.ground_y_max - ps.ground_y_min;
  std::vector<std::size_t> kept;
  for (double tolerance = 1e-3 * relief;; tolerance *= 2.0) {
    kept = shape_vertices(ps.ground, tolerance);
    if (kept.size() <= count || !(tolerance < relief)) break;
  }
  std::vector<double> xs{ps.ground.front().x, ps.ground.back().x};
  for (std::size_t i : kept) xs.push_back(ps.ground[i].x);
  return xs;
}

std::vector<double> ground_samples(const PreparedSection& ps, std::optional<Range> range, int count) {
  Range r{ps.x_min, ps.x_max};
  if (range) {
    r = ordered(*range);
    r.min = std::max(r.min, ps.x_min);
    r.max = std::min(r.max, ps.x_max);
    if (r.min > r.max) return {};
  }
  std::vector<double> xs = linspace(r.min, r.max, count);
  for (double x : shape_vertex_xs(ps, static_cast<std::size_t>(std::max(count, 1))))
    if (x >= r.min && x <= r.max) xs.push_back(x);
  std::sort(xs.begin(), xs.end());
  const double tol = 1e-6 * (ps.x_max - ps.x_min);
  xs.erase(std::unique(xs.begin(), xs.end(), [tol](double a, double b) { return b - a < tol; }), xs.end());
  return xs;
}

}  // namespace

std::vector<Circle> entry_exit_circles(const PreparedSection& ps, const SearchLimits& limits, int samples) {
  std::vector<Circle> circles;
  // A user range is narrower than the whole ground line: it gets 17 of the default 41 points, in proportion.
  const int limited = std::max(3, (samples * 17 + 20) / 41);
  const std::vector<double> entries = ground_samples(ps, limits.entry_x, limits.entry_x ? limited : samples);
  const std::vector<double> exits = ground_samples(ps, limits.exit_x, limits.exit_x ? limited : samples);
  const double relief = ps.ground_y_max - ps.ground_y_min;
  const double tol_y = 1e-3 * relief + 1e-12;
  const double min_chord = 1e-3 * (ps.x_max - ps.x_min);
  static constexpr double half_angles_deg[] = {4, 10, 17, 24, 32, 40, 49, 58, 68, 80};
  for (double xe : entries) {
    const Point p{xe, ps.ground_at(xe)};
    for (double xx : exits) {
      const Point q{xx, ps.ground_at(xx)};
      if (!(p.y > q.y + tol_y) || std::fabs(p.x - q.x) < min_chord) continue;
      const double length = std::hypot(q.x - p.x, q.y - p.y);
      if (limits.radius) {
        const Range rr = ordered(*limits.radius);
        for (double radius : linspace(rr.min, rr.max, 8))
          if (auto c = circle_through(p, q, radius)) circles.push_back(*c);
      } else {
        for (double deg : half_angles_deg) {
          // deg * pi / 180, not radians(deg): this order of operations gives the pinned circles.
          const double radius = 0.5 * length / std::sin(deg * sphslope::pi / 180.0);
          if (auto c = circle_through(p, q, radius)) circles.push_back(*c);
        }
        circles_tangent_to_base(p, q, ps.bottom_y, circles);
      }
    }
  }
  return circles;
}

std::vector<Circle> grid_circles(const PreparedSection& ps, const CentreGrid& grid,
                                 const std::optional<Range>& radius_range) {
  std::vector<Circle> circles;
  for (double xc : linspace(grid.x.min, grid.x.max, std::max(1, grid.nx))) {
    for (double yc : linspace(grid.y.min, grid.y.max, std::max(1, grid.ny))) {
      if (radius_range) {
        const Range rr = ordered(*radius_range);
        for (double radius : linspace(rr.min, rr.max, 10)) circles.push_back(Circle{xc, yc, radius});
        continue;
      }
      const double r_lo = distance_to_polyline(ps.ground, xc, yc);
      const double r_hi = yc - ps.bottom_y;
      if (!(r_hi > r_lo)) continue;
      for (int k = 1; k <= 12; ++k) circles.push_back(Circle{xc, yc, r_lo + (r_hi - r_lo) * k / 12.0});
    }
  }
  return circles;
}

}  // namespace slope::detail
