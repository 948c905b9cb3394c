// The "isph" block of report.json and monitors.csv (coupling/output/isph_report.hpp).
#include "coupling/output/isph_report.hpp"

#include <cmath>
#include <cstdio>

namespace coupling {

nlohmann::json isph_report(const IsphStageResult& r) {
  nlohmann::json j;
  j["status"] = r.summary.stopped_because == "end_time" ? "ok" : "failed";
  j["stopped_because"] = r.summary.stopped_because;
  if (!r.summary.diagnostic.empty()) j["diagnostic"] = r.summary.diagnostic;
  j["pressure"] = r.pressure_mode;
  j["kernel"] = r.kernel;
  j["particle_spacing_m"] = r.particle_spacing;
  j["smoothing_length_m"] = r.smoothing_length;
  j["particles"] = {{"fluid", r.fluid_particles}, {"wall", r.wall_particles}};
  j["steps"] = r.summary.steps;
  j["simulated_time_s"] = r.summary.simulated_time;
  j["wall_s"] = r.summary.wall_seconds;
  j["fluid_mass_kg_per_m"] = {{"start", r.fluid_mass_start}, {"end", r.fluid_mass_end}};
  j["front_x_m"] = r.front_x;
  j["max_density_error"] = r.max_density_error;
  j["frames_written"] = r.summary.frames_written;
  nlohmann::json columns = nlohmann::json::array({"time_s"});
  for (const std::string& c : r.monitors.columns) columns.push_back(c);
  j["monitors"] = {{"file", "monitors.csv"}, {"columns", columns}, {"rows", r.monitors.times.size()}};
  return j;
}

nlohmann::json isph_error_report(const std::string& error) { return {{"status", "failed"}, {"error", error}}; }

}  // namespace coupling
