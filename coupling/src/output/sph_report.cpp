#include "coupling/output/sph_report.hpp"

#include "coupling/output/json_values.hpp"

namespace coupling {

namespace {

void write_model(const SphModelFacts& f, nlohmann::json& report) {
  report["particles"] = f.particles;
  report["soil_particles"] = f.soil_particles;
  report["wall_particles"] = f.wall_particles;
  report["particle_spacing_m"] = f.particle_spacing_m;
  report["smoothing_length_m"] = f.smoothing_length_m;
  report["kernel"] = sphslope::name_of(sph::kernel_names, f.kernel);
  report["kernel_gradient"] = sphslope::name_of(sph::soil::kernel_gradient_names, f.kernel_gradient);
  report["stress_substeps"] = f.stress_substeps;
  report["p_wave_speed_m_s"] = f.p_wave_speed_m_s;
  report["time_step_estimate_s"] = f.time_step_estimate_s;
  report["planned_steps"] = f.planned_steps;
  report["gravity"] = sphslope::name_of(sph::gravity_mode_names, f.gravity);
  if (f.gravity == sph::GravityMode::ramped) report["gravity_ramp_s"] = f.gravity_ramp_s;
  report["wall_layers"] = f.wall_layers;
  report["memory_estimate_MiB"] = f.memory_estimate_MiB;
  report["loads"] = f.loads;
}

void write_summary(const sph::RunSummary& summary, nlohmann::json& report) {
  report["steps"] = summary.total_steps;
  report["steps_this_session"] = summary.steps;
  report["simulated_time_s"] = summary.simulated_time;
  report["seconds"] = summary.wall_seconds;
  report["particle_steps_per_second"] = summary.particle_steps_per_second;
  report["stopped_because"] = summary.stopped_because;
  report["frames"] = summary.frames_written;
}

void write_energies(const SphStageResult& r, nlohmann::json& report) {
  if (r.energies_finite) {
    report["final_energy_J_m"] = {{"kinetic", r.summary.kinetic_energy},
                                  {"potential", r.summary.potential_energy},
                                  {"plastic_dissipation", r.summary.plastic_dissipation}};
  } else {
    report["final_energy_J_m"] = nullptr;  // diverged state (blow-up): see "error"
  }
  if (r.energy_balance) {
    report["energy_balance"] = {{"released_potential_J_m", r.energy_balance->released_potential_J_m},
                                {"kinetic_plus_plastic_J_m", r.energy_balance->kinetic_plus_plastic_J_m},
                                {"ratio", r.energy_balance->ratio}};
  }
  report["warnings"] = r.warnings;
}

nlohmann::json deposit_json(const SphDeposit& d) {
  return {{"initial_length_m", d.initial_length_m},
          {"initial_height_m", d.initial_height_m},
          {"final_length_m", d.final_length_m},
          {"final_height_m", d.final_height_m},
          {"runout_ratio", (d.final_length_m - d.initial_length_m) / d.initial_length_m},
          {"final_height_ratio", d.final_height_m / d.initial_height_m},
          {"note",
           "lengths from the leftmost initial particle edge to the front of the deposit (stray particles "
           "beyond a 1.5-spacing gap excluded); heights from the lowest initial particle edge to the top"}};
}

}  // namespace

nlohmann::json sph_report(const SphStageResult& result) {
  nlohmann::json report = nlohmann::json::object();
  write_model(result.model, report);
  write_summary(result.summary, report);
  write_energies(result, report);
  if (result.files_written)
    report["files"] = {{"frames", "frames.pvd"}, {"energy_history", "energy.csv"}, {"checkpoint", "checkpoint.bin"}};
  if (!result.ok) report["error"] = result.error;
  report["max_displacement_m"] = optional_number(result.max_displacement_m);
  report["max_plastic_strain"] = optional_number(result.max_plastic_strain);
  if (result.deposit) report["deposit"] = deposit_json(*result.deposit);
  return report;
}

nlohmann::json sph_error_report(const std::string& message) {
  return {{"error", message}, {"stopped_because", "error"}};
}

}  // namespace coupling
