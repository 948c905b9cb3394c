// The "isph" block of report.json and monitors.csv (coupling/output/isph_report.hpp).
#include "coupling/output/isph_report.hpp"

#include "coupling/analyses/isph_front.hpp"

namespace coupling {

namespace {

nlohmann::json still_tank_json(const StillTankCheck& c) {
  return {{"depth_m", c.depth},
          {"rho_g_depth_Pa", c.rho_g_depth},
          {"floor_pressure_Pa", c.floor_pressure},
          {"floor_pressure_ratio", c.floor_pressure / c.rho_g_depth},
          {"expected_ratio", c.expected_ratio},
          {"pressure_gradient_ratio", c.gradient_ratio},
          {"max_speed_end_m_s", c.max_speed_end},
          {"sqrt_g_depth_m_s", c.celerity},
          {"max_speed_end_ratio", c.max_speed_end / c.celerity}};
}

nlohmann::json front_error_json(const FrontErrors& e) {
  return {{"reference", "martin_moyce_1952_n2_2"},
          {"T_range", {front_error_T_min, e.T_max}},
          {"points", e.points},
          {"rms_relative_error", e.rms},
          {"rms_relative_error_shifted", e.rms_shifted},
          {"shift_T", e.shift}};
}

nlohmann::json agreement_json(const AgreementStatistics& a) {
  return {{"points", a.points},       {"r", a.r},         {"mean_error", a.mean_error},
          {"mean_absolute_error", a.mean_absolute_error}, {"rms_error", a.rms_error}, {"nse", a.nse}};
}

nlohmann::json ritter_json(const RitterComparison& c) {
  nlohmann::json j = {{"front_X_against_2T", agreement_json(c.front)}, {"front_speed_ratio", c.front_speed_ratio}};
  j["dam_depth_ratio"] = c.dam_depth_ratio ? nlohmann::json(*c.dam_depth_ratio) : nlohmann::json(nullptr);
  j["dam_depth_points"] = c.dam_depth_points;
  return j;
}

nlohmann::json waves_json(const GaugeWaves& w) {
  nlohmann::json gauges = nlohmann::json::array(), celerity = nlohmann::json::array();
  const auto optional = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  for (const GaugeWave& g : w.gauges)
    gauges.push_back({{"name", g.name}, {"x_m", g.x}, {"initial_m", g.initial}, {"highest_m", g.highest}, {"highest_at_s", g.highest_at},
                      {"lowest_m", g.lowest}, {"leading_crest_m", optional(g.crest)},
                      {"leading_crest_at_s", optional(g.crest_at)}});
  for (const WaveCelerity& c : w.celerity)
    celerity.push_back({{"from", c.from}, {"to", c.to}, {"speed_m_s", c.speed}, {"ratio_to_sqrt_g_d", c.ratio}});
  return {{"still_water_depth_m", w.depth},
          {"sqrt_g_d_m_s", w.long_wave_celerity},
          {"leading_crest_least_m", crest_fraction * w.depth},
          {"gauges", gauges},
          {"leading_crest_celerity", celerity}};
}

nlohmann::json bodies_json(const IsphStageResult& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const BodyRecord& b : r.bodies) {
    nlohmann::json j = {{"name", b.name},
                        {"mass_kg_per_m", b.mass},
                        {"travel_m", b.travel},
                        {"speed_end_m_s", b.speed},
                        {"max_speed_m_s", b.max_speed},
                        {"work_on_fluid_J_per_m", b.work_on_fluid}};
    j["stopped_at_s"] = b.stopped_at ? nlohmann::json(*b.stopped_at) : nlohmann::json(nullptr);
    out.push_back(j);
  }
  return out;
}

}  // namespace

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
  j["steps"] = r.summary.total_steps;  // from t = 0, the steps before a --resume included
  j["simulated_time_s"] = r.summary.simulated_time;
  j["wall_s"] = r.summary.wall_seconds;
  j["fluid_mass_kg_per_m"] = {{"start", r.fluid_mass_start}, {"end", r.fluid_mass_end}};
  j["fluid_removed"] = {{"particles", r.fluid_removed}, {"mass_kg_per_m", r.fluid_mass_removed}};
  j["front_x_m"] = r.front_x;
  if (!r.bodies.empty()) {
    j["bodies"] = bodies_json(r);
    double work = 0;
    for (const BodyRecord& b : r.bodies) work += b.work_on_fluid;
    const double gain = r.fluid_energy_end - r.fluid_energy_start;
    j["energy_J_per_m"] = {{"fluid_start", r.fluid_energy_start},
                           {"fluid_end", r.fluid_energy_end},
                           {"fluid_gain", gain},
                           {"work_by_bodies_on_fluid", work},
                           {"gain_over_work", work != 0 ? nlohmann::json(gain / work) : nlohmann::json(nullptr)}};
  }
  j["max_density_error"] = r.max_density_error;
  j["mean_density_error"] = r.mean_density_error;
  j["largest_time_step_s"] = r.largest_time_step;
  j["wall_contacts"] = r.wall_contacts;
  j["fluid_past_walls"] = {{"end", r.past_walls_end}, {"most", r.past_walls_most}};
  if (r.past_walls_first_time) j["fluid_past_walls"]["first_at_s"] = *r.past_walls_first_time;
  if (r.still_tank) j["still_tank"] = still_tank_json(*r.still_tank);
  if (r.front_errors) j["front_error"] = front_error_json(*r.front_errors);
  if (r.ritter) j["ritter"] = ritter_json(*r.ritter);
  if (r.waves) j["waves"] = waves_json(*r.waves);
  j["warnings"] = r.warnings;
  j["figures"] = r.figures;
  j["frames_written"] = r.summary.frames_written;
  nlohmann::json columns = nlohmann::json::array({"time_s"});
  for (const std::string& c : r.monitors.columns) columns.push_back(c);
  j["monitors"] = {{"file", "monitors.csv"}, {"columns", columns}, {"rows", r.monitors.times.size()}};
  return j;
}

nlohmann::json isph_error_report(const std::string& error) { return {{"status", "failed"}, {"error", error}}; }

}  // namespace coupling
