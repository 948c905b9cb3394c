#include "coupling/compare/acceptance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace coupling {

namespace {

std::optional<double> number_at(const nlohmann::json& block, const char* key) {
  if (!block.contains(key) || !block[key].is_number()) return std::nullopt;
  return block[key].get<double>();
}

// Length of an [dx, dy] offset.
std::optional<double> offset_length(const nlohmann::json& block, const char* key) {
  if (!block.contains(key) || !block[key].is_array() || block[key].size() != 2) return std::nullopt;
  return std::hypot(block[key][0].get<double>(), block[key][1].get<double>());
}

std::string format_limit(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

AcceptanceResult evaluate_acceptance(const AcceptanceCriteria& criteria, const nlohmann::json& comparison,
                                     double particle_spacing) {
  AcceptanceResult result;
  const nlohmann::json empty = nlohmann::json::object();
  for (const std::string& method : criteria.methods) {
    const bool has = comparison.contains("methods") && comparison["methods"].contains(method);
    const nlohmann::json& m = has ? comparison["methods"][method] : empty;
    // at most: measured <= limit; at least: measured >= limit
    auto add = [&](const char* name, double limit, std::optional<double> measured, bool at_most, std::string note) {
      CriterionResult c{method, name, limit, measured, false, std::move(note)};
      if (measured) c.passed = at_most ? *measured <= limit : *measured >= limit;
      else c.note = "not measured (no SPH failure surface, or no critical surface for this method)";
      result.criteria.push_back(c);
    };
    auto add_length = [&](const char* name, const std::optional<LengthLimit>& limit, std::optional<double> measured) {
      if (!limit) return;
      add(name, limit->metres(particle_spacing), measured,
          true, limit->in_spacings ? format_limit(limit->value) + " particle spacings" : "");
    };
    add_length("entry_offset_m", criteria.entry_offset, offset_length(m, "entry_offset_m"));
    add_length("exit_offset_m", criteria.exit_offset, offset_length(m, "exit_offset_m"));
    add_length("mean_normal_distance_m", criteria.mean_normal_distance, number_at(m, "mean_normal_distance_m"));
    add_length("max_normal_distance_m", criteria.max_normal_distance, number_at(m, "max_normal_distance_m"));
    if (criteria.min_overlap) add("overlap", *criteria.min_overlap, number_at(m, "intersection_over_union"), false, "");
    if (criteria.max_fs_difference) {
      const auto on_sph = number_at(m, "factor_of_safety_on_sph_circle");
      const auto critical = number_at(m, "lem_factor_of_safety");
      std::optional<double> difference;
      if (on_sph && critical) difference = std::abs(*on_sph - *critical);
      add("fs_difference", *criteria.max_fs_difference, difference, true, "");
      if (!difference && m.contains("factor_of_safety_on_sph_circle_error"))
        result.criteria.back().note = "not measured: " + m["factor_of_safety_on_sph_circle_error"].get<std::string>();
    }
  }
  result.accepted = std::all_of(result.criteria.begin(), result.criteria.end(), [](const auto& c) { return c.passed; });
  return result;
}

nlohmann::json acceptance_json(const AcceptanceResult& result) {
  nlohmann::json criteria = nlohmann::json::array();
  for (const CriterionResult& c : result.criteria) {
    nlohmann::json row = {{"method", c.method}, {"criterion", c.criterion}, {"limit", c.limit},
                          {"measured", c.measured ? nlohmann::json(*c.measured) : nlohmann::json()},
                          {"passed", c.passed}};
    if (!c.note.empty()) row["note"] = c.note;
    criteria.push_back(row);
  }
  return {{"accepted", result.accepted}, {"criteria", criteria}};
}

std::vector<std::string> failed_criteria_lines(const AcceptanceResult& result) {
  std::vector<std::string> lines;
  for (const CriterionResult& c : result.criteria) {
    if (c.passed) continue;
    const bool at_least = c.criterion == "overlap";
    std::string line = c.method + " " + c.criterion + ": ";
    line += c.measured ? format_limit(*c.measured) + (at_least ? " < " : " > ") + format_limit(c.limit) : "not measured";
    if (!c.note.empty()) line += " (" + c.note + ")";
    lines.push_back(line);
  }
  return lines;
}

}  // namespace coupling
