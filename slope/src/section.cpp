// Section geometry queries and input checks.
#include "slope/section.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slope {

double Surcharge::load_on(double x0, double x1) const {
  const double a = std::max(from_x, x0), b = std::min(to_x, x1);
  if (!(b > a)) return 0.0;
  const double mid = 0.5 * (a + b);
  const double p = pressure + (end_pressure() - pressure) * (mid - from_x) / (to_x - from_x);
  return p * (b - a);  // exact for a linear pressure
}


double polyline_y(const std::vector<Point>& line, double x) {
  if (line.empty()) return 0.0;
  if (x <= line.front().x) return line.front().y;
  if (x >= line.back().x) return line.back().y;
  const auto upper = std::upper_bound(line.begin(), line.end(), x,
                                      [](double value, const Point& p) { return value < p.x; });
  const Point& b = *upper;
  const Point& a = *(upper - 1);
  const double t = (x - a.x) / (b.x - a.x);
  return a.y + t * (b.y - a.y);
}

double Section::x_min() const {
  return profile_lines.empty() || profile_lines.front().points.empty() ? 0.0 : profile_lines.front().points.front().x;
}

double Section::x_max() const {
  return profile_lines.empty() || profile_lines.front().points.empty() ? 0.0 : profile_lines.front().points.back().x;
}

int facing_direction(const Section& section) {
  const double left = section.ground_y(section.x_min()), right = section.ground_y(section.x_max());
  if (left > right) return 1;
  if (right > left) return -1;
  return 0;
}

double Section::ground_y(double x) const {
  if (profile_lines.empty()) return 0.0;
  return polyline_y(profile_lines.front().points, std::clamp(x, x_min(), x_max()));
}

namespace {

// What is wrong with material m of a section (empty: nothing).
std::string material_error(const Material& material, std::size_t m) {
  std::ostringstream out;
  if (!(material.unit_weight > 0.0) || !(material.cohesion >= 0.0) || !(material.friction_angle >= 0.0) ||
      !(material.friction_angle < 1.5707963267948966)) {
    out << "material " << m << " ('" << material.name
        << "') needs a positive unit weight, cohesion >= 0 and 0 <= friction angle < 90 degrees";
    return out.str();
  }
  if (material.saturated_unit_weight &&
      (!(*material.saturated_unit_weight > 0.0) || !std::isfinite(*material.saturated_unit_weight))) {
    out << "material " << m << " ('" << material.name << "') needs a positive finite saturated unit weight";
    return out.str();
  }
  if (!(material.pore_pressure_ratio >= 0.0) || !(material.pore_pressure_ratio < 1.0)) {
    out << "material " << m << " ('" << material.name << "') needs a pore-pressure ratio r_u with 0 <= r_u < 1";
    return out.str();
  }
  if (!(material.cohesion_rate >= 0.0) || !std::isfinite(material.cohesion_rate) ||
      !(material.cohesion_max >= material.cohesion) ||
      (material.cohesion_datum_y && !std::isfinite(*material.cohesion_datum_y))) {
    out << "material " << m << " ('" << material.name
        << "') needs a finite cohesion rate >= 0, a maximum cohesion >= its cohesion and a finite datum";
    return out.str();
  }
  if (material.envelope) {
    if (const std::string e = envelope_error(*material.envelope); !e.empty()) {
      out << "material " << m << " ('" << material.name << "'): " << e;
      return out.str();
    }
    if (material.cohesion_rate != 0.0) {
      out << "material " << m << " ('" << material.name
          << "') has a strength envelope and a cohesion increasing with depth: give one or the other";
      return out.str();
    }
  }
  return {};
}

}  // namespace

std::string section_error(const Section& section) {
  std::ostringstream out;
  if (section.profile_lines.empty()) return "the section has no profile lines";
  if (section.materials.empty()) return "the section has no materials";
  const double x0 = section.x_min();
  const double x1 = section.x_max();
  const double span_tolerance = 1e-9 * (1.0 + std::fabs(x1 - x0));
  for (std::size_t k = 0; k < section.profile_lines.size(); ++k) {
    const ProfileLine& line = section.profile_lines[k];
    if (line.points.size() < 2) {
      out << "profile line " << k << " needs at least two points";
      return out.str();
    }
    if (line.material >= section.materials.size()) {
      out << "profile line " << k << " refers to material " << line.material << " which does not exist";
      return out.str();
    }
    for (std::size_t i = 1; i < line.points.size(); ++i) {
      if (!(line.points[i].x > line.points[i - 1].x)) {
        out << "profile line " << k << ": x must increase strictly (point " << i << ")";
        return out.str();
      }
    }
    if (std::fabs(line.points.front().x - x0) > span_tolerance || std::fabs(line.points.back().x - x1) > span_tolerance) {
      out << "profile line " << k << " must span the same x range as the ground surface";
      return out.str();
    }
    for (const Point& p : line.points) {
      if (p.y < section.bottom_y - span_tolerance) {
        out << "profile line " << k << " passes below the rigid base bottom_y";
        return out.str();
      }
      if (k > 0 && p.y > section.ground_y(p.x) + span_tolerance) {
        out << "profile line " << k << " rises above the ground surface at x = " << p.x;
        return out.str();
      }
    }
  }
  for (std::size_t m = 0; m < section.materials.size(); ++m)
    if (std::string e = material_error(section.materials[m], m); !e.empty()) return e;
  if (section.water) {
    const auto& line = section.water->piezometric_line;
    if (line.size() < 2) return "the piezometric line needs at least two points";
    for (std::size_t i = 1; i < line.size(); ++i) {
      if (!(line[i].x > line[i - 1].x)) return "the piezometric line: x must increase strictly";
    }
    if (!(section.water->unit_weight > 0.0)) return "the unit weight of water must be positive";
  }
  for (const Surcharge& s : section.surcharges) {
    if (!(s.to_x > s.from_x)) return "a surcharge needs from_x < to_x";
    if (!std::isfinite(s.pressure) || !std::isfinite(s.end_pressure()))
      return "a surcharge's pressures must be finite";
  }
  if (!std::isfinite(section.seismic_coefficient)) return "the seismic coefficient must be finite";
  if (!(std::fabs(section.vertical_seismic_coefficient) < 1.0))
    return "the vertical seismic coefficient must lie in (-1, 1)";
  for (const LineLoad& q : section.line_loads)
    if (!std::isfinite(q.x) || !std::isfinite(q.force_x) || !std::isfinite(q.force_y))
      return "a line load's position and force must be finite";
  for (std::size_t k = 0; k < section.reinforcement.size(); ++k)
    if (std::string why = reinforcement_error(section.reinforcement[k]); !why.empty())
      return "reinforcement element " + std::to_string(k) + ": " + why;
  return {};
}

}  // namespace slope
