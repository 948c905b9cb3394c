#pragma once
// Slicing the sliding mass above a slip surface: a circle (slice_circle) or a polyline (slice_polyline), with an
// optional tension crack at the upper end of a polyline.
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
  int envelope = -1;             // index into SlipMass::envelopes when the base material's strength is a non-linear
                                 // envelope (cohesion and tan_friction are then not used), -1: Mohr-Coulomb
  // Added for the methods (zero when there is no water / no seismic load):
  double seismic_force = 0.0;    // N/m, kh * weight, horizontal, in the direction of sliding, acting at mid-height
                                 // of the slice ((base_y + top_y) / 2: centroid approximated at mid-height)
  double water_thrust = 0.0;     // N/m, horizontal component of the free-water pressure on the sloping slice top,
                                 // positive in the direction of sliding, acting at (base_x, top_y)
  double vertical_seismic_force = 0.0;  // N/m, kv * weight, upward, on the slice centre line
};

// A line load of the section (Section::line_loads) on a sliding mass: on the slice under it.
struct AppliedLineLoad {
  std::size_t load = 0;   // index into Section::line_loads
  std::size_t slice = 0;  // the slice under it
  Point at;               // m, on the ground
  double force_x = 0.0;   // N/m, global
  double force_y = 0.0;   // N/m, upward
};

struct SlipMass {
  // The circle of a circular surface. For a polyline surface (`surface` not empty): centre = the moment point,
  // radius 0.
  Circle circle;
  Point entry;        // m, upper intersection with the ground surface (behind the crest)
  Point exit;         // m, lower intersection with the ground surface (near the toe)
  int direction = 1;  // +1: the mass slides toward +x; -1: toward -x
  std::vector<Slice> slices;
  // The non-linear strength envelopes of the base materials that have one (Slice::envelope indexes them).
  std::vector<StrengthEnvelope> envelopes;
  // Polyline surfaces only (empty for a circle): the surface analysed, left to right; with a tension crack it
  // starts (or ends) at the bottom of the crack.
  std::vector<Point> surface;
  Point moment_point;             // m, point the moment equations take moments about (a circle: its centre)
  double crack_depth = 0.0;       // m, depth of the tension crack at the upper end (0: no crack)
  double crack_water_force = 0.0; // N/m, hydrostatic thrust of a water-filled crack, horizontal, toward sliding
  double crack_water_force_y = 0.0;  // m, height of its line of action (a third of the crack above its bottom)
  // The reinforcement elements the slip surface crosses (Section::reinforcement), each at its first crossing from
  // its head, with the force it puts on the mass there.
  std::vector<SupportForce> supports;
  // The section's line loads that stand on the mass's ground surface.
  std::vector<AppliedLineLoad> line_loads;
};

// A vertical tension crack at the upper end of a slip surface (LE practice, e.g. Duncan & Wright 2005, Soil
// Strength and Slope Stability): the crack replaces the slip surface from the ground down to where the surface lies `depth` below the ground;
// the soil above the cut-off part of the surface carries no shear. A water-filled crack pushes the mass toward its
// exit with the hydrostatic thrust gw z^2 / 2, acting horizontally at z / 3 above the crack bottom.
struct TensionCrack {
  // m; empty: the Rankine depth z_c = 2 c' / (gamma sqrt(Ka)), Ka = tan^2(45 deg - phi' / 2), of the soil at the
  // ground surface at the upper end (zero for a cohesionless soil: then there is no crack)
  std::optional<double> depth;
  bool water_filled = false;
};

// A slip surface given by its vertices.
struct SlipPolyline {
  // m, x strictly increasing; the first and last point on the ground surface (to 1e-6 of the section's size),
  // every other point below the ground and none below bottom_y.
  std::vector<Point> points;
  // Point the moment equations (Ordinary, Bishop; Spencer and Morgenstern-Price also take moments, but their
  // factor of safety does not depend on the point) take moments about. Empty: the centre of the circle through
  // the entry, the exit and the point of the surface farthest below the entry-exit chord (as SLOPE/W's automatic
  // axis; for a surface inscribed in a circle, that circle's centre). For a planar surface (no such circle) the
  // point on the chord's perpendicular bisector one chord length above the chord.
  std::optional<Point> moment_point;
  std::optional<TensionCrack> tension_crack;
  // rad, kinematic admissibility: in the direction of sliding no segment may be steeper than the one before it by
  // more than this (the surface is concave upward: a convex kink would have the rigid slices overlap or open up).
  double convex_tolerance = 0.0;
};
struct SliceOptions {
  int slices = 50;  // target number of slices (boundaries are also put at every profile vertex and material change)
};

// Builds the slices of the mass between the ground surface and the circle. Returns nullopt and sets *reason
// when the circle is not an admissible slip surface (does not cut the ground twice, passes below bottom_y, ...).
std::optional<SlipMass> slice_circle(const Section& section, const Circle& circle, const SliceOptions& options,
                                     std::string* reason = nullptr);

// Builds the slices of the mass between the ground surface and a polyline: slice boundaries at every vertex of the
// polyline and where a profile line or the piezometric line crosses it (otherwise as slice_circle). Returns nullopt
// and sets *reason when the polyline is not an admissible slip surface.
std::optional<SlipMass> slice_polyline(const Section& section, const SlipPolyline& surface,
                                       const SliceOptions& options, std::string* reason = nullptr);

// A circle as a polyline, so that it can carry a tension crack: `segments` chords of equal angle inscribed in the
// arc between the circle's entry and exit (those of slice_circle, exactly on the ground), moments about the centre.
// The factor of safety differs from the circle's by O(segments^-2) (below 5e-6 at 256 segments on the
// Griffiths & Lane slope, both finely sliced). Returns nullopt and sets *reason when the circle is not an admissible slip surface.
std::optional<SlipPolyline> circle_as_polyline(const Section& section, const Circle& circle, int segments = 256,
                                               std::string* reason = nullptr);

// The default moment point of a polyline (see SlipPolyline::moment_point).
Point default_moment_point(const std::vector<Point>& points);

// Rankine depth of a tension crack, 2 c' / (gamma sqrt(Ka)) with Ka = tan^2(pi/4 - phi'/2), in m.
double rankine_crack_depth(const Material& material);

}  // namespace slope
