#include "coupling/output/srm_report.hpp"

namespace coupling {

namespace {

nlohmann::json trials_json(const std::vector<SrmTrial>& trials) {
  nlohmann::json out = nlohmann::json::array();
  for (const SrmTrial& t : trials)
    out.push_back({{"factor", t.factor},
                   {"failed", t.failed},
                   {"max_displacement_m", t.max_displacement_m},
                   {"stopped_because", t.stopped_because},
                   {"reason", t.reason},
                   {"simulated_time_s", t.simulated_time_s},
                   {"wall_seconds", t.wall_seconds}});
  return out;
}

// The bisection's outcome: method, criterion, factor of safety and bracket.
void write_bisection(const BisectionResult& b, nlohmann::json& report) {
  report["method"] =
      "SPH strength reduction: c/F, atan(tan(phi)/F), atan(tan(psi)/F) for every material; "
      "geostatic K0 initial stress, linear velocity damping; bisection on F";
  report["failure_criterion"] =
      "a trial fails if the largest soil-particle displacement exceeds "
      "failure_displacement_m, or if the soil is still moving faster than rest_speed_m_s "
      "at max_time_s, or if the run stops abnormally; it is stable if it comes to rest";
  report["bracketed"] = b.bracketed;
  if (b.bracketed) {
    report["factor_of_safety"] = b.factor_of_safety;
    report["bracket"] = {b.lo, b.hi};
  } else {
    report["factor_of_safety"] = nullptr;
  }
  if (!b.error.empty()) report["error"] = "srm: " + b.error;
}

// The settings the trials used.
void write_plan(const SrmResult& r, nlohmann::json& report) {
  report["tolerance"] = r.tolerance;
  report["initial_bracket"] = {r.initial_bracket.lo, r.initial_bracket.hi};
  report["initial_bracket_source"] = r.initial_bracket.source;
  report["slope_height_m"] = r.plan.height;
  report["failure_displacement_m"] = r.plan.failure_displacement;
  report["damping_per_s"] = r.plan.damping;
  report["first_mode_period_s"] = r.plan.period;
  report["max_time_s"] = r.plan.max_time;
  report["rest_speed_m_s"] = r.plan.rest_speed;
  report["rest_check_after_s"] = r.plan.min_time;
}

// The LEM factors next to FS_SPH, and the loads SPH left out.
void write_lem_context(const SrmResult& r, nlohmann::json& report) {
  report["lem_factor_of_safety"] = nlohmann::json::object();
  for (const auto& [key, fs] : r.lem_fs_by_method) report["lem_factor_of_safety"][key] = fs;
  report["warnings"] = r.warnings;
  if (r.lem_bishop) {
    report["lem_bishop"] = *r.lem_bishop;
    if (r.bisection.bracketed) report["ratio_to_lem_bishop"] = r.bisection.factor_of_safety / *r.lem_bishop;
  }
}

}  // namespace

nlohmann::json srm_report(const SrmResult& result) {
  nlohmann::json report = nlohmann::json::object();
  write_bisection(result.bisection, report);
  write_plan(result, report);
  report["particle_spacing_m"] = result.particle_spacing_m;
  report["soil_particles"] = result.soil_particles;
  write_lem_context(result, report);
  report["trials"] = trials_json(result.bisection.trials);
  report["seconds"] = result.seconds;
  return report;
}

nlohmann::json srm_error_report(const std::string& message) { return {{"error", message}}; }

}  // namespace coupling
