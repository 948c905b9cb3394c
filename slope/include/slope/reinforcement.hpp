#pragma once
// Reinforcement and support in limit equilibrium: soil nails, grouted tiebacks, end-anchored bolts, geosynthetics
// and piles. Each element is a straight segment from its head (the end at the slope face, in the sliding mass) to
// its tail. Where a slip surface crosses it, the element acts on the slice whose base holds the crossing with a
// force per metre of slope width: the capacity of the element there (below) divided by its out-of-plane spacing,
// in the element's force direction. An active force enters every equation of every method as it is (an external
// load on the slice base: it lessens the driving force); a passive one enters divided by the factor of safety (it is
// mobilised with the soil's strength: SLOPE/W's "F of S dependent", Slide2's passive support). SI units: m, N, rad.
//
// Capacity of a tensile element (nail, tieback, bolt, geosynthetic) at a crossing s metres from the head (the
// pull-out envelope of Slide2 and XSLOPE):
//     T(s) = min(tensile, head + bond * (bonded length between the head and s), tail + bond * (bonded length
//     between s and the tail end)),
// with the bonded part and the end capacities of each type (reinforcement_defaults). A pile gives its shear
// capacity wherever it is crossed.
#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

#include "slope/point.hpp"
#include "sphslope/names.hpp"

namespace slope {

enum class SupportType {
  soil_nail,     // bonded over its whole length; head plate
  tieback,       // grouted anchor: free length, then a bond length at the tail; head plate
  end_anchored,  // bolt anchored at both ends (head and tail plates), no bond
  geosynthetic,  // bonded over its whole length, no head capacity
  pile,          // shear
};
inline constexpr sphslope::NameTable<SupportType, 5> support_type_names{{{"soil_nail", SupportType::soil_nail},
                                                                         {"tieback", SupportType::tieback},
                                                                         {"end_anchored", SupportType::end_anchored},
                                                                         {"geosynthetic", SupportType::geosynthetic},
                                                                         {"pile", SupportType::pile}}};

// The direction of the force on the sliding mass; every one opposes sliding.
enum class SupportDirection {
  along,          // along the element, from the crossing toward the tail
  tangent,        // tangent to the slip surface at the crossing (the slice base), against sliding
  bisector,       // between the two above
  perpendicular,  // perpendicular to the element, its horizontal part against sliding (piles)
  angle,          // Reinforcement::force_angle below the horizontal, its horizontal part against sliding
};
inline constexpr sphslope::NameTable<SupportDirection, 5> support_direction_names{
    {{"along", SupportDirection::along},
     {"tangent", SupportDirection::tangent},
     {"bisector", SupportDirection::bisector},
     {"perpendicular", SupportDirection::perpendicular},
     {"angle", SupportDirection::angle}}};

enum class SupportApplication {
  active,   // the force as it is
  passive,  // the force divided by the factor of safety
};
inline constexpr sphslope::NameTable<SupportApplication, 2> support_application_names{
    {{"active", SupportApplication::active}, {"passive", SupportApplication::passive}}};

struct Reinforcement {
  SupportType type = SupportType::soil_nail;
  Point head;  // m, the end at the slope face (in the sliding mass)
  Point tail;  // m, the end in the ground behind the slip surface
  double spacing = 1.0;  // m, out of plane (a geosynthetic: 1 with its capacities per metre of width)
  double tensile_capacity = 0.0;  // N per element (tensile types)
  double head_capacity = 0.0;     // N per element, the plate or facing at the head
  double tail_capacity = 0.0;     // N per element, an anchor plate at the tail (end_anchored)
  // N per metre of element length, per element, on the bonded part [bond_start, bond_end] (m from the head);
  // infinity: the element never pulls out there
  double bond_strength = std::numeric_limits<double>::infinity();
  double bond_start = 0.0;
  double bond_end = std::numeric_limits<double>::infinity();  // clipped to the element's length
  double shear_capacity = 0.0;  // N per element (piles)
  SupportDirection direction = SupportDirection::along;
  double force_angle = 0.0;  // rad, SupportDirection::angle only
  SupportApplication application = SupportApplication::passive;

  double length() const;  // m, head to tail
};

// An element of the type with that type's defaults (Slide2's and XSLOPE's presets): a soil nail bonded over its
// length, head capacity = its tensile capacity, along, passive; a tieback bonded over bond_end - bond_start at its
// tail (the caller sets bond_start), along, active; an end-anchored bolt with no bond and both ends as strong as
// the bolt, along, active; a geosynthetic bonded over its length, no head capacity, tangent, active; a pile,
// tangent, active. The capacities follow the tensile capacity when the caller sets it through
// set_tensile_capacity.
Reinforcement reinforcement_defaults(SupportType type);
// Sets the tensile capacity and the end capacities that follow it for the type (head of nails, tiebacks and bolts;
// tail of bolts).
void set_tensile_capacity(Reinforcement& element, double capacity);

// The element's capacity at a crossing `s` metres from its head (N per element; the pile's shear capacity).
double capacity_at(const Reinforcement& element, double s);

// Empty when the element can be used; otherwise a sentence saying what is wrong.
std::string reinforcement_error(const Reinforcement& element);

// The force of an element on a sliding mass, where a slip surface crosses it (SlipMass::supports).
struct SupportForce {
  std::size_t element = 0;  // index into Section::reinforcement
  std::size_t slice = 0;    // the slice whose base holds the crossing
  Point at;                 // m, the crossing
  double distance = 0.0;    // m, from the element's head
  double capacity = 0.0;    // N/m of slope width: the element's capacity there over its spacing
  double force_x = 0.0;     // N/m, the force at full capacity, global x
  double force_y = 0.0;     // N/m, global y (upward)
  bool passive = false;     // enters the equations divided by the factor of safety
};

}  // namespace slope
