// Reinforcement elements (slope/reinforcement.hpp): their defaults and capacity, where a slip surface crosses them
// and the force each puts on its slice (slice_table.hpp).
#include "slope/reinforcement.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "slice_table.hpp"

namespace slope {

double Reinforcement::length() const { return std::hypot(tail.x - head.x, tail.y - head.y); }

Reinforcement reinforcement_defaults(SupportType type) {
  Reinforcement e;
  e.type = type;
  switch (type) {
    case SupportType::soil_nail: break;  // bonded over its length, along, passive
    case SupportType::tieback: e.application = SupportApplication::active; break;
    case SupportType::end_anchored:
      e.bond_strength = 0.0;
      e.application = SupportApplication::active;
      break;
    case SupportType::geosynthetic:
      e.direction = SupportDirection::tangent;
      e.application = SupportApplication::active;
      break;
    case SupportType::pile:
      e.direction = SupportDirection::tangent;
      e.application = SupportApplication::active;
      break;
  }
  return e;
}

void set_tensile_capacity(Reinforcement& e, double capacity) {
  e.tensile_capacity = capacity;
  if (e.type == SupportType::soil_nail || e.type == SupportType::tieback || e.type == SupportType::end_anchored)
    e.head_capacity = capacity;
  if (e.type == SupportType::end_anchored) e.tail_capacity = capacity;
}

namespace {

// The pull-out resistance of the bonded part of [from, to] (m from the head): bond times the bonded length, with an
// unlimited bond where any of it is bonded.
double bonded_resistance(const Reinforcement& e, double from, double to) {
  const double start = std::max(from, e.bond_start);
  const double end = std::min({to, e.bond_end, e.length()});
  const double length = end - start;
  if (!(length > 0.0) || !(e.bond_strength > 0.0)) return 0.0;
  return std::isinf(e.bond_strength) ? e.bond_strength : e.bond_strength * length;
}

}  // namespace

double capacity_at(const Reinforcement& e, double s) {
  if (e.type == SupportType::pile) return e.shear_capacity;
  const double length = e.length();
  const double head_side = e.head_capacity + bonded_resistance(e, 0.0, s);
  const double tail_side = e.tail_capacity + bonded_resistance(e, s, length);
  return std::min({e.tensile_capacity, head_side, tail_side});
}

std::string reinforcement_error(const Reinforcement& e) {
  std::ostringstream out;
  auto finite_points = std::isfinite(e.head.x) && std::isfinite(e.head.y) && std::isfinite(e.tail.x) &&
                       std::isfinite(e.tail.y);
  if (!finite_points) out << "its head and tail must be finite points";
  else if (!(e.length() > 0.0)) out << "its head and tail are the same point (length 0)";
  else if (!(e.spacing > 0.0) || !std::isfinite(e.spacing)) out << "spacing must be a positive length in m";
  else if (e.type == SupportType::pile && !(e.shear_capacity > 0.0 && std::isfinite(e.shear_capacity)))
    out << "a pile needs a positive finite shear capacity";
  else if (e.type != SupportType::pile && !(e.tensile_capacity > 0.0 && std::isfinite(e.tensile_capacity)))
    out << "a tensile element needs a positive finite tensile capacity";
  else if (!(e.head_capacity >= 0.0) || !(e.tail_capacity >= 0.0) || !(e.bond_strength >= 0.0))
    out << "its end capacities and bond strength must not be negative";
  else if (!(e.bond_start >= 0.0) || !(e.bond_end > e.bond_start))
    out << "its bonded part must start at or after the head and end after it starts";
  else if (e.type == SupportType::tieback && !(e.bond_start < e.length()))
    out << "its bond length must lie within the element (bond length <= length)";
  else if (e.direction == SupportDirection::angle &&
           !(std::fabs(e.force_angle) <= 0.5 * 3.141592653589793 && std::isfinite(e.force_angle)))
    out << "its force angle must lie between -90 and 90 degrees";
  else if (e.type == SupportType::pile &&
           (e.direction == SupportDirection::along || e.direction == SupportDirection::bisector))
    out << "a pile's shear acts tangent to the slip surface, perpendicular to the pile or at an angle";
  return out.str();
}

namespace detail {

namespace {

// The least parameter t in [0, 1] of the segment head + t (tail - head) on the circle's lower arc between
// x_lo and x_hi; a negative value when there is none.
double circle_crossing(const Circle& c, Point h, Point d, double x_lo, double x_hi) {
  const double fx = h.x - c.xc, fy = h.y - c.yc;
  const double a = d.x * d.x + d.y * d.y;
  const double b = 2.0 * (d.x * fx + d.y * fy);
  const double k = fx * fx + fy * fy - c.radius * c.radius;
  const double disc = b * b - 4.0 * a * k;
  if (!(disc >= 0.0) || !(a > 0.0)) return -1.0;
  const double root = std::sqrt(disc);
  for (double t : {(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)}) {
    const double x = h.x + t * d.x, y = h.y + t * d.y;
    if (t >= 0.0 && t <= 1.0 && y <= c.yc && x >= x_lo && x <= x_hi) return t;
  }
  return -1.0;
}

// As circle_crossing, on a polyline surface.
double polyline_crossing(const std::vector<Point>& surface, Point h, Point d, double x_lo, double x_hi) {
  double best = -1.0;
  for (std::size_t j = 0; j + 1 < surface.size(); ++j) {
    const Point p = surface[j];
    const Point q{surface[j + 1].x - p.x, surface[j + 1].y - p.y};
    const double den = d.x * q.y - d.y * q.x;
    if (den == 0.0) continue;  // parallel
    const double wx = p.x - h.x, wy = p.y - h.y;
    const double t = (wx * q.y - wy * q.x) / den;  // along the element
    const double u = (wx * d.y - wy * d.x) / den;  // along the surface segment
    if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) continue;
    const double x = h.x + t * d.x;
    if (x < x_lo || x > x_hi) continue;
    if (best < 0.0 || t < best) best = t;
  }
  return best;
}

// Unit direction of an element's force on the mass at slice i's base (global frame).
Point force_direction(const Reinforcement& e, const SliceTable& t, int i) {
  const double dir = t.direction >= 0 ? 1.0 : -1.0;
  const Point slide{dir * t.cos_a[i], -t.sin_a[i]};  // the direction of sliding along the base
  const double length = e.length();
  const Point along{(e.tail.x - e.head.x) / length, (e.tail.y - e.head.y) / length};
  switch (e.direction) {
    case SupportDirection::along: return along;
    case SupportDirection::tangent: return Point{-slide.x, -slide.y};
    case SupportDirection::bisector: {
      const Point sum{along.x - slide.x, along.y - slide.y};
      const double norm = std::hypot(sum.x, sum.y);
      return norm > 0.0 ? Point{sum.x / norm, sum.y / norm} : along;
    }
    case SupportDirection::perpendicular: {
      const Point p{-along.y, along.x};
      return p.x * slide.x + p.y * slide.y > 0.0 ? Point{-p.x, -p.y} : p;
    }
    case SupportDirection::angle: return Point{-dir * std::cos(e.force_angle), -std::sin(e.force_angle)};
  }
  return along;
}

}  // namespace

void find_support_crossings(const std::vector<Reinforcement>& elements, SliceTable& t) {
  t.supports.clear();
  if (elements.empty() || t.count < 1) return;
  const double x_lo = t.x_left[0];
  const double x_hi = t.x_right[t.count - 1];
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const Reinforcement& e = elements[k];
    const Point d{e.tail.x - e.head.x, e.tail.y - e.head.y};
    const double s = t.circular ? circle_crossing(t.circle, e.head, d, x_lo, x_hi)
                                : polyline_crossing(t.surface, e.head, d, x_lo, x_hi);
    if (s < 0.0) continue;
    SupportForce f;
    f.element = k;
    f.at = Point{e.head.x + s * d.x, e.head.y + s * d.y};
    f.distance = s * e.length();
    f.capacity = capacity_at(e, f.distance) / e.spacing;
    if (!(f.capacity > 0.0)) continue;
    const auto slice = std::lower_bound(t.x_right.begin(), t.x_right.begin() + t.count, f.at.x);
    f.slice = static_cast<std::size_t>(std::min<std::ptrdiff_t>(slice - t.x_right.begin(), t.count - 1));
    const Point u = force_direction(e, t, static_cast<int>(f.slice));
    f.force_x = f.capacity * u.x;
    f.force_y = f.capacity * u.y;
    f.passive = e.application == SupportApplication::passive;
    t.supports.push_back(f);
  }
}

void find_line_loads(const PreparedSection& ps, SliceTable& t) {
  t.line_loads.clear();
  if (ps.line_loads.empty() || t.count < 1) return;
  const double x_lo = t.x_left[0];
  const double x_hi = t.x_right[t.count - 1];
  for (std::size_t k = 0; k < ps.line_loads.size(); ++k) {
    const LineLoad& q = ps.line_loads[k];
    if (q.x < x_lo || q.x > x_hi) continue;
    const auto slice = std::lower_bound(t.x_right.begin(), t.x_right.begin() + t.count, q.x);
    AppliedLineLoad a;
    a.load = k;
    a.slice = static_cast<std::size_t>(std::min<std::ptrdiff_t>(slice - t.x_right.begin(), t.count - 1));
    a.at = Point{q.x, ps.ground_at(q.x)};
    a.force_x = q.force_x;
    a.force_y = q.force_y;
    t.line_loads.push_back(a);
  }
}

// A force (global fx, fy) at `at` on slice i: its vertical part lessens V, its horizontal part adds to H (in the
// sliding direction), its moment about the centre to the driving moment.
void SliceTable::add_point_force(int i, Point at, double fx_global, double fy) {
  const double dir = direction >= 0 ? 1.0 : -1.0;
  const double fx = dir * fx_global;  // mirrored frame
  vertical[i] -= fy;
  horizontal[i] += fx;
  const double rx = dir * (at.x - circle.xc);
  const double ry = at.y - circle.yc;
  const double m = rx * fy - ry * fx;
  drive_moment[i] += m;
  total_drive_moment += m;
  drive_moment_scale += std::fabs(rx * fy) + std::fabs(ry * fx);
}

// The line loads and the support forces on their slices, a passive support force times passive_scale.
void SliceTable::add_support_forces() {
  has_passive_supports = false;
  for (const AppliedLineLoad& q : line_loads) add_point_force(static_cast<int>(q.slice), q.at, q.force_x, q.force_y);
  for (const SupportForce& f : supports) {
    has_passive_supports = has_passive_supports || f.passive;
    const double scale = f.passive ? passive_scale : 1.0;
    add_point_force(static_cast<int>(f.slice), f.at, scale * f.force_x, scale * f.force_y);
  }
}

}  // namespace detail

}  // namespace slope
