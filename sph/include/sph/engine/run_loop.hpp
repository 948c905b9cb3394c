#pragma once
// One run loop for every physics: runs a Stepper to its end time with output frames, the energy history,
// checkpoints, progress, the blow-up guard and observers (stop criteria, monitors). To resume, read the
// checkpoint into the particle set and RunState first, then run again with the same options.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sph/engine/settings.hpp"
#include "sph/engine/stepper.hpp"

namespace sph {

// Why a run stopped (report key in parentheses).
enum class StopReason {
  end_time,      // "end_time": reached the end time
  blow_up,       // "blow_up": the health guard or the kinetic-energy test stopped it
  interrupted,   // "interrupted": RunCallbacks::interrupt asked for it (Ctrl-C); a checkpoint is written
  quasi_static,  // "quasi_static": every particle slower than the rest speed after the minimum time
  step_limit,    // "step_limit": RunOptions::max_steps reached
  observer,      // an observer's own reason (RunSummary::stopped_because holds its key)
};
const char* stop_reason_key(StopReason reason);

struct Progress {
  double time = 0, end_time = 0;  // simulated [s]
  std::uint64_t step = 0;
  double steps_per_second = 0;    // wall-clock rate over the last progress interval
  double eta_seconds = 0;         // estimated wall time left
  double max_speed = 0;           // [m/s]
  double time_step = 0;           // [s]
};

struct RunOptions {
  std::string output_dir;            // empty: no files at all
  bool write_frames = true;          // output_dir/frames/frame_NNNNNN.vtu + output_dir/frames.pvd
  bool write_energy = true;          // output_dir/energy.csv
  std::string checkpoint_path;       // empty: output_dir/checkpoint.bin (none if output_dir is empty)
  // OpenMP threads: one per this many particles, at most what OpenMP offers (OMP_NUM_THREADS). A small run on
  // more threads pays a fork and join per loop for little work, and on a machine whose other cores are busy its
  // waiting threads slow it down many times over (docs/performance.md).
  std::size_t min_particles_per_thread = 2000;
  bool checkpoint_on_stop = true;    // also write a checkpoint when the run stops normally or is interrupted
  std::uint64_t max_steps = 0;       // stop when the step counter reaches this (0: no limit)
  double progress_interval_wall_s = 1.0;
  double quasi_static_speed = 0.0;   // stop when max speed < this after quasi_static_min_time (0: off)
  double quasi_static_min_time = 0.0;
};

// Watches the run after every step; may stop it with a reason of its own.
class Observer {
 public:
  virtual ~Observer() = default;
  // Called after every healthy step. Return a non-empty key ("displacement_limit") to stop the run.
  virtual std::string after_step(const ParticleSet& particles, const RunState& state, const Energies& energies) = 0;
};

struct RunCallbacks {
  std::function<void(const Progress&)> progress;  // called every progress_interval_wall_s
  std::function<bool()> interrupt;                // polled every step; true stops the run ("interrupted")
  std::vector<Observer*> observers;               // called after every step, in order
};

struct RunSummary {
  std::size_t particles = 0, soil_particles = 0;  // all; moving (kind 0)
  std::uint64_t steps = 0;          // steps taken in this call
  std::uint64_t total_steps = 0;    // step counter at the end
  double simulated_time = 0;        // time at the end [s]
  double wall_seconds = 0;
  double particle_steps_per_second = 0;  // moving particles x steps / wall seconds
  StopReason reason = StopReason::end_time;
  std::string stopped_because;      // stop_reason_key(reason), or the observer's key
  std::string diagnostic;           // blow-up diagnostic (particle id, field, step)
  std::uint64_t frames_written = 0;
  double kinetic_energy = 0, potential_energy = 0, plastic_dissipation = 0;  // final [J/m]
};

// What the loop needs from the physics besides the stepper.
struct RunTarget {
  RunTarget(ParticleSet& p, RunState& s, Stepper& st) : particles(p), state(s), stepper(st) {}
  ParticleSet& particles;
  RunState& state;
  Stepper& stepper;
  double end_time = 0;                    // [s]
  double output_interval = 0;             // [s] simulated time between frames / energy rows (<= 0: none)
  double checkpoint_interval_wall_s = 0;  // wall-clock seconds between checkpoints (<= 0: none)
  double blow_up_energy_factor = 10;      // stop if KE > factor * (released potential energy + energy_floor)
  double energy_floor = 0;                // [J/m]
  std::function<void(const std::string& path)> write_checkpoint;
  // Writes a frame (path, time); when empty the loop writes `particles` with the stepper's derived outputs.
  std::function<void(const std::string& path, double time)> write_frame;
};

RunSummary run_loop(RunTarget& target, const RunOptions& options, const RunCallbacks& callbacks = {});

// Floor for the kinetic-energy runaway test: 1 % of (weight of the moving particles (kind 0) x their height range,
// at least one particle spacing) [J/m].
double moving_energy_floor(const ParticleSet& particles, const EngineSettings& settings);

// Kinetic and potential energy (gravity of `settings`) and the largest speed of the moving particles (kind 0), in
// index order on one thread; no plastic dissipation (physics without a plastic material).
Energies moving_energies(const ParticleSet& particles, const EngineSettings& settings);

// The run target of a physics on the engine: end time, output and checkpoint intervals and the blow-up factor from
// its settings, the energy floor of its moving particles; the caller sets write_checkpoint.
RunTarget run_target(ParticleSet& particles, RunState& state, Stepper& stepper, const EngineSettings& settings);

// Passes a physics' stepper to a watcher after every step (never stops the run).
template <class Step>
class WatchObserver : public Observer {
 public:
  using Watcher = std::function<void(const Step&, const RunState&)>;
  WatchObserver(const Step& step, const Watcher& watcher) : step_(step), watcher_(watcher) {}
  std::string after_step(const ParticleSet&, const RunState& state, const Energies&) override {
    watcher_(step_, state);
    return {};
  }

 private:
  const Step& step_;
  const Watcher& watcher_;
};

// The run of a tank physics' model (the fluid's, the MPS's: a Model with particles, state and settings, and its
// Step) through the run loop, its checkpoints written by `write_checkpoint`, with a watcher of the stepper after
// every step (when given).
template <class Step, class Model, class WriteCheckpoint>
RunSummary run_model(Model& model, const RunOptions& options, const RunCallbacks& callbacks,
                     const typename WatchObserver<Step>::Watcher& watcher, WriteCheckpoint write_checkpoint) {
  Step stepper(model);
  RunTarget target = run_target(model.particles, model.state, stepper, model.settings);
  target.write_checkpoint = [&model, &write_checkpoint](const std::string& path) { write_checkpoint(path, model); };
  RunCallbacks cb = callbacks;
  WatchObserver<Step> watch(stepper, watcher);
  if (watcher) cb.observers.insert(cb.observers.begin(), &watch);
  return run_loop(target, options, cb);
}

}  // namespace sph
