#pragma once
// JSON values the report writers share: a point [x, y], a polyline [[x, y], ...], and an optional number (null
// when absent).
#include <optional>

#include <nlohmann/json.hpp>

#include "slope/section.hpp"

namespace coupling {

inline nlohmann::json point_json(const slope::Point& p) { return nlohmann::json::array({p.x, p.y}); }

template <class Points>
nlohmann::json polyline_json(const Points& line) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : line) out.push_back(point_json(p));
  return out;
}

inline nlohmann::json optional_number(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json();
}

}  // namespace coupling
