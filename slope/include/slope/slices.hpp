#pragma once
// Slicing the sliding mass above a circular slip surface.
#include <optional>
#include <string>
#include <vector>

#include "slope/section.hpp"

namespace slope {

struct Circle {
  double xc = 0.0;      // m, centre x
  double yc = 0.0;      // m, centre y
  double radius = 0.0;  // m
};

// One slice of the sliding mass. Slices are listed left to right (increasing x) whatever the direction of sliding.
// Angles are measured so that a positive base angle drives the mass in the
// direction of sliding (the mass slides toward +x when SlipMass::direction = +1, toward -x when -1).
struct Slice {
  double x_left = 0.0;           // m
  double x_right = 0.0;          // m
  double width = 0.0;            // m, x_right - x_left
  double base_angle = 0.0;       // rad, inclination of the base chord, positive when it drives sliding
  double base_length = 0.0;      // m
  double base_x = 0.0;           // m, base midpoint
  double base_y = 0.0;           // m, base midpoint
  double top_y = 0.0;            // m, ground surface at the slice centre line
  double weight = 0.0;           // N/m, soil weight of the slice
  double surcharge_load = 0.0;   // N/m, vertical surcharge resultant on the slice top
  double ponded_water_load = 0.0;// N/m, weight of free water standing on the slice top (if any)
  double cohesion = 0.0;         // Pa, of the material at the base
  double tan_friction = 0.0;     // tan(phi') of the material at the base
  double pore_pressure = 0.0;    // Pa, at the base midpoint
  std::size_t base_material = 0; // index into Section::materials
  // Added for the methods (zero when there is no water / no seismic load):
  double seismic_force = 0.0;    // N/m, kh * weight, horizontal, in the direction of sliding, acting at mid-height
                                 // of the slice ((base_y + top_y) / 2: centroid approximated at mid-height)
  double water_thrust = 0.0;     // N/m, horizontal component of the free-water pressure on the sloping slice top,
                                 // positive in the direction of sliding, acting at (base_x, top_y)
};

struct SlipMass {
  Circle circle;
  Point entry;        // m, upper intersection with the ground surface (behind the crest)
  Point exit;         // m, lower intersection with the ground surface (near the toe)
  int direction = 1;  // +1: the mass slides toward +x; -1: toward -x
  std::vector<Slice> slices;
};

struct SliceOptions {
  int slices = 50;  // target number of slices (boundaries are also put at every profile vertex and material change)
};

// Builds the slices of the mass between the ground surface and the circle. Returns nullopt and sets *reason
// when the circle is not an admissible slip surface (does not cut the ground twice, passes below bottom_y, ...).
std::optional<SlipMass> slice_circle(const Section& section, const Circle& circle, const SliceOptions& options,
                                     std::string* reason = nullptr);

}  // namespace slope
