#pragma once
// Sections for the limit-equilibrium tests, built directly in C++ (SI units: m, N/m^3, Pa, rad).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "slope/section.hpp"

namespace lem_test {

inline double radians(double degrees) { return degrees * M_PI / 180.0; }

inline slope::Material material(const std::string& name, double unit_weight_kN_m3, double cohesion_kPa,
                                double friction_angle_deg) {
  return slope::Material{name, unit_weight_kN_m3 * 1e3, cohesion_kPa * 1e3, radians(friction_angle_deg)};
}

// A simple slope facing right: crest at height toe_y + height from x = 0 to crest_length, face inclined at
// `angle_deg`, toe ground at toe_y for toe_length beyond the toe. Rigid base at y = 0.
inline slope::Section simple_slope(double height, double angle_deg, double crest_length, double toe_length,
                                   double toe_y, const slope::Material& soil) {
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials.push_back(soil);
  const double face = height / std::tan(radians(angle_deg));
  s.profile_lines.push_back(slope::ProfileLine{
      0, {{0.0, toe_y + height}, {crest_length, toe_y + height}, {crest_length + face, toe_y},
          {crest_length + face + toe_length, toe_y}}});
  return s;
}

// Griffiths & Lane (1999), Geotechnique 49(3):387-403, homogeneous 2:1 slope: H = 10 m, c' = 10 kPa,
// phi' = 20 deg, gamma = 20 kN/m^3: crest from x = 0 to 20, toe at (40, 10), level ground to x = 60, a foundation
// of the same soil down to the rigid base at y = 0 (depth factor D = 2). (cases/griffiths_lane_1999.json is the
// section without the foundation, D = 1: griffiths_lane_no_foundation() 10 m lower.)
inline slope::Section griffiths_lane_1999() {
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials.push_back(material("soil", 20.0, 10.0, 20.0));
  s.profile_lines.push_back(slope::ProfileLine{0, {{0, 20}, {20, 20}, {40, 10}, {60, 10}}});
  return s;
}

// The same slope without a foundation layer (D = 1, rigid base at the toe level), as the paper's example 1 is
// described by independent re-implementations (OpenSees and XC examples: "homogeneous slope with no foundation
// layer (D=1)", crest 1.2 H wide); a 20 m level run-out on the base beyond the toe carries no soil.
inline slope::Section griffiths_lane_no_foundation() {
  slope::Section s;
  s.bottom_y = 10.0;
  s.materials.push_back(material("soil", 20.0, 10.0, 20.0));
  s.profile_lines.push_back(slope::ProfileLine{0, {{0, 20}, {12, 20}, {32, 10}, {52, 10}}});
  return s;
}

// Mirror image about x = 0 (the slope then faces the other way).
inline slope::Section mirrored(const slope::Section& in) {
  slope::Section s = in;
  auto flip = [](std::vector<slope::Point>& line) {
    for (slope::Point& p : line) p.x = -p.x;
    std::reverse(line.begin(), line.end());
  };
  for (slope::ProfileLine& line : s.profile_lines) flip(line.points);
  if (s.water) flip(s.water->piezometric_line);
  for (slope::Surcharge& q : s.surcharges) {
    const double from = -q.to_x;
    q.to_x = -q.from_x;
    q.from_x = from;
  }
  return s;
}

}  // namespace lem_test
