#pragma once
// Internal: the slices of one slip mass in structure-of-arrays form, and the slicer that fills it without
// allocating per trial circle. The public slice_circle() and factor_of_safety() go through the same code.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "indexed_polyline.hpp"
#include "slope/section.hpp"
#include "slope/slices.hpp"

namespace slope::detail {

// Why a circle is not an admissible slip surface.
enum class Rejection {
  none,
  invalid_circle,        // radius not positive / not finite
  misses_ground,         // the lower arc does not cut into the ground
  not_closed_lower_arc,  // the ground stays above the circle's lowest half: no closed mass on the lower arc
  beyond_section,        // the mass would extend past the left or right end of the section
  several_masses,        // the circle leaves and re-enters the ground by more than 1 % of the relief
  below_base,            // the arc passes below the rigid base bottom_y
  too_small,             // the mass is vanishingly small
  radius_too_large,      // radius above 1e4 section extents: a plane to within floating-point geometry
};
const char* rejection_text(Rejection rejection);

// Slices of one mass, ordered left to right (increasing x). Primitive fields mirror slope::Slice; the derived
// fields are what the methods use and are computed in exactly one place, compute_loads().
struct SliceTable {
  int count = 0;
  Circle circle;
  Point entry;
  Point exit;
  int direction = 1;
  double max_depth = 0.0;  // m, largest vertical thickness of the mass at a slice centre line
  // A polyline surface: moments are about `circle`'s centre (the moment point; radius 0), the base normal forces
  // have a moment about it (normal_arm), Janbu's f0 uses chord_depth. A circle: none of these.
  bool circular = true;
  double chord_depth = 0.0;   // m, largest depth of the surface below the entry-exit chord (polylines)
  std::vector<Point> surface; // the polyline (empty for a circle)
  double crack_depth = 0.0;   // m, tension crack at the upper end (0: none)
  double crack_force = 0.0;   // N/m, water thrust in the crack, horizontal, toward sliding
  double crack_force_y = 0.0; // m, its line of action

  // primitive, per slice
  std::vector<double> x_left, x_right, width, sin_a, cos_a, base_length, base_x, base_y, top_y;
  std::vector<double> weight, surcharge, ponded, water_thrust, seismic;
  std::vector<double> seismic_up;  // kv W, upward (Slice::vertical_seismic_force)
  std::vector<double> cohesion, tan_phi, pore_pressure;
  std::vector<std::size_t> material;
  // Non-linear strength (slope/strength.hpp): envelope[i] indexes *envelopes for a base whose strength is an
  // envelope's, -1 for Mohr-Coulomb (cohesion, tan_phi). solve_row (method_table.hpp) then rewrites cohesion and
  // tan_phi with the envelope's tangent at the base's normal stress. has_envelopes: any base has one (compute_loads).
  std::vector<int> envelope;
  const std::vector<StrengthEnvelope>* envelopes = nullptr;
  bool has_envelopes = false;
  // Reinforcement (slope/reinforcement.hpp): the forces of the elements this surface crosses (find_support_crossings).
  // compute_loads adds each to its slice's loads, a passive one times passive_scale (1 / F: solve_row iterates on
  // it); has_passive_supports: some force is passive (compute_loads).
  std::vector<SupportForce> supports;
  // The line loads on the mass's ground surface (find_line_loads), added to their slices' loads as the supports are.
  std::vector<AppliedLineLoad> line_loads;
  double passive_scale = 1.0;
  bool has_passive_supports = false;
  // derived, per slice
  std::vector<double> cohesion_force;  // c' l
  std::vector<double> pore_force;      // U = u l
  std::vector<double> vertical;        // V = W + surcharge + ponded water - kv W, downward
  std::vector<double> horizontal;      // H = kh W + water thrust, in the sliding direction
  std::vector<double> drive_moment;    // moment of V and H about the centre, positive when it drives sliding
  std::vector<double> shear_arm;       // distance from the centre to the base chord
  // polylines: moment of a unit base normal force about the moment point, positive when it drives sliding (zero
  // for a circle: the normal passes through the centre)
  std::vector<double> normal_arm;
  double total_drive_moment = 0.0;
  double drive_moment_scale = 0.0;  // sum of |moments|: a total below 1e-9 of it counts as no driving moment
  bool driven() const { return total_drive_moment > 1e-9 * drive_moment_scale; }

  // A number no other surface sliced in this process has: resize() draws a new one, as every new surface is sliced
  // through it (the envelope iteration starts from the last solution's stresses on the same surface).
  std::uint64_t surface_id = 0;

  void resize(int n);  // sets count and a new surface_id; grows the buffers only when needed
  void compute_loads();

 private:
  void compute_polyline_arms();  // shear and normal arms about a moment point (polylines)
  double shared_loads(int i, double dir, double& scale);  // the loads and driving moment a circle and a polyline share
  void add_crack_force();        // the water thrust of a crack on the upslope slice
  void add_support_forces();     // the reinforcement's forces and the line loads (reinforcement.cpp)
  void add_point_force(int i, Point at, double fx, double fy);
};

// The crossings of the elements with the table's slip surface (circle or polyline, between the mass's ends), each
// element at its first crossing from its head, into table.supports. An element that leaves the mass through a
// tension crack's face only does not act (as in Slide2, UTEXAS4 and SLOPE/W: tests/slope/test_lem_loads.cpp,
// Pockoski & Duncan's test slope 7). Call after the slices are filled.
void find_support_crossings(const std::vector<Reinforcement>& elements, SliceTable& table);
struct PreparedSection;
// The section's line loads on the ground between the mass's ends (inclusive), each on the slice under it, into
// table.line_loads. Call after the slices are filled.
void find_line_loads(const PreparedSection& section, SliceTable& table);

// Section data arranged for fast repeated slicing.
struct PreparedSection {
  double x_min = 0.0, x_max = 0.0, bottom_y = 0.0;
  double ground_y_min = 0.0, ground_y_max = 0.0;
  std::vector<Point> ground;
  // profile lines ordered from the top (the ground surface, lines[0]) down; they may touch but not cross
  std::vector<IndexedPolyline> lines;
  std::vector<double> line_unit_weight, line_cohesion, line_tan_phi;
  // below the piezometric line (the unit weight where the material has no saturated one or there is no water)
  std::vector<double> line_saturated_weight;
  bool has_saturated_weights = false;  // some line's differs from its unit weight
  // cohesion with depth (Material::cohesion_rate): rate, datum (NaN: below the line itself) and cap of each line
  std::vector<double> line_cohesion_rate, line_cohesion_datum, line_cohesion_max;
  std::vector<std::size_t> line_material;
  std::vector<double> material_ru;  // r_u of each material of the section (by its index), 0 when none
  // the strength envelopes of the section's materials, and each material's index into them (-1: Mohr-Coulomb)
  std::vector<StrengthEnvelope> envelopes;
  std::vector<int> material_envelope;
  // The cohesion of line k's material at the point (x, y) in it, with its increase with depth.
  double cohesion_at(std::size_t k, double x, double y) const;
  bool has_water = false;
  IndexedPolyline piezometric_line;
  double water_unit_weight = 0.0;
  std::vector<Surcharge> surcharges;
  double seismic_coefficient = 0.0;
  double vertical_seismic_coefficient = 0.0;
  std::vector<Reinforcement> reinforcement;
  std::vector<LineLoad> line_loads;
  // x where a slice must end whatever the circle: surcharge ends and where the piezometric line crosses the ground
  // (the edge of ponded water). Vertices are not among them: the slices integrate the lines exactly.
  std::vector<double> fixed_breaks;
  // x of the ground vertices that lie on the rigid base (e.g. the toe of a slope standing on a firm base): no soil
  // on one side, so a slip surface may end there
  std::vector<double> base_contacts;

  explicit PreparedSection(const Section& section);
  const IndexedPolyline& ground_line() const { return lines.front(); }
  double ground_at(double x) const;
};

class Slicer {
 public:
  explicit Slicer(const Section& section) : prepared_(section) {}
  const PreparedSection& prepared() const { return prepared_; }
  // Fills `table` with the slices of the mass above `circle`. No allocation once the buffers have grown.
  Rejection slice(const Circle& circle, int target_slices, SliceTable& table);
  // Fills `table` with the slices of the mass above a polyline (polyline_slices.cpp). Returns why the polyline is
  // not an admissible slip surface, empty when it is.
  std::string slice_polyline(const SlipPolyline& surface, int target_slices, SliceTable& table);

 private:
  void fill_slices(const Circle& circle, int dir, SliceTable& table);
  // Slices between bounds_, from the base heights arc_y_ and ground heights ground_y_ at the bounds.
  // circle: the arc of a circular surface (nullptr for a polyline), to settle a base chord lying on a layer line.
  void fill_from_bounds(int dir, SliceTable& table, const Circle* circle);
  void slice_water(int i, double sdir, SliceTable& table) const;
  struct SliceSpan {
    double x0, x1, width, base_x, base_y, top_y;  // [m]
  };
  SliceSpan span_of(int i, const SliceTable& table) const;
  double slice_layers(int i, const Circle* circle, SliceTable& table);
  double surcharge_load(double x0, double x1) const;
  // Slice boundaries bounds_ from the mass's ends and the sorted breaks_ inside it (xr appended here).
  int place_bounds(double xl, double xr, int target_slices);
  bool shallow_gap(const Circle& circle, double x0, double x1) const;
  // The steps of slice(): the split points of the ground against the arc, the mass between two of them, its
  // sliding direction, the boundaries its base must break at.
  struct MassEnds {
    double left = 0.0, right = 0.0;  // [m]
    bool left_is_root = false, left_is_contact = false, right_is_contact = false;
  };
  void split_points(const Circle& circle, double x_lo, double x_hi);
  Rejection find_mass(const Circle& circle, double x_lo, double x_hi, MassEnds& mass);
  int sliding_direction(double xl, double xr, double xc) const;
  void collect_breaks(const Circle& circle, double xl, double xr);

  PreparedSection prepared_;
  std::vector<double> roots_, gaps_, breaks_, bounds_, arc_y_, ground_y_, line_y_;
  std::vector<char> root_is_contact_;
};

// Largest depth of a polyline's vertices below the chord joining its ends, perpendicular to the chord (m).
double chord_depth(const std::vector<Point>& surface);

// Conversions between the table and the public SlipMass (one place each).
void table_to_mass(const SliceTable& table, SlipMass& mass);
void mass_to_table(const SlipMass& mass, SliceTable& table);

}  // namespace slope::detail
