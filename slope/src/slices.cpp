// Slicing the mass above a circular slip surface.
//
// Geometry: the slip surface is the lower half of the circle. The mass is the single region where the ground
// surface lies above the arc. Slice boundaries are put where the base must break whatever the slice count asks:
// where a profile line (a material change) or the piezometric line crosses the arc inside the mass, at surcharge
// ends and where the piezometric line crosses the ground (the edge of ponded water); the intervals between these
// are divided into near-equal slices so that the total is close to the target. The polylines' vertices set no
// boundaries: the weight of every layer, the ponded water and the mean ground height of a slice are integrals of
// the polylines over the slice, exact for any number of vertices and found in O(log n) from cumulative areas. The
// cost of a circle is therefore set by its slices, not by how finely the ground was surveyed. The base is the
// chord of the arc between the slice boundaries (its normal at the chord midpoint passes through the circle
// centre); pore pressure is taken at the chord midpoint.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "slice_table.hpp"
#include "slope/slices.hpp"

namespace slope::detail {

const char* rejection_text(Rejection rejection) {
  switch (rejection) {
    case Rejection::none: return "admissible";
    case Rejection::invalid_circle: return "the circle radius is not a positive finite number";
    case Rejection::misses_ground: return "the circle does not cut into the ground surface";
    case Rejection::not_closed_lower_arc:
      return "the ground surface stays above the circle's lower half (no closed mass on the lower arc)";
    case Rejection::beyond_section: return "the slip mass would extend beyond the end of the section";
    case Rejection::several_masses:
      return "the circle leaves the ground and re-enters it (by more than 1 % of the relief in between)";
    case Rejection::below_base: return "the circle passes below the rigid base (bottom_y)";
    case Rejection::too_small: return "the slip mass is vanishingly small";
    case Rejection::radius_too_large:
      return "the radius exceeds 10^4 times the section's extent (the circle is a plane to within the accuracy of "
             "the geometry; planes are approached by smaller circles)";
  }
  return "unknown";
}

PreparedSection::PreparedSection(const Section& section) {
  x_min = section.x_min();
  x_max = section.x_max();
  bottom_y = section.bottom_y;
  ground = section.profile_lines.front().points;
  ground_y_min = std::numeric_limits<double>::infinity();
  ground_y_max = -std::numeric_limits<double>::infinity();
  for (const Point& p : ground) {
    ground_y_min = std::min(ground_y_min, p.y);
    ground_y_max = std::max(ground_y_max, p.y);
  }

  // Order the profile lines from the top down. They do not cross, so comparing their mean heights is enough;
  // the ground surface stays first.
  const std::size_t n_lines = section.profile_lines.size();
  std::vector<double> level(n_lines, 0.0);
  for (std::size_t k = 0; k < n_lines; ++k) {
    lines.emplace_back(section.profile_lines[k].points);
    level[k] = lines.back().integral(x_min, x_max);
  }
  std::vector<std::size_t> order(n_lines);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin() + 1, order.end(), [&](std::size_t a, std::size_t b) { return level[a] > level[b]; });
  std::vector<IndexedPolyline> ordered;
  for (std::size_t k : order) {
    const ProfileLine& line = section.profile_lines[k];
    const Material& m = section.materials.at(line.material);
    ordered.push_back(std::move(lines[k]));
    line_unit_weight.push_back(m.unit_weight);
    line_saturated_weight.push_back(section.water ? m.saturated_unit_weight.value_or(m.unit_weight) : m.unit_weight);
    has_saturated_weights = has_saturated_weights || line_saturated_weight.back() != m.unit_weight;
    line_cohesion.push_back(m.cohesion);
    line_tan_phi.push_back(std::tan(m.friction_angle));
    line_cohesion_rate.push_back(m.cohesion_rate);
    line_cohesion_datum.push_back(m.cohesion_datum_y.value_or(std::numeric_limits<double>::quiet_NaN()));
    line_cohesion_max.push_back(m.cohesion_max);
    line_material.push_back(line.material);
  }
  lines = std::move(ordered);
  for (const Material& m : section.materials) {
    material_ru.push_back(m.pore_pressure_ratio);
    material_envelope.push_back(m.envelope ? static_cast<int>(envelopes.size()) : -1);
    if (m.envelope) envelopes.push_back(tabulated(*m.envelope));
  }

  if (section.water) {
    has_water = true;
    piezometric_line = IndexedPolyline(section.water->piezometric_line);
    water_unit_weight = section.water->unit_weight;
    // where the piezometric line crosses the ground surface (edge of ponded water)
    std::vector<double> knots;
    for (const Point& p : ground) knots.push_back(p.x);
    for (const Point& p : section.water->piezometric_line) knots.push_back(std::clamp(p.x, x_min, x_max));
    std::sort(knots.begin(), knots.end());
    const IndexedPolyline& g = lines.front();
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
      const double a = knots[i];
      const double b = knots[i + 1];
      if (!(b > a)) continue;
      const double da = piezometric_line.y(a) - g.y(a);
      const double db = piezometric_line.y(b) - g.y(b);
      if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) fixed_breaks.push_back(a + (b - a) * da / (da - db));
    }
  }
  const double contact_tolerance = 1e-9 * (1.0 + std::fabs(bottom_y) + (ground_y_max - ground_y_min));
  for (const Point& p : ground)
    if (p.y <= bottom_y + contact_tolerance && p.x > x_min && p.x < x_max) base_contacts.push_back(p.x);
  surcharges = section.surcharges;
  for (const Surcharge& s : surcharges) {
    fixed_breaks.push_back(s.from_x);
    fixed_breaks.push_back(s.to_x);
  }
  seismic_coefficient = section.seismic_coefficient;
  vertical_seismic_coefficient = section.vertical_seismic_coefficient;
  reinforcement = section.reinforcement;
  line_loads = section.line_loads;
  std::sort(fixed_breaks.begin(), fixed_breaks.end());
  fixed_breaks.erase(std::unique(fixed_breaks.begin(), fixed_breaks.end()), fixed_breaks.end());
}

double PreparedSection::cohesion_at(std::size_t k, double x, double y) const {
  const double rate = line_cohesion_rate[k];
  if (!(rate > 0.0)) return line_cohesion[k];
  double top = line_cohesion_datum[k];
  if (std::isnan(top)) {
    // the material's own top: its line, or a line above where that one is lower (lines touch, never cross)
    const double xc = std::clamp(x, x_min, x_max);
    top = lines[0].y(xc);
    for (std::size_t j = 1; j <= k; ++j) top = std::min(top, lines[j].y(xc));
  }
  return std::min(line_cohesion[k] + rate * std::max(0.0, top - y), line_cohesion_max[k]);
}

double PreparedSection::ground_at(double x) const { return lines.front().y(std::clamp(x, x_min, x_max)); }

// Whether the lower arc, above the ground between two crossings x0 < x1, stays within 1 % of the ground's relief
// of it: the arc then merely grazes the roughness of a surveyed surface, and the masses on either side are one.
// The arc is convex and the ground straight between vertices, so the largest gap is at a ground vertex.
bool Slicer::shallow_gap(const Circle& circle, double x0, double x1) const {
  const PreparedSection& ps = prepared_;
  const double limit = 0.01 * (ps.ground_y_max - ps.ground_y_min);
  const double r2 = circle.radius * circle.radius;
  const auto& points = ps.ground_line().points();
  auto it = std::upper_bound(points.begin(), points.end(), x0, [](double v, const Point& p) { return v < p.x; });
  for (; it != points.end() && it->x < x1; ++it) {
    const double d = it->x - circle.xc;
    if (circle.yc - std::sqrt(std::max(0.0, r2 - d * d)) - it->y > limit) return false;
  }
  return true;
}

namespace {

// The height of the circle's lower half at x [m].
double lower_arc_y(const Circle& c, double x) {
  const double d = x - c.xc;
  return c.yc - std::sqrt(std::max(0.0, c.radius * c.radius - d * d));
}

}  // namespace

// The points that split [x_lo, x_hi] where soil may begin or end above the arc: the arc's crossings of the ground
// and the ground's contacts with the rigid base (roots_, sorted, with root_is_contact_ alongside).
void Slicer::split_points(const Circle& circle, double x_lo, double x_hi) {
  const PreparedSection& ps = prepared_;
  roots_.clear();
  ps.ground_line().lower_arc_crossings(circle, x_lo, x_hi, roots_);
  const std::size_t n_crossings = roots_.size();
  for (double x : ps.base_contacts)
    if (x > x_lo && x < x_hi) roots_.push_back(x);
  if (roots_.size() > n_crossings) {
    // keep track of which split points are base contacts (they need the arc to pass through them)
    root_is_contact_.assign(roots_.size(), 0);
    for (std::size_t k = n_crossings; k < roots_.size(); ++k) root_is_contact_[k] = 1;
    for (std::size_t k = 1; k < roots_.size(); ++k)  // insertion sort of the few split points, flags alongside
      for (std::size_t j = k; j > 0 && roots_[j - 1] > roots_[j]; --j) {
        std::swap(roots_[j - 1], roots_[j]);
        std::swap(root_is_contact_[j - 1], root_is_contact_[j]);
      }
  } else {
    std::sort(roots_.begin(), roots_.end());
    root_is_contact_.assign(roots_.size(), 0);
  }
}

// The single interval between split points where there is soil above the arc (gaps_ gets the stretches where the
// arc only grazes a surveyed surface's roughness). Soil lies between the ground and the rigid base, so where the
// ground is on the base (a slope on a firm stratum at toe level) there is none, and such ground vertices may end a
// mass like a crossing does.
Rejection Slicer::find_mass(const Circle& circle, double x_lo, double x_hi, MassEnds& m) {
  const PreparedSection& ps = prepared_;
  // Intervals shorter than tol_x between split points are empty (coincident roots). The tolerance follows the
  // section's size, not the circle's: with a radius of 1e6 m or more (the search approaching a plane) a
  // radius-relative tolerance exceeded the 1 mm width of a "vertical" face and dropped the face crossing.
  const double tol_x = 1e-10 * (ps.x_max - ps.x_min + 1.0) + 1e-14 * (circle.radius + std::fabs(circle.xc));
  const double tol_base = 1e-9 * (1.0 + circle.radius + std::fabs(ps.bottom_y));
  gaps_.clear();
  bool open = false, found = false;
  int masses = 0;
  double a = x_lo;
  bool a_is_root = false, a_is_contact = false;
  const std::size_t n_roots = roots_.size();
  for (std::size_t k = 0; k <= n_roots; ++k) {
    const double b = k < n_roots ? roots_[k] : x_hi;
    const bool b_is_root = k < n_roots;
    const bool b_is_contact = k < n_roots && root_is_contact_[k] != 0;
    if (b - a > tol_x) {
      const double mid = 0.5 * (a + b);
      const double g = ps.ground_at(mid);
      const bool positive = g > lower_arc_y(circle, mid) && g > ps.bottom_y + tol_base;
      if (positive && !open && found && !m.right_is_contact && !a_is_contact && shallow_gap(circle, m.right, a)) {
        // the arc rose above the ground only by a survey's roughness: one mass, the gap's slices empty
        open = true;
        found = false;
        gaps_.push_back(m.right);
        gaps_.push_back(a);
      } else if (positive && !open) {  // a new positive stretch (adjacent positive stretches merge: tangent touch)
        open = true;
        m.left = a;
        m.left_is_root = a_is_root;
        m.left_is_contact = a_is_contact;
        ++masses;
      } else if (!positive && open) {
        open = false;
        m.right = a;
        m.right_is_contact = a_is_contact;
        found = true;
        if (!a_is_root) return Rejection::beyond_section;
      }
    }
    a = b;
    a_is_root = b_is_root;
    a_is_contact = b_is_contact;
  }
  if (open) {  // positive up to x_hi
    if (x_hi < ps.x_max - tol_x) return Rejection::not_closed_lower_arc;
    return Rejection::beyond_section;
  }
  if (masses == 0 || !found) return Rejection::misses_ground;
  if (masses > 1) return Rejection::several_masses;
  if (!m.left_is_root) return (x_lo > ps.x_min + tol_x) ? Rejection::not_closed_lower_arc : Rejection::beyond_section;
  if (m.right - m.left < 1e-7 * (ps.x_max - ps.x_min)) return Rejection::too_small;
  const double xc = circle.xc, yc = circle.yc, R = circle.radius;
  if (xc > m.left && xc < m.right && yc - R < ps.bottom_y - tol_base) return Rejection::below_base;
  // a mass ending on the base must have its arc through that point, not below it
  if ((m.left_is_contact && lower_arc_y(circle, m.left) < ps.bottom_y - tol_base) ||
      (m.right_is_contact && lower_arc_y(circle, m.right) < ps.bottom_y - tol_base))
    return Rejection::below_base;
  return Rejection::none;
}

// The sliding direction of the mass between xl and xr: from its higher end to its lower end (+1: toward +x).
int Slicer::sliding_direction(double xl, double xr, double xc) const {
  const double yl = prepared_.ground_at(xl);
  const double yr = prepared_.ground_at(xr);
  const double tol_y = 1e-9 * (1.0 + std::fabs(yl) + std::fabs(yr));
  if (yl > yr + tol_y) return 1;
  if (yr > yl + tol_y) return -1;
  return 0.5 * (xl + xr) < xc ? 1 : -1;
}

// The boundaries the base must break at inside the mass (breaks_, sorted): surcharge ends and the edge of ponded
// water, the grazing gaps, and where a layer line or the piezometric line crosses the arc.
void Slicer::collect_breaks(const Circle& circle, double xl, double xr) {
  const PreparedSection& ps = prepared_;
  breaks_.clear();
  for (auto it = std::upper_bound(ps.fixed_breaks.begin(), ps.fixed_breaks.end(), xl);
       it != ps.fixed_breaks.end() && *it < xr; ++it)
    breaks_.push_back(*it);
  breaks_.insert(breaks_.end(), gaps_.begin(), gaps_.end());
  for (std::size_t k = 1; k < ps.lines.size(); ++k) ps.lines[k].lower_arc_crossings(circle, xl, xr, breaks_);
  if (ps.has_water) ps.piezometric_line.lower_arc_crossings(circle, xl, xr, breaks_);
  std::sort(breaks_.begin(), breaks_.end());
}

Rejection Slicer::slice(const Circle& circle, int target_slices, SliceTable& table) {
  const PreparedSection& ps = prepared_;
  const double xc = circle.xc;
  const double yc = circle.yc;
  const double R = circle.radius;
  if (!(R > 0.0) || !std::isfinite(R) || !std::isfinite(xc) || !std::isfinite(yc)) return Rejection::invalid_circle;
  // Beyond this radius the arc and its crossings are computed from differences of numbers 1e8 times larger than
  // the section, and Janbu's f0 and the slice geometry lose their accuracy (seen with vertical faces, where the
  // force-equilibrium methods favour planes and the refinement drifts to radii of 1e8 m).
  if (R > 1e4 * (ps.x_max - ps.x_min + ps.ground_y_max - ps.bottom_y)) return Rejection::radius_too_large;

  // 1. The lower arc against the ground surface: the single interval where there is soil above the arc.
  const double x_lo = std::max(ps.x_min, xc - R);
  const double x_hi = std::min(ps.x_max, xc + R);
  if (!(x_hi > x_lo)) return Rejection::misses_ground;
  split_points(circle, x_lo, x_hi);
  MassEnds mass;
  if (const Rejection why = find_mass(circle, x_lo, x_hi, mass); why != Rejection::none) return why;

  // 2. Direction of sliding: from the higher end to the lower end.
  const int dir = sliding_direction(mass.left, mass.right, xc);

  // 3. Slice boundaries.
  collect_breaks(circle, mass.left, mass.right);
  if (place_bounds(mass.left, mass.right, target_slices) < 1) return Rejection::too_small;

  fill_slices(circle, dir, table);
  return Rejection::none;
}

// Slice boundaries: the ends, the breaks_ (sorted, inside the mass) and near-equal slices between them.
// Returns the number of slices.
int Slicer::place_bounds(double xl, double xr, int target_slices) {
  const double span = xr - xl;
  breaks_.push_back(xr);
  const double target_width = span / std::max(1, target_slices);
  const double min_gap = 1e-6 * span;
  bounds_.clear();
  bounds_.push_back(xl);
  double prev = xl;
  for (double b : breaks_) {
    const double gap = b - prev;
    if (gap < min_gap) {
      if (b == xr) bounds_.back() = xr;  // keep the exact end
      continue;
    }
    const long k = std::max(1L, std::lround(gap / target_width));
    for (long j = 1; j < k; ++j) bounds_.push_back(prev + gap * static_cast<double>(j) / static_cast<double>(k));
    bounds_.push_back(b);
    prev = b;
  }
  return static_cast<int>(bounds_.size()) - 1;
}

// Steps 4 and 5 of slice(): the slices between bounds_, their geometry, weights and loads.
void Slicer::fill_slices(const Circle& circle, int dir, SliceTable& table) {
  const PreparedSection& ps = prepared_;
  const IndexedPolyline& ground = ps.ground_line();
  const double R2 = circle.radius * circle.radius;
  auto arc = [&](double x) {
    const double d = x - circle.xc;
    return circle.yc - std::sqrt(std::max(0.0, R2 - d * d));
  };
  // 4. Arc and ground at the boundaries.
  arc_y_.resize(bounds_.size());
  ground_y_.resize(bounds_.size());
  for (std::size_t j = 0; j < bounds_.size(); ++j) {
    arc_y_[j] = arc(bounds_[j]);
    ground_y_[j] = ground.y(bounds_[j]);
  }
  arc_y_.front() = ground_y_.front();  // the ends lie on the ground
  arc_y_.back() = ground_y_.back();
  table.circular = true;
  table.circle = circle;
  table.surface.clear();
  table.crack_depth = table.crack_force = table.crack_force_y = table.chord_depth = 0.0;
  fill_from_bounds(dir, table, &circle);
  find_support_crossings(ps.reinforcement, table);
  find_line_loads(ps, table);
  table.passive_scale = 1.0;
  table.compute_loads();
}

// 5. The slices between bounds_ with the base heights arc_y_ and the ground heights ground_y_ at the bounds: their
// geometry, weights and loads (compute_loads() is left to the caller).
void Slicer::fill_from_bounds(int dir, SliceTable& table, const Circle* circle) {
  const PreparedSection& ps = prepared_;
  const IndexedPolyline& ground = ps.ground_line();
  const int n = static_cast<int>(bounds_.size()) - 1;
  table.resize(n);
  table.direction = dir;
  const Point p_left{bounds_.front(), ground_y_.front()};
  const Point p_right{bounds_.back(), ground_y_.back()};
  table.entry = dir > 0 ? p_left : p_right;
  table.exit = dir > 0 ? p_right : p_left;
  const double sdir = dir > 0 ? 1.0 : -1.0;
  const std::size_t n_lines = ps.lines.size();
  line_y_.resize(n_lines + 1);
  const double kh = ps.seismic_coefficient;
  const double kv = ps.vertical_seismic_coefficient;
  double max_depth = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x0 = bounds_[i];
    const double x1 = bounds_[i + 1];
    const double b = x1 - x0;
    const double yb0 = arc_y_[i];
    const double yb1 = arc_y_[i + 1];
    const double dy = yb1 - yb0;
    const double l = std::sqrt(b * b + dy * dy);
    const double inv_l = 1.0 / l;
    const double xm = 0.5 * (x0 + x1);
    const double ybm = 0.5 * (yb0 + yb1);  // the chord's mean height
    const double ytm = ground.mean(x0, x1);  // the ground's mean height
    const double h = std::max(0.0, ytm - ybm);
    max_depth = std::max(max_depth, h);
    table.x_left[i] = x0;
    table.x_right[i] = x1;
    table.width[i] = b;
    table.sin_a[i] = -sdir * dy * inv_l;
    table.cos_a[i] = b * inv_l;
    table.base_length[i] = l;
    table.base_x[i] = xm;
    table.base_y[i] = ybm;
    table.top_y[i] = ytm;

    const double weight = slice_layers(i, circle, table);
    slice_water(i, sdir, table);
    table.seismic[i] = kh * weight;
    table.seismic_up[i] = kv * weight;

    table.surcharge[i] = surcharge_load(x0, x1);
  }
  table.max_depth = max_depth;
}

// The strip loads on [x0, x1] [N/m].
double Slicer::surcharge_load(double x0, double x1) const {
  double q = 0.0;
  for (const Surcharge& s : prepared_.surcharges) q += s.load_on(x0, x1);
  return q;
}

// Slice i's ends x0, x1, width, base midpoint and mean top height, as fill_from_bounds put them in the table.
Slicer::SliceSpan Slicer::span_of(int i, const SliceTable& table) const {
  const double x0 = bounds_[i];
  const double x1 = bounds_[i + 1];
  return {x0, x1, x1 - x0, table.base_x[i], table.base_y[i], table.top_y[i]};
}

// The weight of slice i (between bounds_[i] and bounds_[i + 1]; base and top heights already in the table) and the
// soil its base lies in, written to the table; returns the weight [N/m].
double Slicer::slice_layers(int i, const Circle* circle, SliceTable& table) {
  const PreparedSection& ps = prepared_;
  const std::size_t n_lines = ps.lines.size();
  const auto [x0, x1, b, xm, ybm, ytm] = span_of(i, table);
  // Layers from their mean heights over the slice: line k's material fills [Y(k+1), Y(k)], the last one down to
  // bottom_y; the layer the chord lies in is cut at the chord. The chord crosses no line inside a slice (the
  // crossings are boundaries), so these areas are exact. The base lies in the layer the chord lies in; a chord
  // lying on a line (both its ends are crossings of that line) takes the side the arc's middle lies on, which the
  // arc cannot leave within the slice.
  line_y_[0] = ytm;
  for (std::size_t k = 1; k < n_lines; ++k) line_y_[k] = std::min(ps.lines[k].mean(x0, x1), line_y_[k - 1]);
  line_y_[n_lines] = std::min(ps.bottom_y, line_y_[n_lines - 1]);
  double weight = 0.0;
  std::size_t base_line = n_lines - 1;
  const double on_line = 1e-9 * (1.0 + std::fabs(ybm));
  // soil below the piezometric line weighs its saturated unit weight (where its material has one)
  const double water_y = ps.has_saturated_weights ? ps.piezometric_line.mean(x0, x1) : 0.0;
  for (std::size_t k = 0; k < n_lines; ++k) {
    const double top = line_y_[k];
    const double bottom = std::max(line_y_[k + 1], ybm);
    if (top > bottom) {
      const double unit_weight = ps.line_unit_weight[k];
      const double saturated = ps.line_saturated_weight[k];
      if (saturated == unit_weight) {
        weight += unit_weight * (top - bottom);
      } else {
        const double wet_top = std::clamp(water_y, bottom, top);
        weight += unit_weight * (top - wet_top) + saturated * (wet_top - bottom);
      }
    }
    double y_base = ybm;
    if (circle != nullptr && std::fabs(line_y_[k + 1] - ybm) <= on_line) y_base = lower_arc_y(*circle, xm);
    if (line_y_[k + 1] < y_base) {
      base_line = k;
      break;
    }
  }
  weight *= b;
  table.weight[i] = weight;
  table.material[i] = ps.line_material[base_line];
  // A slice over a gap where the arc grazes above rough ground (shallow_gap) has no weight; its base keeps the
  // strength of the soil beneath, as if the roughness were smoothed: with zero strength there the interslice
  // force methods meet tension on these weightless slices and refuse the surface.
  table.cohesion[i] = ps.cohesion_at(base_line, xm, ybm);
  table.tan_phi[i] = ps.line_tan_phi[base_line];
  table.envelope[i] = ps.material_envelope[table.material[i]];
  table.envelopes = &ps.envelopes;
  return weight;
}

// The water of slice i (between bounds_[i] and bounds_[i + 1]; base and top heights, weight and base material
// already in the table): pore pressure at the base midpoint (r_u times the soil's overburden W / b where the base's
// material has a pore-pressure ratio, else from the piezometric line), ponded water on the top and its thrust.
void Slicer::slice_water(int i, double sdir, SliceTable& table) const {
  const PreparedSection& ps = prepared_;
  const auto [x0, x1, b, xm, ybm, ytm] = span_of(i, table);
  double u = 0.0, ponded = 0.0, thrust = 0.0;
  const double ru = ps.material_ru[table.material[i]];
  if (ru > 0.0) u = ru * table.weight[i] / b;
  if (ps.has_water) {
    if (!(ru > 0.0)) u = ps.water_unit_weight * std::max(0.0, ps.piezometric_line.y(xm) - ybm);
    // The piezometric line does not cross the ground inside a slice (the crossings are boundaries).
    const double depth = ps.piezometric_line.mean(x0, x1) - ytm;
    if (depth > 0.0) {
      ponded = ps.water_unit_weight * depth * b;
      // Water pressure p = gw (hw - G) normal to the ground pushes on the slice top with p G' per unit x toward
      // +x: gw (d0^2 - d1^2) / 2 from the water depths d at the slice ends, exact for a level water surface
      // over any number of ground vertices.
      const double d0 = std::max(0.0, ps.piezometric_line.y(x0) - ground_y_[i]);
      const double d1 = std::max(0.0, ps.piezometric_line.y(x1) - ground_y_[i + 1]);
      thrust = sdir * 0.5 * ps.water_unit_weight * (d0 * d0 - d1 * d1);
    }
  }
  table.pore_pressure[i] = u;
  table.ponded[i] = ponded;
  table.water_thrust[i] = thrust;
}

}  // namespace slope::detail

namespace slope {

std::optional<SlipMass> slice_circle(const Section& section, const Circle& circle, const SliceOptions& options,
                                     std::string* reason) {
  if (const std::string error = section_error(section); !error.empty()) {
    if (reason != nullptr) *reason = "invalid section: " + error;
    return std::nullopt;
  }
  detail::Slicer slicer(section);
  detail::SliceTable table;
  const detail::Rejection rejection = slicer.slice(circle, options.slices, table);
  if (rejection != detail::Rejection::none) {
    if (reason != nullptr) *reason = detail::rejection_text(rejection);
    return std::nullopt;
  }
  SlipMass mass;
  detail::table_to_mass(table, mass);
  if (reason != nullptr) reason->clear();
  return mass;
}

}  // namespace slope
