// section.reinforcement: soil nails, tiebacks, end-anchored bolts, geosynthetics and piles (slope/reinforcement.hpp),
// read into SI with each type's defaults; the keys a type does not have are unknown keys for it.
#include <cmath>
#include <optional>
#include <string>

#include "scene_internal.hpp"
#include "slope/reinforcement.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

bool tensile(slope::SupportType type) { return type != slope::SupportType::pile; }

std::optional<slope::Point> read_point(JsonReader& r, std::string_view key, Need need) {
  const nlohmann::json* value = r.raw(key, need);
  if (value == nullptr) return std::nullopt;
  const auto pair = read_pair(*value, r.path_of(key), r.diagnostics(), "a point [x_m, y_m]");
  if (!pair) return std::nullopt;
  return slope::Point{pair->first, pair->second};
}

// The tail: tail_m, or length_m with inclination_deg (below the horizontal, pointing into the slope: away from the
// face, toward the higher ground; `into` is -1 or +1 in x).
std::optional<slope::Point> read_tail(JsonReader& r, const slope::Point& head, int into) {
  const bool by_point = r.raw("tail_m", Need::optional) != nullptr;
  const bool by_length = r.raw("length_m", Need::optional) != nullptr;
  if (by_point == by_length) {
    r.diagnostics().error(r.path(), by_point ? "give either tail_m or length_m with inclination_deg, not both"
                                             : "give the element's other end: tail_m [x, y], or length_m and "
                                               "inclination_deg (below the horizontal, into the slope)");
    return std::nullopt;
  }
  if (by_point) return read_point(r, "tail_m", Need::required);
  if (into == 0) {
    r.diagnostics().error(r.path_of("length_m"), "the ground is level at both ends of the section, so \"into the "
                                                 "slope\" is not defined: give tail_m [x, y] instead");
    return std::nullopt;
  }
  const auto length = r.number("length_m", Need::required);
  const auto inclination = r.number("inclination_deg", Need::required);
  if (!length || !inclination) return std::nullopt;
  const double a = sphslope::radians(*inclination);
  return slope::Point{head.x + into * *length * std::cos(a), head.y - *length * std::sin(a)};
}

// The capacities and bond of a tensile element (kN, kN/m to N, N/m).
void read_tensile(JsonReader& r, slope::Reinforcement& e) {
  const auto tensile_kN = r.number("tensile_capacity_kN", Need::required);
  if (tensile_kN) slope::set_tensile_capacity(e, *tensile_kN * kilo);
  if (const auto head = r.number("head_capacity_kN", Need::optional)) e.head_capacity = *head * kilo;
  if (e.type == slope::SupportType::end_anchored) {
    if (const auto tail = r.number("tail_capacity_kN", Need::optional))
      e.tail_capacity = *tail * kilo;
    return;  // no bond
  }
  const Need bond_need = e.type == slope::SupportType::tieback ? Need::required : Need::optional;
  if (const auto bond = r.number("bond_strength_kN_m", bond_need)) e.bond_strength = *bond * kilo;
  if (e.type == slope::SupportType::tieback) {
    const auto bond_length = r.number("bond_length_m", Need::required);
    if (bond_length) {
      if (!(*bond_length <= e.length() * (1.0 + 1e-12)))
        r.diagnostics().error(r.path_of("bond_length_m"), "must be at most the element's length, " +
                                                              format_number(e.length()) + " m (got " +
                                                              format_number(*bond_length) + ")");
      e.bond_start = std::max(0.0, e.length() - *bond_length);
    }
  }
}

std::optional<slope::Reinforcement> read_element(JsonReader& r, int into) {
  const auto type = read_named_required(r, "type", slope::support_type_names);
  const auto head = read_point(r, "head_m", Need::required);
  if (!type || !head) return std::nullopt;
  slope::Reinforcement e = slope::reinforcement_defaults(*type);
  e.head = *head;
  const auto tail = read_tail(r, *head, into);
  if (!tail) return std::nullopt;
  e.tail = *tail;
  e.spacing = r.number_or("spacing_m", 1.0);
  if (tensile(e.type)) read_tensile(r, e);
  else if (const auto shear = r.number("shear_capacity_kN", Need::required))
    e.shear_capacity = *shear * kilo;
  read_named(r, "direction", slope::support_direction_names, e.direction);
  if (e.direction == slope::SupportDirection::angle) {
    if (const auto angle = r.number("force_angle_deg", Need::required))
      e.force_angle = sphslope::radians(*angle);
  }
  read_named(r, "application", slope::support_application_names, e.application);
  return e;
}

}  // namespace

std::vector<slope::Reinforcement> read_reinforcement(const nlohmann::json& array, const std::string& path,
                                                     const SectionExtent& extent, Diagnostics& diagnostics, bool& ok) {
  std::vector<slope::Reinforcement> result;
  for (std::size_t i = 0; i < array.size(); ++i) {
    JsonReader r(array[i], index_path(path, i), diagnostics);
    const std::size_t errors_before = diagnostics.size();
    std::optional<slope::Reinforcement> e = read_element(r, extent.into_slope);
    r.finish();
    if (!e || diagnostics.size() != errors_before) {
      ok = false;
      continue;
    }
    if (const std::string why = slope::reinforcement_error(*e); !why.empty()) {
      diagnostics.error(r.path(), why);
      ok = false;
      continue;
    }
    if (extent.known && (std::fmin(e->head.x, e->tail.x) < extent.x_min || std::fmax(e->head.x, e->tail.x) > extent.x_max)) {
      diagnostics.error(r.path(), "must lie on the section (x " + format_number(extent.x_min) + " to " +
                                      format_number(extent.x_max) + " m), got x " + format_number(e->head.x) +
                                      " to " + format_number(e->tail.x) + " m");
      ok = false;
      continue;
    }
    result.push_back(*e);
  }
  return result;
}

}  // namespace coupling
