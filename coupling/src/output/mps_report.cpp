// The "mps" block of report.json (coupling/output/mps_report.hpp).
#include "coupling/output/mps_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include "coupling/output/svg.hpp"

namespace coupling {

namespace {
nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
}  // namespace

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
  j["steps"] = r.summary.total_steps;  // from t = 0, the steps before a --resume included
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
  j["pore_pressure"] = r.pore_pressure;
  j["phases"] = nlohmann::json::array();
  for (const MpsStageResult::Phase& p : r.phases)
    j["phases"].push_back({{"material", p.name},
                           {"density_kg_m3", p.density},
                           {"mass_in_tank_kg_per_m", {{"start", p.mass_start}, {"end", p.mass_end}}}});
  if (!r.profiles.empty()) {
    nlohmann::json times = nlohmann::json::array();
    for (const Profile& p : r.profiles) times.push_back(p.time);
    j["profiles"] = {{"file", "profiles.csv"}, {"figure", "profiles.svg"}, {"times_s", times}};
  }
  if (r.dam_x) {
    nlohmann::json rows = nlohmann::json::array();
    for (const DamBreakFigures& f : r.dam_break)
      rows.push_back({{"time_s", f.time},
                      {"front_x_m", f.front_x},
                      {"ritter_front_x_m", f.ritter_front_x},
                      {"level_ahead_m", finite_or_null(f.level_ahead)},
                      {"depth_ahead_m", finite_or_null(f.depth_ahead)},
                      {"negative_wave_x_m", finite_or_null(f.negative_wave_x)},
                      {"ritter_negative_wave_x_m", finite_or_null(f.ritter_negative_wave_x)},
                      {"bed_at_dam_m", f.bed_at_dam},
                      {"scour_m", f.bed_at_dam_start - f.bed_at_dam}});
    const double depth = r.dam_break.empty() ? 0.0 : r.dam_break.front().depth;
    j["dam_break"] = {{"dam_x_m", *r.dam_x}, {"water_depth_m", depth}, {"at", rows}};
  }
  return j;
}

nlohmann::json mps_error_report(const std::string& error) { return {{"status", "failed"}, {"error", error}}; }

std::string profiles_csv(const std::vector<Profile>& profiles) {
  std::ostringstream os;
  os.precision(10);
  os << "time_s,x_m,surface_m,bed_m\n";
  for (const Profile& p : profiles)
    for (std::size_t k = 0; k < p.x.size(); ++k)
      os << p.time << ',' << p.x[k] << ',' << p.surface[k] << ',' << p.bed[k] << '\n';
  return os.str();
}

std::string profiles_svg(const std::vector<Profile>& profiles, const Tank& tank, const std::string& title,
                         std::optional<double> dam_x) {
  double top = tank.y_min;
  for (const Profile& p : profiles)
    for (const double s : p.surface) top = std::max(top, s);
  top = tank.y_min + 1.1 * (top - tank.y_min);
  const double exaggeration = std::max(1.0, std::floor(0.35 * (tank.x_max - tank.x_min) / (top - tank.y_min)));
  SvgCanvas canvas(tank.x_min, tank.x_max, tank.y_min, top, 900.0, exaggeration);
  canvas.title(title);
  std::ostringstream ylabel;
  ylabel << "y (m), drawn " << exaggeration << "x";
  canvas.axes("x (m)", ylabel.str());
  if (dam_x) {
    canvas.polyline({{*dam_x, tank.y_min}, {*dam_x, top}}, "#999", 1.0, "2,3");
  }
  std::vector<std::tuple<std::string, std::string, std::string>> legend;
  for (std::size_t k = 0; k < profiles.size(); ++k) {
    const Profile& p = profiles[k];
    const double t = profiles.size() > 1 ? static_cast<double>(k) / static_cast<double>(profiles.size() - 1) : 0.0;
    const std::string colour = to_hex(colour_map(0.85 * t));
    std::vector<slope::Point> surface, bed;
    for (std::size_t b = 0; b < p.x.size(); ++b) {
      surface.push_back({p.x[b], p.surface[b]});
      bed.push_back({p.x[b], p.bed[b]});
    }
    canvas.polyline(surface, colour, 1.6);
    canvas.polyline(bed, colour, 1.6, "6,3");
    std::ostringstream label;
    label.precision(3);
    label << "t = " << p.time << " s";
    legend.emplace_back(colour, "", label.str());
  }
  legend.emplace_back("#444", "", "surface (solid)");
  legend.emplace_back("#444", "6,3", "bed: top of the grains (dashed)");
  if (dam_x) legend.emplace_back("#999", "2,3", "the dam at t = 0");
  canvas.legend(legend);
  return canvas.str();
}

}  // namespace coupling
