#include "sph/integrator/run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "sph/atomic_file.hpp"
#include "sph/checkpoint.hpp"
#include "sph/soil_step.hpp"
#include "sph/vtk_output.hpp"

namespace sph {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string frame_name(std::uint64_t k) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "frames/frame_%06llu.vtu", static_cast<unsigned long long>(k));
  return buf;
}

const char* kEnergyHeader = "time_s,kinetic_J_m,potential_J_m,plastic_dissipation_J_m,max_speed_m_s\n";

// The first `bytes` bytes of a file (the part of the energy history that belongs to a resumed state).
std::string read_prefix(const std::string& path, std::uint64_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(bytes), '\0');
  in.read(text.data(), static_cast<std::streamsize>(bytes));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

}  // namespace

RunSummary run(Model& model, const RunOptions& opt, const RunCallbacks& cb) {
  const auto t_start = Clock::now();
  SoilStep stepper(model);
  RunState& rs = model.state;
  const Settings& st = model.settings;
  const bool files = !opt.output_dir.empty();
  const std::string ckpt_path =
      !opt.checkpoint_path.empty() ? opt.checkpoint_path : (files ? opt.output_dir + "/checkpoint.bin" : "");
  const std::string energy_path = files ? opt.output_dir + "/energy.csv" : "";
  if (files) {
    fs::create_directories(opt.output_dir);
    if (opt.write_frames) fs::create_directories(opt.output_dir + "/frames");
  }
  const bool fresh = rs.step == 0 && !rs.rates_valid;
  stepper.initialise();
  if (fresh) {
    rs.initial_potential_energy = stepper.energies().potential;
    rs.next_output_time = 0.0;
    rs.frames_written = 0;
    rs.frame_times.clear();
    rs.energy_csv_bytes = 0;
  }
  // energy history: start fresh or cut back to what belongs to the resumed state; the whole file is rewritten
  // through the durable writer at each output (a few hundred rows at most)
  std::string energy_text;
  if (files && opt.write_energy) {
    if (!fresh && fs::exists(energy_path)) energy_text = read_prefix(energy_path, rs.energy_csv_bytes);
    if (energy_text.empty()) energy_text = kEnergyHeader;
    write_file_atomically(energy_path, energy_text);
    rs.energy_csv_bytes = energy_text.size();
  }
  // Floor for the kinetic-energy runaway test: 1 % of (soil weight x soil height range).
  double energy_floor = 0;
  {
    const Particles& p = model.particles;
    double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin, weight = 0;
    const double g = std::hypot(st.gravity_x, st.gravity_y);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == 0) {
        ymin = std::min(ymin, p.y[i]);
        ymax = std::max(ymax, p.y[i]);
        weight += p.mass[i] * g;
      }
    energy_floor = 0.01 * weight * std::max(ymax - ymin, st.particle_spacing);
  }

  RunSummary sum;
  sum.particles = model.particles.size();
  sum.soil_particles = model.particles.count(ParticleKind::soil);
  std::vector<std::pair<double, std::string>> pvd;
  for (std::uint64_t k = 0; k < rs.frame_times.size(); ++k) pvd.emplace_back(rs.frame_times[k], frame_name(k).substr(0));

  auto write_output = [&](const Energies& e) {
    if (!files) return;
    if (opt.write_frames) {
      const std::string name = frame_name(rs.frames_written);
      write_vtu(opt.output_dir + "/" + name, model.particles, rs.time);
      rs.frame_times.push_back(rs.time);
      pvd.emplace_back(rs.time, name);
      write_pvd(opt.output_dir + "/frames.pvd", pvd);
    }
    rs.frames_written += 1;
    if (opt.write_energy) {
      char line[256];
      std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g\n", rs.time, e.kinetic, e.potential,
                    e.plastic_dissipation, e.max_speed);
      energy_text += line;
      write_file_atomically(energy_path, energy_text);
      rs.energy_csv_bytes = energy_text.size();
    }
  };
  auto maybe_output = [&](bool force) {
    if (st.output_interval <= 0 && !force) return;
    if (force || rs.time >= rs.next_output_time - 1e-12 * std::max(1.0, st.end_time)) {
      write_output(stepper.energies());
      if (st.output_interval > 0)
        while (rs.next_output_time <= rs.time + 1e-12 * std::max(1.0, st.end_time)) rs.next_output_time += st.output_interval;
    }
  };

  maybe_output(false);  // frame at t = 0 (fresh run) or nothing (resume: already written)

  auto last_ckpt = Clock::now();
  auto last_progress = Clock::now();
  std::uint64_t progress_step0 = rs.step;
  double progress_time0 = rs.time;
  const std::uint64_t step_at_start = rs.step;
  double last_dt = 0;
  const double end_tol = 1e-12 * std::max(1.0, st.end_time);
  std::string reason;

  while (true) {
    if (rs.time >= st.end_time - end_tol) { reason = "end_time"; break; }
    if (opt.max_steps > 0 && rs.step >= opt.max_steps) { reason = "step_limit"; break; }
    if (cb.interrupt && cb.interrupt()) { reason = "interrupted"; break; }
    double dt = stepper.stable_time_step();
    if (rs.time + dt > st.end_time) dt = st.end_time - rs.time;
    last_dt = dt;
    stepper.advance(dt);

    const Health health = stepper.check_health();
    Energies e;
    bool blown = !health.ok;
    std::string diag = health.diagnostic;
    if (!blown) {
      e = stepper.energies();
      const double released = std::max(rs.initial_potential_energy - e.potential, 0.0);
      if (!std::isfinite(e.kinetic) || e.kinetic > st.blow_up_energy_factor * (released + energy_floor)) {
        blown = true;
        std::ostringstream os;
        os << "blow-up at step " << rs.step << " (t = " << rs.time << " s): field kinetic_energy " << e.kinetic
           << " J/m exceeds " << st.blow_up_energy_factor << " x (released potential energy " << released
           << " + floor " << energy_floor << ") J/m; max speed " << e.max_speed << " m/s";
        diag = os.str();
      }
    }
    if (blown) {
      reason = "blow_up";
      sum.diagnostic = diag;
      break;  // last good frame and checkpoint are kept as they are
    }
    maybe_output(false);
    if (opt.quasi_static_speed > 0 && rs.time >= opt.quasi_static_min_time && e.max_speed < opt.quasi_static_speed) {
      reason = "quasi_static";
      break;
    }
    if (!ckpt_path.empty() && st.checkpoint_interval_wall_s > 0 &&
        seconds_since(last_ckpt) >= st.checkpoint_interval_wall_s) {
      write_checkpoint(ckpt_path, model);
      last_ckpt = Clock::now();
    }
    if (cb.progress && seconds_since(last_progress) >= opt.progress_interval_wall_s) {
      const double wall = seconds_since(last_progress);
      Progress pr;
      pr.time = rs.time;
      pr.end_time = st.end_time;
      pr.step = rs.step;
      pr.steps_per_second = static_cast<double>(rs.step - progress_step0) / wall;
      const double sim_rate = (rs.time - progress_time0) / wall;
      pr.eta_seconds = sim_rate > 0 ? (st.end_time - rs.time) / sim_rate : std::numeric_limits<double>::infinity();
      pr.max_speed = e.max_speed;
      pr.time_step = dt;
      cb.progress(pr);
      last_progress = Clock::now();
      progress_step0 = rs.step;
      progress_time0 = rs.time;
    }
  }
  (void)last_dt;

  if (reason != "blow_up") {
    // final frame if the last one is older than the final state
    if (files && (rs.frame_times.empty() || rs.frame_times.back() < rs.time) && reason == "end_time")
      maybe_output(true);
    if (!ckpt_path.empty() && opt.checkpoint_on_stop) write_checkpoint(ckpt_path, model);
  }
  const Energies e = stepper.energies();
  sum.stopped_because = reason;
  sum.steps = rs.step - step_at_start;
  sum.total_steps = rs.step;
  sum.simulated_time = rs.time;
  sum.wall_seconds = seconds_since(t_start);
  sum.particle_steps_per_second =
      sum.wall_seconds > 0 ? static_cast<double>(sum.soil_particles) * static_cast<double>(sum.steps) / sum.wall_seconds : 0;
  sum.frames_written = rs.frames_written;
  sum.kinetic_energy = e.kinetic;
  sum.potential_energy = e.potential;
  sum.plastic_dissipation = e.plastic_dissipation;
  return sum;
}

}  // namespace sph
