// The "coupled" block of report.json (coupling/output/coupled_report.hpp; its keys in docs/scene-format.md).
#include "coupling/output/coupled_report.hpp"

namespace coupling {

namespace {

nlohmann::json coupled_impact_report(const CoupledImpact& c);

}  // namespace

nlohmann::json coupled_report(const CoupledStageResult& r) {
  nlohmann::json j;
  j["status"] = r.summary.stopped_because == "end_time" ? "ok" : "failed";
  j["stopped_because"] = r.summary.stopped_because;
  if (!r.summary.diagnostic.empty()) j["diagnostic"] = r.summary.diagnostic;
  j["particle_spacing_m"] = r.particle_spacing;
  j["particles"] = {{"soil", r.soil_particles}, {"soil_walls", r.soil_wall_particles}, {"water", r.water_particles}};
  j["water_steps"] = r.summary.total_steps;  // from t = 0, the steps before a --resume included
  j["simulated_time_s"] = r.summary.simulated_time;
  j["wall_s"] = r.summary.wall_seconds;
  j["since_start"] = {{"soil_steps", r.soil_steps},
                      {"soil_substeps_per_water_step", {{"mean", r.mean_substeps}, {"most", r.most_substeps}}},
                      {"solver_iterations_per_water_step",
                       {{"mean", r.mean_solver_iterations}, {"most", r.most_solver_iterations}}},
                      {"wall_s", {{"soil", r.soil_seconds}, {"water", r.water_seconds}}},
                      {"particle_steps_per_s",
                       {{"soil", r.soil_particle_steps_per_second}, {"water", r.water_particle_steps_per_second}}}};
  j["soil_mass_kg_per_m"] = {{"start", r.soil_mass_start}, {"end", r.soil_mass_end}};
  j["water_volume_m2"] = {{"start", r.water_volume_start},
                          {"end", r.water_volume_end},
                          {"ratio", r.water_volume_start > 0 ? nlohmann::json(r.water_volume_end / r.water_volume_start)
                                                             : nlohmann::json(nullptr)}};
  j["water_removed"] = r.water_removed;
  j["water_inside_soil_end"] = r.water_inside_soil;
  j["soil_max_displacement_m"] = r.soil_max_displacement;
  j["soil_max_plastic_strain"] = r.soil_max_plastic_strain;
  j["water_max_speed_end_m_s"] = r.water_max_speed;
  j["warnings"] = r.warnings;
  j["figures"] = r.figures;
  j["frames_written"] = r.summary.frames_written;
  nlohmann::json columns = nlohmann::json::array({"time_s"});
  for (const std::string& c : r.monitors.columns) columns.push_back(c);
  j["monitors"] = {{"file", "monitors.csv"}, {"columns", columns}, {"rows", r.monitors.times.size()}};
  nlohmann::json slide_columns = nlohmann::json::array({"time_s"});
  for (const std::string& c : r.slide.columns) slide_columns.push_back(c);
  j["slide"] = {{"file", "slide.csv"}, {"columns", slide_columns}, {"rows", r.slide.times.size()}};
  double fastest = 0, fastest_at = 0;
  for (const auto& [t, speed] : monitor_column(r.slide, "centroid_speed_m_s"))
    if (speed > fastest) {
      fastest = speed;
      fastest_at = t;
    }
  j["slide"]["fastest_centroid_speed_m_s"] = fastest;
  j["slide"]["fastest_at_s"] = fastest_at;
  if (r.impact) j["impact"] = coupled_impact_report(*r.impact);
  return j;
}

namespace {

nlohmann::json coupled_impact_report(const CoupledImpact& c) {
  if (!c.missing.empty()) return {{"status", "no impact"}, {"reason", c.missing}};
  nlohmann::json ranges = nlohmann::json::object();
  for (const ImpactGroup& g : c.predicted.groups)
    ranges[g.name] = {{"value", g.value}, {"range", {g.low, g.high}}, {"inside", g.inside()}};
  const ImpulseWave& w = c.predicted;
  nlohmann::json celerity = nlohmann::json::array();
  for (const CelerityCheck& k : c.celerity)
    celerity.push_back({{"from", k.from}, {"to", k.to}, {"speed_m_s", k.speed}, {"expected_m_s", k.expected},
                        {"ratio", k.speed / k.expected}});
  return {{"status", "ok"},
          {"time_s", c.time},
          {"slide",
           {{"centroid_speed_m_s", c.slide.speed}, {"thickness_m", c.slide.thickness},
            {"mass_kg_per_m", c.slide.mass_per_width}, {"ramp_angle_deg", c.slide.angle_deg},
            {"still_water_depth_m", c.slide.depth}}},
          {"parameters", {{"F", w.F}, {"S", w.S}, {"M", w.M}, {"alpha_deg", c.slide.angle_deg}, {"P", w.P}}},
          {"ranges", ranges},
          {"inside_ranges", w.inside_ranges()},
          {"heller_hager_2010",
           {{"crest_amplitude_m", w.crest_amplitude}, {"wave_height_m", w.wave_height},
            {"crest_distance_m", w.crest_position}, {"period_s", w.period}, {"celerity_m_s", w.celerity}}},
          {"gauges",
           {{"largest_crest_m", c.largest_crest}, {"largest_crest_gauge", c.largest_crest_gauge},
            {"largest_crest_at_s", c.largest_crest_at}, {"largest_crest_distance_m", c.largest_crest_distance},
            {"crest_ratio", c.largest_crest / w.crest_amplitude}, {"leading_crest_celerity", celerity}}}};
}

}  // namespace

nlohmann::json coupled_error_report(const std::string& error) { return {{"status", "failed"}, {"error", error}}; }

}  // namespace coupling
