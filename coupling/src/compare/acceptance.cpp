#include "coupling/compare/acceptance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace coupling {

namespace {

// A length criterion is given in metres ("<name>_max_m") or in particle spacings ("<name>_max_spacings"), not both.
std::optional<LengthLimit> read_length_limit(JsonReader& r, const std::string& name) {
  const auto metres = r.number(name + "_max_m", Need::optional, Bounds::non_negative());
  const auto spacings = r.number(name + "_max_spacings", Need::optional, Bounds::non_negative());
  if (metres && spacings) {
    r.diagnostics().error(r.path_of(name + "_max_spacings"),
                          "give the limit either in metres (" + name + "_max_m) or in particle spacings, not both");
    return std::nullopt;
  }
  if (metres) return LengthLimit{*metres, false};
  if (spacings) return LengthLimit{*spacings, true};
  return std::nullopt;
}

std::vector<std::string> read_methods(JsonReader& r, const std::vector<std::string>& known) {
  std::vector<std::string> methods;
  const nlohmann::json* list = r.array("methods", Need::optional, 1, limits::name_list);
  if (list == nullptr) {
    const bool has_bishop = std::find(known.begin(), known.end(), "bishop") != known.end();
    if (has_bishop) methods.push_back("bishop");
    else if (!known.empty()) methods.push_back(known.front());
    return methods;
  }
  std::string allowed;
  for (const auto& k : known) allowed += (allowed.empty() ? "" : ", ") + k;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string path = index_path(r.path_of("methods"), i);
    const auto key = read_string((*list)[i], path, r.diagnostics());
    if (!key) continue;
    if (std::find(known.begin(), known.end(), *key) == known.end())
      r.diagnostics().error(path, "method \"" + *key + "\" is not computed by analyses.lem (computed: " + allowed + ")");
    else
      methods.push_back(*key);
  }
  return methods;
}

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

std::optional<AcceptanceCriteria> read_acceptance(const nlohmann::json& block, const std::vector<std::string>& known_methods,
                                                  Diagnostics& diagnostics) {
  JsonReader r(block, "analyses.compare.acceptance", diagnostics);
  const std::size_t errors_before = diagnostics.size();
  AcceptanceCriteria c;
  c.methods = read_methods(r, known_methods);
  c.entry_offset = read_length_limit(r, "entry_offset");
  c.exit_offset = read_length_limit(r, "exit_offset");
  c.mean_normal_distance = read_length_limit(r, "mean_normal_distance");
  c.max_normal_distance = read_length_limit(r, "max_normal_distance");
  c.min_overlap = r.number("overlap_min", Need::optional, Bounds::closed(0.0, 1.0));
  c.max_fs_difference = r.number("fs_difference_max", Need::optional, Bounds::non_negative());
  r.finish();
  const bool any = c.entry_offset || c.exit_offset || c.mean_normal_distance || c.max_normal_distance ||
                   c.min_overlap || c.max_fs_difference;
  if (!any && diagnostics.size() == errors_before)
    diagnostics.error("analyses.compare.acceptance",
                      "no criterion given (allowed: entry_offset_max_m, exit_offset_max_m, mean_normal_distance_max_m, "
                      "max_normal_distance_max_m (each also as _max_spacings), overlap_min, fs_difference_max)");
  if (diagnostics.size() != errors_before) return std::nullopt;
  return c;
}

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
