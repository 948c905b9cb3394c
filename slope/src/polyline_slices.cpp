// Slicing the mass above a slip surface given as a polyline, with an optional tension crack at its upper end.
//
// The polyline runs left to right from one point on the ground surface to another, below the ground in between
// and not below the rigid base. Slice boundaries are put at every vertex of the polyline (the base is then straight
// within each slice), where a profile line or the piezometric line crosses it, and at the fixed breaks of the
// section (surcharge ends, edges of ponded water); the stretches between are split into near-equal slices as for a
// circle, and the slices are filled by the same code (Slicer::fill_from_bounds). Moments are taken about a stated
// point (SlipPolyline::moment_point); the base normal forces then have a moment too (SliceTable::normal_arm).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "slice_table.hpp"
#include "sphslope/units.hpp"
#include "slope/slices.hpp"

namespace slope::detail {

namespace {

std::string point_text(const Point& p) {
  std::ostringstream out;
  out.precision(6);
  out << "(" << p.x << ", " << p.y << ")";
  return out.str();
}

// Height of the polyline at x (x inside its range), linear between vertices.
double surface_y(const std::vector<Point>& s, double x) { return polyline_y(s, x); }

// The shape of the polyline alone: enough points, finite, x strictly increasing, inside the section.
std::string shape_error(const PreparedSection& ps, const std::vector<Point>& s) {
  if (s.size() < 2) return "a slip surface needs at least two points";
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (!std::isfinite(s[k].x) || !std::isfinite(s[k].y)) return "point " + std::to_string(k) + " is not finite";
    if (k > 0 && !(s[k].x > s[k - 1].x))
      return "the x of the points must increase strictly (point " + std::to_string(k) + " " + point_text(s[k]) +
             " is not right of the one before)";
  }
  if (s.front().x < ps.x_min || s.back().x > ps.x_max)
    return "the surface extends beyond the section (x from " + std::to_string(ps.x_min) + " to " +
           std::to_string(ps.x_max) + " m)";
  return {};
}

// Entry and exit on the ground, the rest below it and above the rigid base. tol: 1e-6 of the section's size.
std::string position_error(const PreparedSection& ps, const std::vector<Point>& s, double tol) {
  for (const Point* end : {&s.front(), &s.back()}) {
    const double g = ps.ground_at(end->x);
    if (std::fabs(end->y - g) > tol)
      return "the end point " + point_text(*end) + " is not on the ground surface (ground at y = " +
             std::to_string(g) + " m there)";
  }
  for (std::size_t k = 1; k + 1 < s.size(); ++k) {
    if (!(s[k].y < ps.ground_at(s[k].x) - tol))
      return "point " + std::to_string(k) + " " + point_text(s[k]) + " is not below the ground surface";
  }
  for (const Point& g : ps.ground)
    if (g.x > s.front().x && g.x < s.back().x && g.y < surface_y(s, g.x) - tol)
      return "the ground surface dips below the slip surface at x = " + std::to_string(g.x) +
             " m (the mass would be two masses)";
  for (std::size_t k = 0; k < s.size(); ++k)
    if (s[k].y < ps.bottom_y - tol)
      return "point " + std::to_string(k) + " " + point_text(s[k]) + " lies below the rigid base (bottom_y = " +
             std::to_string(ps.bottom_y) + " m)";
  return {};
}

// Concave upward in the direction of sliding: each segment's driving inclination is at most the one before it
// (plus the tolerance).
std::string kinematic_error(const std::vector<Point>& s, int dir, double tolerance) {
  const std::size_t n = s.size() - 1;
  double previous = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t k = dir > 0 ? j : n - 1 - j;  // segments from the entry
    const double angle = std::atan2(-(dir > 0 ? 1.0 : -1.0) * (s[k + 1].y - s[k].y), s[k + 1].x - s[k].x);
    if (j > 0 && angle > previous + tolerance + 1e-12)
      return "the surface turns convex at point " + std::to_string(dir > 0 ? k : k + 1) + " " +
             point_text(dir > 0 ? s[k] : s[k + 1]) +
             " (it steepens in the direction of sliding): not kinematically admissible for a mass of rigid slices";
    previous = angle;
  }
  return {};
}

// The lowest profile line at the ground at x: the material at the ground surface there.
std::size_t surface_line(const PreparedSection& ps, double x) {
  const double g = ps.ground_at(x);
  std::size_t line = 0;
  for (std::size_t k = 1; k < ps.lines.size(); ++k)
    if (ps.lines[k].y(x) >= g - 1e-9 * (1.0 + std::fabs(g))) line = k;
  return line;
}

// Every x inside (x0, x1) where the segment (x0, y0)-(x1, y1) crosses the line, appended to out.
void segment_crossings(const IndexedPolyline& line, const Point& a, const Point& b, std::vector<double>& out) {
  std::vector<double> xs{a.x};
  for (const Point& p : line.points())
    if (p.x > a.x && p.x < b.x) xs.push_back(p.x);
  xs.push_back(b.x);
  auto gap = [&](double x) { return line.y(x) - (a.y + (x - a.x) * (b.y - a.y) / (b.x - a.x)); };
  double g0 = gap(xs.front());
  for (std::size_t k = 1; k < xs.size(); ++k) {
    const double g1 = gap(xs[k]);
    if ((g0 > 0.0 && g1 < 0.0) || (g0 < 0.0 && g1 > 0.0)) {
      const double x = xs[k - 1] + (xs[k] - xs[k - 1]) * g0 / (g0 - g1);
      if (x > a.x && x < b.x) out.push_back(x);
    }
    g0 = g1;
  }
}

// Cuts the surface at a tension crack of depth z at its upper end: the crack stands where the surface first lies z
// below the ground, walking from the entry; the part of the surface above it is dropped. Returns false when the
// surface is nowhere that deep.
bool cut_at_crack(const PreparedSection& ps, std::vector<Point>& s, int dir, double z) {
  std::vector<double> xs;
  for (const Point& p : s) xs.push_back(p.x);
  for (const Point& g : ps.ground)
    if (g.x > s.front().x && g.x < s.back().x) xs.push_back(g.x);
  std::sort(xs.begin(), xs.end());
  if (dir < 0) std::reverse(xs.begin(), xs.end());
  auto depth = [&](double x) { return ps.ground_at(x) - surface_y(s, x); };
  double d0 = depth(xs.front());
  for (std::size_t k = 1; k < xs.size(); ++k) {
    const double d1 = depth(xs[k]);
    if (d1 >= z) {
      const double x = xs[k - 1] + (xs[k] - xs[k - 1]) * (z - d0) / (d1 - d0);
      const Point bottom{x, ps.ground_at(x) - z};
      std::vector<Point> cut;
      if (dir > 0) {
        cut.push_back(bottom);
        for (const Point& p : s)
          if (p.x > x) cut.push_back(p);
      } else {
        for (const Point& p : s)
          if (p.x < x) cut.push_back(p);
        cut.push_back(bottom);
      }
      s = std::move(cut);
      return true;
    }
    d0 = d1;
  }
  return false;
}

}  // namespace

double chord_depth(const std::vector<Point>& s) {
  if (s.size() < 2) return 0.0;
  const double lx = s.back().x - s.front().x;
  const double ly = s.back().y - s.front().y;
  const double chord = std::sqrt(lx * lx + ly * ly);
  if (!(chord > 0.0)) return 0.0;
  double depth = 0.0;
  for (const Point& p : s) {
    // below the chord: on the side of -normal, normal = (-ly, lx) / chord points up for lx > 0
    const double above = (-(p.x - s.front().x) * ly + (p.y - s.front().y) * lx) / chord;
    depth = std::max(depth, -above);
  }
  return depth;
}

// Checks the polyline, finds its direction, cuts it at a tension crack and slices the mass above it.
std::string Slicer::slice_polyline(const SlipPolyline& in, int target_slices, SliceTable& table) {
  const PreparedSection& ps = prepared_;
  const double tol = 1e-6 * (ps.x_max - ps.x_min + ps.ground_y_max - ps.bottom_y);
  std::vector<Point> s = in.points;
  if (std::string e = shape_error(ps, s); !e.empty()) return e;
  if (std::string e = position_error(ps, s, tol); !e.empty()) return e;
  s.front().y = ps.ground_at(s.front().x);
  s.back().y = ps.ground_at(s.back().x);
  if (std::fabs(s.front().y - s.back().y) <= tol)
    return "the entry and exit are at the same height: the direction of sliding is undefined";
  const int dir = s.front().y > s.back().y ? 1 : -1;
  if (std::string e = kinematic_error(s, dir, in.convex_tolerance); !e.empty()) return e;
  const Point moment_point = in.moment_point ? *in.moment_point : default_moment_point(s);
  if (!std::isfinite(moment_point.x) || !std::isfinite(moment_point.y)) return "the moment point is not finite";
  double z = 0.0, force = 0.0, force_y = 0.0;
  if (in.tension_crack) {
    const double entry_x = dir > 0 ? s.front().x : s.back().x;
    const std::size_t line = surface_line(ps, entry_x);
    // the Rankine depth from the cohesion at the ground where the surface enters (with its increase with depth)
    // (a strength envelope: its tangent at zero normal stress)
    double c = ps.cohesion_at(line, entry_x, ps.ground_at(entry_x));
    double tan_phi = ps.line_tan_phi[line];
    if (const int e = ps.material_envelope[ps.line_material[line]]; e >= 0) {
      const EnvelopePoint p = envelope_at(ps.envelopes[static_cast<std::size_t>(e)], 0.0);
      c = p.shear;
      tan_phi = p.slope;
    }
    const Material soil{"", ps.line_unit_weight[line], c, std::atan(tan_phi)};
    z = in.tension_crack->depth ? *in.tension_crack->depth : rankine_crack_depth(soil);
    if (!(z >= 0.0) || !std::isfinite(z)) return "the tension crack depth is not a non-negative number";
    if (z > 0.0 && !cut_at_crack(ps, s, dir, z))
      return "the tension crack (" + std::to_string(z) + " m deep) reaches below the slip surface everywhere: the " +
             "mass is nowhere that deep";
    if (z > 0.0 && in.tension_crack->water_filled) {
      const double gw = ps.has_water ? ps.water_unit_weight : 9810.0;
      force = 0.5 * gw * z * z;
      force_y = (dir > 0 ? s.front().y : s.back().y) + z / 3.0;
    }
  }
  const double xl = s.front().x, xr = s.back().x;
  if (xr - xl < 1e-7 * (ps.x_max - ps.x_min)) return "the slip mass is vanishingly small";
  breaks_.clear();
  for (std::size_t k = 1; k + 1 < s.size(); ++k) breaks_.push_back(s[k].x);
  for (double b : ps.fixed_breaks)
    if (b > xl && b < xr) breaks_.push_back(b);
  for (std::size_t k = 0; k + 1 < s.size(); ++k) {
    for (std::size_t j = 1; j < ps.lines.size(); ++j) segment_crossings(ps.lines[j], s[k], s[k + 1], breaks_);
    if (ps.has_water) segment_crossings(ps.piezometric_line, s[k], s[k + 1], breaks_);
  }
  std::sort(breaks_.begin(), breaks_.end());
  if (place_bounds(xl, xr, target_slices) < 1) return "the slip mass is vanishingly small";
  arc_y_.resize(bounds_.size());
  ground_y_.resize(bounds_.size());
  for (std::size_t j = 0; j < bounds_.size(); ++j) {
    arc_y_[j] = surface_y(s, bounds_[j]);
    ground_y_[j] = ps.ground_line().y(bounds_[j]);
  }
  fill_from_bounds(dir, table, nullptr);
  table.circular = false;
  table.circle = Circle{moment_point.x, moment_point.y, 0.0};
  table.chord_depth = chord_depth(s);
  table.crack_depth = z;
  table.crack_force = force;
  table.crack_force_y = force_y;
  table.surface = std::move(s);
  find_support_crossings(ps.reinforcement, table);
  find_line_loads(ps, table);
  table.passive_scale = 1.0;
  table.compute_loads();
  return {};
}

}  // namespace slope::detail

namespace slope {

std::optional<SlipMass> slice_polyline(const Section& section, const SlipPolyline& surface,
                                       const SliceOptions& options, std::string* reason) {
  if (const std::string error = section_error(section); !error.empty()) {
    if (reason != nullptr) *reason = "invalid section: " + error;
    return std::nullopt;
  }
  detail::Slicer slicer(section);
  detail::SliceTable table;
  const std::string error = slicer.slice_polyline(surface, options.slices, table);
  if (!error.empty()) {
    if (reason != nullptr) *reason = error;
    return std::nullopt;
  }
  SlipMass mass;
  detail::table_to_mass(table, mass);
  if (reason != nullptr) reason->clear();
  return mass;
}

double rankine_crack_depth(const Material& material) {
  const double ka = std::pow(std::tan(0.25 * sphslope::pi - 0.5 * material.friction_angle), 2);
  if (!(material.unit_weight > 0.0) || !(ka > 0.0)) return 0.0;
  return 2.0 * material.cohesion / (material.unit_weight * std::sqrt(ka));
}

std::optional<SlipPolyline> circle_as_polyline(const Section& section, const Circle& circle, int segments,
                                               std::string* reason) {
  const auto mass = slice_circle(section, circle, SliceOptions{}, reason);
  if (!mass) return std::nullopt;
  const Point left = mass->direction > 0 ? mass->entry : mass->exit;
  const Point right = mass->direction > 0 ? mass->exit : mass->entry;
  // angle from the downward vertical through the centre: x = xc + R sin t, y = yc - R cos t
  const double t0 = std::atan2(left.x - circle.xc, circle.yc - left.y);
  const double t1 = std::atan2(right.x - circle.xc, circle.yc - right.y);
  const int n = std::max(1, segments);
  SlipPolyline out;
  out.points.push_back(left);
  for (int k = 1; k < n; ++k) {
    const double t = t0 + (t1 - t0) * k / n;
    out.points.push_back({circle.xc + circle.radius * std::sin(t), circle.yc - circle.radius * std::cos(t)});
  }
  out.points.push_back(right);
  out.moment_point = Point{circle.xc, circle.yc};
  return out;
}

Point default_moment_point(const std::vector<Point>& s) {
  const Point a = s.front();
  const Point b = s.back();
  const double lx = b.x - a.x;
  const double ly = b.y - a.y;
  const double chord = std::sqrt(lx * lx + ly * ly);
  // the point farthest below the chord
  Point deepest = a;
  double depth = 0.0;
  for (const Point& p : s) {
    const double below = ((p.x - a.x) * ly - (p.y - a.y) * lx) / chord;
    if (below > depth) {
      depth = below;
      deepest = p;
    }
  }
  const Point mid{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  const Point up{-ly / chord, lx / chord};  // unit normal of the chord pointing up (lx > 0)
  if (!(depth > 1e-6 * chord)) return Point{mid.x + chord * up.x, mid.y + chord * up.y};
  // circumcentre of a, b, deepest
  const double bx = b.x - a.x, by = b.y - a.y, cx = deepest.x - a.x, cy = deepest.y - a.y;
  const double d = 2.0 * (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return Point{a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

}  // namespace slope
