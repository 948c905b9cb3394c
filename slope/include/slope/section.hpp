#pragma once
// Slope cross-section for limit-equilibrium analysis (plane strain, per metre of slope width).
// All quantities are SI: m, N/m^3, Pa, rad. Scene files use kPa and kN/m^3; coupling converts once.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "slope/point.hpp"
#include "slope/reinforcement.hpp"
#include "slope/strength.hpp"

namespace slope {

struct Material {
  std::string name;
  double unit_weight = 0.0;     // N/m^3 (total unit weight; above the piezometric line when saturated_unit_weight is given)
  double cohesion = 0.0;        // Pa (effective cohesion c')
  double friction_angle = 0.0;  // rad (effective friction angle phi')
  // r_u (-): when > 0, the pore pressure on a slice base in this material is r_u times the vertical overburden of
  // soil above the base's midpoint (the slice's soil weight / its width), in place of the piezometric line's;
  // 0: the piezometric line (if any) gives it. 0 <= r_u < 1.
  double pore_pressure_ratio = 0.0;
  // Cohesion increasing with depth (an undrained strength Su that grows with depth when friction_angle = 0): on a
  // slice base, c = cohesion + cohesion_rate * z at the base's midpoint, at most cohesion_max, with z the depth
  // below the horizontal datum y = cohesion_datum_y when it is given (z = 0 above it), else below this material's
  // own top at the midpoint's x (its profile line, or a line above where that one is lower). cohesion is then the
  // strength at the datum or at the top. cohesion_rate = 0: c = cohesion everywhere.
  double cohesion_rate = 0.0;                                     // Pa/m, >= 0
  std::optional<double> cohesion_datum_y{};                       // m
  double cohesion_max = std::numeric_limits<double>::infinity();  // Pa, >= cohesion
  // N/m^3, > 0: the total unit weight of this material below the piezometric line (Section::water); empty: unit_weight
  // everywhere. Each slice splits each layer at the piezometric line's mean height over the slice.
  std::optional<double> saturated_unit_weight{};
  // A non-linear strength envelope (strength.hpp): when given, it is the strength of slice bases in this material
  // (cohesion, friction_angle and the cohesion's increase with depth are not used: cohesion_rate must be 0).
  std::optional<StrengthEnvelope> envelope{};
};

// A profile line is the top of its material; the material extends down to the next line below it
// (or to Section::bottom_y). Lines run left to right with x strictly increasing and all span the same x range.
struct ProfileLine {
  std::size_t material = 0;   // index into Section::materials
  std::vector<Point> points;  // m
};

// Pore pressure at a point below the piezometric line: u = unit_weight * (height of the line above the point), on the
// bases of materials without a pore-pressure ratio (Material::pore_pressure_ratio); the water above the ground
// (ponded) acts on every slice top.
struct Water {
  std::vector<Point> piezometric_line;  // m, x strictly increasing, spans the section
  double unit_weight = 9810.0;          // N/m^3
};

// Vertical strip load on the ground surface between from_x and to_x: uniform, or trapezoidal (linear from
// `pressure` at from_x to `pressure_end` at to_x).
struct Surcharge {
  double from_x = 0.0;    // m
  double to_x = 0.0;      // m
  double pressure = 0.0;  // Pa
  std::optional<double> pressure_end{};  // Pa; empty: `pressure` over the whole strip

  double end_pressure() const { return pressure_end.value_or(pressure); }
  // The load on [x0, x1] (N/m of slope width): the pressure integrated over its overlap with the strip.
  double load_on(double x0, double x1) const;
};

// A line load (a force per metre of slope width) on the ground surface at x, in any direction.
struct LineLoad {
  double x = 0.0;        // m
  double force_x = 0.0;  // N/m, + toward +x
  double force_y = 0.0;  // N/m, + upward (a load pressing on the ground has force_y < 0)
};

struct Section {
  double bottom_y = 0.0;                   // m, rigid base: no slip surface may pass below it
  std::vector<ProfileLine> profile_lines;  // [0] is the ground surface
  std::vector<Material> materials;
  std::optional<Water> water;
  std::vector<Surcharge> surcharges;
  std::vector<LineLoad> line_loads;
  double seismic_coefficient = 0.0;  // horizontal pseudo-static coefficient kh (force kh*W out of the slope)
  // vertical pseudo-static coefficient kv: the force kv*W acts upward when kv > 0 (it lightens the soil), downward
  // when kv < 0; with kh (both at once)
  double vertical_seismic_coefficient = 0.0;
  std::vector<Reinforcement> reinforcement;  // nails, anchors, geosynthetics, piles (reinforcement.hpp)

  double x_min() const;  // m, left end of the section
  double x_max() const;  // m, right end of the section
  // Height of the ground surface (profile line 0) at x, m. x is clamped to the section.
  double ground_y(double x) const;
};

// The way the section's slope faces: +1 when the ground's left end is higher than its right end (a mass slides
// toward +x), -1 the other way, 0 when both ends are level.
int facing_direction(const Section& section);

// Height of a polyline (x strictly increasing) at x, linear between vertices, constant beyond the ends.
double polyline_y(const std::vector<Point>& line, double x);

// Empty when the section can be analysed; otherwise a sentence saying what is wrong with it (profile lines not
// strictly increasing in x or not spanning the same range, a line above the ground or below bottom_y, a missing
// material, a non-positive unit weight, ...).
std::string section_error(const Section& section);

}  // namespace slope
