// The one reader of a run folder's report.json (coupling/analyses/report_record.hpp). The keys are the writer's
// (coupling/output), documented in docs/scene-format.md.
#include "coupling/analyses/report_record.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

namespace coupling {

namespace {

using nlohmann::json;

std::optional<double> number_at(const json& object, const char* key) {
  if (object.is_object() && object.contains(key) && object[key].is_number()) return object[key].get<double>();
  return std::nullopt;
}

std::optional<slope::Point> point_at(const json& object, const char* key) {
  if (!object.is_object() || !object.contains(key)) return std::nullopt;
  const json& p = object[key];
  if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) return std::nullopt;
  return slope::Point{p[0].get<double>(), p[1].get<double>()};
}

IsphCarryOver isph_carry_over(const json& isph) {
  IsphCarryOver c;
  c.max_density_error = isph.value("max_density_error", 0.0);
  c.mean_density_error = isph.value("mean_density_error", 0.0);
  c.largest_time_step = isph.value("largest_time_step_s", 0.0);
  c.wall_contacts = isph.value("wall_contacts", std::size_t{0});
  c.fluid_energy_start = number_at(isph.value("energy_J_per_m", json::object()), "fluid_start");
  if (isph.contains("bodies") && isph["bodies"].is_array())
    for (const json& j : isph["bodies"]) {
      BodyRecord b;
      b.name = j.value("name", "");
      b.max_speed = j.value("max_speed_m_s", 0.0);
      b.work_on_fluid = j.value("work_on_fluid_J_per_m", 0.0);
      b.stopped_at = number_at(j, "stopped_at_s");
      c.bodies.push_back(b);
    }
  const json past = isph.value("fluid_past_walls", json::object());
  c.past_walls_most = past.value("most", std::size_t{0});
  c.past_walls_first_time = number_at(past, "first_at_s");
  return c;
}

AcceptanceResult acceptance_of(const json& block) {
  AcceptanceResult a;
  a.accepted = block.value("accepted", false);
  for (const json& c : block.value("criteria", json::array())) {
    CriterionResult r;
    r.method = c.value("method", "");
    r.criterion = c.value("criterion", "");
    r.limit = c.value("limit", 0.0);
    r.measured = number_at(c, "measured");
    r.passed = c.value("passed", false);
    r.note = c.value("note", "");
    a.criteria.push_back(r);
  }
  return a;
}

std::optional<ComparisonRecord> comparison_of(const json& comparison) {
  if (!comparison.is_object() || !comparison.contains("methods") || !comparison["methods"].is_object() ||
      comparison["methods"].empty())
    return std::nullopt;
  const json& methods = comparison["methods"];
  ComparisonRecord c;
  c.method = methods.contains("bishop") ? "bishop" : methods.begin().key();
  const json& m = methods[c.method];
  c.entry_offset = point_at(m, "entry_offset_m");
  c.exit_offset = point_at(m, "exit_offset_m");
  c.mean_normal_distance = number_at(m, "mean_normal_distance_m");
  c.intersection_over_union = number_at(m, "intersection_over_union");
  if (comparison.contains("acceptance")) c.acceptance = acceptance_of(comparison["acceptance"]);
  return c;
}

}  // namespace

std::optional<ReportRecord> read_report_record(const std::filesystem::path& report_json) {
  std::ifstream in(report_json);
  if (!in) return std::nullopt;
  const json report = json::parse(in, nullptr, false);
  if (report.is_discarded() || !report.is_object()) return std::nullopt;  // a foreign file is not a report
  ReportRecord r;
  r.status = report.value("status", "failed");
  for (const json& e : report.value("errors", json::array()))
    if (e.is_string()) r.errors.push_back(e.get<std::string>());
  r.total_seconds = report.value("timing_s", json::object()).value("total", 0.0);
  if (report.contains("sph") && report["sph"].is_object() && report["sph"].contains("stopped_because"))
    r.sph_stopped_because = report["sph"].value("stopped_because", "");
  if (report.contains("lem") && report["lem"].is_object()) {
    const json methods = report["lem"].value("methods", json::object());
    for (const auto& [key, method] : methods.items()) r.lem_factors.emplace_back(key, number_at(method, "factor_of_safety"));
  }
  if (report.contains("comparison")) r.comparison = comparison_of(report["comparison"]);
  if (report.contains("isph") && report["isph"].is_object()) r.isph = isph_carry_over(report["isph"]);
  if (report.contains("mps") && report["mps"].is_object()) r.mps = MpsCarryOver{report["mps"].value("max_speed_m_s", 0.0)};
  return r;
}

}  // namespace coupling
