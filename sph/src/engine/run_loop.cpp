#include "sph/engine/run_loop.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "sph/engine/atomic_file.hpp"
#include "sph/engine/vtk_output.hpp"
#include "sphslope/wall_clock.hpp"

namespace sph {

const char* stop_reason_key(StopReason reason) {
  switch (reason) {
    case StopReason::end_time: return "end_time";
    case StopReason::blow_up: return "blow_up";
    case StopReason::interrupted: return "interrupted";
    case StopReason::quasi_static: return "quasi_static";
    case StopReason::step_limit: return "step_limit";
    case StopReason::observer: return "observer";
  }
  return "unknown";
}

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

using sphslope::seconds_since;

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

// Stops the run once every moving particle is slower than `speed` after `min_time` (a slope at rest).
class QuasiStaticStop : public Observer {
 public:
  QuasiStaticStop(double speed, double min_time) : speed_(speed), min_time_(min_time) {}
  std::string after_step(const ParticleSet&, const RunState& state, const Energies& e) override {
    return state.time >= min_time_ && e.max_speed < speed_ ? "quasi_static" : "";
  }

 private:
  double speed_, min_time_;
};

// The loop's state between steps: files, the energy history, the wall clocks of checkpoints and progress.
class Loop {
 public:
  Loop(RunTarget& t, const RunOptions& o, const RunCallbacks& cb) : t_(t), o_(o), cb_(cb) {
    files_ = !o.output_dir.empty();
    ckpt_path_ = !o.checkpoint_path.empty() ? o.checkpoint_path : (files_ ? o.output_dir + "/checkpoint.bin" : "");
    energy_path_ = files_ ? o.output_dir + "/energy.csv" : "";
    if (o.quasi_static_speed > 0) quasi_static_.emplace(o.quasi_static_speed, o.quasi_static_min_time);
  }

  RunSummary run() {
    const auto t_start = Clock::now();
    start();
    maybe_output(false);  // frame at t = 0 (fresh run) or nothing (resume: already written)
    const std::uint64_t step_at_start = t_.state.step;
    while (!stopped_ && !stop_before_step()) step();
    finish();
    return summary(step_at_start, seconds_since(t_start));
  }

 private:
  void start() {
    RunState& rs = t_.state;
    if (files_) {
      fs::create_directories(o_.output_dir);
      if (o_.write_frames) fs::create_directories(o_.output_dir + "/frames");
    }
    const bool fresh = rs.step == 0 && !rs.rates_valid;
    t_.stepper.initialise();
    if (fresh) {
      rs.initial_potential_energy = t_.stepper.energies().potential;
      rs.next_output_time = 0.0;
      rs.frames_written = 0;
      rs.frame_times.clear();
      rs.energy_csv_bytes = 0;
    }
    // energy history: start fresh or cut back to what belongs to the resumed state; the whole file is rewritten
    // through the durable writer at each output (a few hundred rows at most)
    if (files_ && o_.write_energy) {
      if (!fresh && fs::exists(energy_path_)) energy_text_ = read_prefix(energy_path_, rs.energy_csv_bytes);
      if (energy_text_.empty()) energy_text_ = kEnergyHeader;
      write_file_atomically(energy_path_, energy_text_);
      rs.energy_csv_bytes = energy_text_.size();
    }
    for (std::uint64_t k = 0; k < rs.frame_times.size(); ++k) pvd_.emplace_back(rs.frame_times[k], frame_name(k));
    last_ckpt_ = last_progress_ = Clock::now();
    progress_step0_ = rs.step;
    progress_time0_ = rs.time;
  }

  // End time, step limit or an interruption, checked before every step.
  bool stop_before_step() {
    const RunState& rs = t_.state;
    const double end_tol = 1e-12 * std::max(1.0, t_.end_time);
    if (rs.time >= t_.end_time - end_tol) return stop(StopReason::end_time);
    if (o_.max_steps > 0 && rs.step >= o_.max_steps) return stop(StopReason::step_limit);
    if (cb_.interrupt && cb_.interrupt()) return stop(StopReason::interrupted);
    return false;
  }

  bool stop(StopReason reason, std::string key = {}) {
    reason_ = reason;
    key_ = key.empty() ? stop_reason_key(reason) : std::move(key);
    return true;
  }

  void step() {
    RunState& rs = t_.state;
    double dt = t_.stepper.stable_time_step();
    if (rs.time + dt > t_.end_time) dt = t_.end_time - rs.time;
    t_.stepper.advance(dt);
    Energies e;
    if (blown_up(e)) return;  // last good frame and checkpoint are kept as they are
    maybe_output(false);
    if (observers_stop(e)) return;
    maybe_checkpoint();
    maybe_progress(e, dt);
  }

  // The health guard, then the kinetic-energy runaway test; fills e when healthy.
  bool blown_up(Energies& e) {
    const Health health = t_.stepper.check_health();
    if (!health.ok) {
      diagnostic_ = health.diagnostic;
      stopped_ = stop(StopReason::blow_up);
      return true;
    }
    e = t_.stepper.energies();
    const RunState& rs = t_.state;
    const double released = std::max(rs.initial_potential_energy - e.potential, 0.0);
    if (std::isfinite(e.kinetic) && !(e.kinetic > t_.blow_up_energy_factor * (released + t_.energy_floor)))
      return false;
    std::ostringstream os;
    os << "blow-up at step " << rs.step << " (t = " << rs.time << " s): field kinetic_energy " << e.kinetic
       << " J/m exceeds " << t_.blow_up_energy_factor << " x (released potential energy " << released
       << " + floor " << t_.energy_floor << ") J/m; max speed " << e.max_speed << " m/s";
    diagnostic_ = os.str();
    stopped_ = stop(StopReason::blow_up);
    return true;
  }

  bool observers_stop(const Energies& e) {
    auto ask = [&](Observer& observer) {
      std::string key = observer.after_step(t_.particles, t_.state, e);
      if (key.empty()) return false;
      stopped_ = key == "quasi_static" ? stop(StopReason::quasi_static) : stop(StopReason::observer, key);
      return true;
    };
    if (quasi_static_ && ask(*quasi_static_)) return true;
    for (Observer* observer : cb_.observers)
      if (ask(*observer)) return true;
    return false;
  }

  void write_output(const Energies& e) {
    RunState& rs = t_.state;
    if (!files_) return;
    if (o_.write_frames) {
      const std::string name = frame_name(rs.frames_written);
      if (t_.write_frame)
        t_.write_frame(o_.output_dir + "/" + name, rs.time);
      else
        write_vtu(o_.output_dir + "/" + name, t_.particles, rs.time, t_.stepper.derived_outputs());
      rs.frame_times.push_back(rs.time);
      pvd_.emplace_back(rs.time, name);
      write_pvd(o_.output_dir + "/frames.pvd", pvd_);
    }
    rs.frames_written += 1;
    if (o_.write_energy) {
      char line[256];
      std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g\n", rs.time, e.kinetic, e.potential,
                    e.plastic_dissipation, e.max_speed);
      energy_text_ += line;
      write_file_atomically(energy_path_, energy_text_);
      rs.energy_csv_bytes = energy_text_.size();
    }
  }

  void maybe_output(bool force) {
    RunState& rs = t_.state;
    if (t_.output_interval <= 0 && !force) return;
    const double tol = 1e-12 * std::max(1.0, t_.end_time);
    if (!force && rs.time < rs.next_output_time - tol) return;
    write_output(t_.stepper.energies());
    if (t_.output_interval > 0)
      while (rs.next_output_time <= rs.time + tol) rs.next_output_time += t_.output_interval;
  }

  void maybe_checkpoint() {
    if (ckpt_path_.empty() || !(t_.checkpoint_interval_wall_s > 0) ||
        seconds_since(last_ckpt_) < t_.checkpoint_interval_wall_s)
      return;
    t_.write_checkpoint(ckpt_path_);
    last_ckpt_ = Clock::now();
  }

  void maybe_progress(const Energies& e, double dt) {
    if (!cb_.progress || seconds_since(last_progress_) < o_.progress_interval_wall_s) return;
    const RunState& rs = t_.state;
    const double wall = seconds_since(last_progress_);
    Progress pr;
    pr.time = rs.time;
    pr.end_time = t_.end_time;
    pr.step = rs.step;
    pr.steps_per_second = static_cast<double>(rs.step - progress_step0_) / wall;
    const double sim_rate = (rs.time - progress_time0_) / wall;
    pr.eta_seconds = sim_rate > 0 ? (t_.end_time - rs.time) / sim_rate : std::numeric_limits<double>::infinity();
    pr.max_speed = e.max_speed;
    pr.time_step = dt;
    cb_.progress(pr);
    last_progress_ = Clock::now();
    progress_step0_ = rs.step;
    progress_time0_ = rs.time;
  }

  // A final frame if the last one is older than the final state, and the checkpoint (not after a blow-up).
  void finish() {
    if (reason_ == StopReason::blow_up) return;
    const RunState& rs = t_.state;
    if (files_ && (rs.frame_times.empty() || rs.frame_times.back() < rs.time) && reason_ == StopReason::end_time)
      maybe_output(true);
    if (!ckpt_path_.empty() && o_.checkpoint_on_stop) t_.write_checkpoint(ckpt_path_);
  }

  RunSummary summary(std::uint64_t step_at_start, double wall_seconds) const {
    const RunState& rs = t_.state;
    const Energies e = t_.stepper.energies();
    RunSummary sum;
    sum.particles = t_.particles.size();
    sum.soil_particles = t_.particles.count(ParticleKind::material);
    sum.reason = reason_;
    sum.stopped_because = key_;
    sum.diagnostic = diagnostic_;
    sum.steps = rs.step - step_at_start;
    sum.total_steps = rs.step;
    sum.simulated_time = rs.time;
    sum.wall_seconds = wall_seconds;
    sum.particle_steps_per_second =
        wall_seconds > 0 ? static_cast<double>(sum.soil_particles) * static_cast<double>(sum.steps) / wall_seconds : 0;
    sum.frames_written = rs.frames_written;
    sum.kinetic_energy = e.kinetic;
    sum.potential_energy = e.potential;
    sum.plastic_dissipation = e.plastic_dissipation;
    return sum;
  }

  RunTarget& t_;
  const RunOptions& o_;
  const RunCallbacks& cb_;
  bool files_ = false;
  std::string ckpt_path_, energy_path_, energy_text_;
  std::vector<std::pair<double, std::string>> pvd_;
  std::optional<QuasiStaticStop> quasi_static_;
  Clock::time_point last_ckpt_, last_progress_;
  std::uint64_t progress_step0_ = 0;
  double progress_time0_ = 0;
  StopReason reason_ = StopReason::end_time;
  std::string key_ = "end_time", diagnostic_;
  bool stopped_ = false;
};

}  // namespace

namespace {

// Sets the OpenMP thread count for one run and restores it afterwards. The results do not depend on it (the
// parallel loops gather per particle and reduce only by min and max).
class ThreadBudget {
 public:
  ThreadBudget(std::size_t particles, std::size_t min_particles_per_thread) {
#ifdef _OPENMP
    previous_ = omp_get_max_threads();
    const std::size_t per_thread = std::max<std::size_t>(min_particles_per_thread, 1);
    const std::size_t wanted = std::max<std::size_t>(particles / per_thread, 1);
    omp_set_num_threads(static_cast<int>(std::min<std::size_t>(wanted, static_cast<std::size_t>(previous_))));
#else
    (void)particles;
    (void)min_particles_per_thread;
#endif
  }
  ~ThreadBudget() {
#ifdef _OPENMP
    omp_set_num_threads(previous_);
#endif
  }
  ThreadBudget(const ThreadBudget&) = delete;
  ThreadBudget& operator=(const ThreadBudget&) = delete;

 private:
  int previous_ = 1;
};

}  // namespace

RunSummary run_loop(RunTarget& target, const RunOptions& options, const RunCallbacks& callbacks) {
  const ThreadBudget threads(target.particles.size(), options.min_particles_per_thread);
  Loop loop(target, options, callbacks);
  return loop.run();
}

double moving_energy_floor(const ParticleSet& p, const EngineSettings& st) {
  double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == static_cast<std::uint8_t>(ParticleKind::material)) {
      ymin = std::min(ymin, p.y[i]);
      ymax = std::max(ymax, p.y[i]);
    }
  const double g = std::hypot(st.gravity_x, st.gravity_y);
  return 0.01 * p.total_mass(ParticleKind::material) * g * std::max(ymax - ymin, st.particle_spacing);
}

Energies moving_energies(const ParticleSet& p, const EngineSettings& st) {
  Energies e;
  double v2_max = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != static_cast<std::uint8_t>(ParticleKind::material)) continue;
    const double v2 = p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i];
    e.kinetic += 0.5 * p.mass[i] * v2;
    e.potential -= p.mass[i] * (st.gravity_x * p.x[i] + st.gravity_y * p.y[i]);
    v2_max = std::max(v2_max, v2);
  }
  e.max_speed = std::sqrt(v2_max);
  return e;
}

RunTarget run_target(ParticleSet& particles, RunState& state, Stepper& stepper, const EngineSettings& st) {
  RunTarget target(particles, state, stepper);
  target.end_time = st.end_time;
  target.output_interval = st.output_interval;
  target.checkpoint_interval_wall_s = st.checkpoint_interval_wall_s;
  target.blow_up_energy_factor = st.blow_up_energy_factor;
  target.energy_floor = moving_energy_floor(particles, st);
  return target;
}

}  // namespace sph
