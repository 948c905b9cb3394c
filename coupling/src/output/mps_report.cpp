// The "mps" block of report.json (coupling/output/mps_report.hpp).
#include "coupling/output/mps_report.hpp"

namespace coupling {

nlohmann::json mps_report(const MpsStageResult& r) {
  nlohmann::json j;
  j["status"] = r.summary.stopped_because == "end_time" ? "ok" : "failed";
  j["stopped_because"] = r.summary.stopped_because;
  if (!r.summary.diagnostic.empty()) j["diagnostic"] = r.summary.diagnostic;
  j["regularisation"] = r.regularisation;
  j["interaction_viscosity"] = r.interaction_viscosity;
  j["effective_pressure"] = r.effective_pressure;
  j["stress_divergence"] = r.stress_divergence;
  j["particle_spacing_m"] = r.particle_spacing;
  j["effective_radius_m"] = r.effective_radius;
  j["sound_speed_m_s"] = r.sound_speed;
  j["viscosity_cap_Pa_s"] = r.viscosity_cap;
  if (r.gate)
    j["gate"] = {{"x_m", r.gate_x}, {"lift_speed_m_s", r.gate_lift_speed}, {"lift_distance_m", r.gate_lift_distance}};
  j["particles"] = {{"moving", r.moving_particles}, {"wall", r.wall_particles}};
  j["steps"] = r.summary.steps;
  j["simulated_time_s"] = r.summary.simulated_time;
  j["wall_s"] = r.summary.wall_seconds;
  j["mass_kg_per_m"] = {{"start", r.mass_start}, {"end", r.mass_end}};
  j["deposit"] = {{"front_x_m", {{"start", r.front_start}, {"end", r.front_end}}},
                  {"wall_height_m", {{"start", r.wall_height_start}, {"end", r.wall_height_end}}},
                  {"max_speed_end_m_s", r.max_speed_end}};
  j["max_speed_m_s"] = r.max_speed_run;
  j["warnings"] = nlohmann::json::array();
  for (const std::string& w : r.warnings) j["warnings"].push_back(w);
  j["frames_written"] = r.summary.frames_written;
  nlohmann::json columns = nlohmann::json::array({"time_s"});
  for (const std::string& c : r.monitors.columns) columns.push_back(c);
  j["monitors"] = {{"file", "monitors.csv"}, {"columns", columns}, {"rows", r.monitors.times.size()}};
  return j;
}

nlohmann::json mps_error_report(const std::string& error) { return {{"status", "failed"}, {"error", error}}; }

}  // namespace coupling
