#include "coupling/compare/acceptance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "coupling/compare/comparison.hpp"

namespace coupling {

namespace {

std::string format_limit(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

AcceptanceResult evaluate_acceptance(const AcceptanceCriteria& criteria, const ComparisonResult& comparison,
                                     double particle_spacing) {
  AcceptanceResult result;
  const MethodComparison empty;
  for (const std::string& method : criteria.methods) {
    const MethodComparison* found = comparison.find(method);
    const MethodComparison& m = found ? *found : empty;
    auto geometric = [&](double value) { return m.has_geometry ? std::optional<double>(value) : std::nullopt; };
    auto offset = [&](const std::optional<slope::Point>& p) {
      return m.has_geometry && p ? std::optional<double>(std::hypot(p->x, p->y)) : std::nullopt;
    };
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
    add_length("entry_offset_m", criteria.entry_offset, offset(m.entry_offset_m));
    add_length("exit_offset_m", criteria.exit_offset, offset(m.exit_offset_m));
    add_length("mean_normal_distance_m", criteria.mean_normal_distance, geometric(m.mean_normal_distance_m));
    add_length("max_normal_distance_m", criteria.max_normal_distance, geometric(m.max_normal_distance_m));
    if (criteria.min_overlap) add("overlap", *criteria.min_overlap, geometric(m.intersection_over_union), false, "");
    if (criteria.max_fs_difference) {
      std::optional<double> difference;
      if (m.factor_of_safety_on_sph_circle && m.lem_factor_of_safety)
        difference = std::abs(*m.factor_of_safety_on_sph_circle - *m.lem_factor_of_safety);
      add("fs_difference", *criteria.max_fs_difference, difference, true, "");
      if (!difference && m.on_sph_circle_error) result.criteria.back().note = "not measured: " + *m.on_sph_circle_error;
    }
  }
  result.accepted = std::all_of(result.criteria.begin(), result.criteria.end(), [](const auto& c) { return c.passed; });
  return result;
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
