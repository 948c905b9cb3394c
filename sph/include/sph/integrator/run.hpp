#pragma once
// Runs a model to its end time: time loop, output frames, energy history, checkpoints, progress,
// blow-up guard. To resume, call read_checkpoint(path, model) first, then run() with the same options.
#include <cstdint>
#include <functional>
#include <string>

#include "sph/model.hpp"

namespace sph {

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
  bool checkpoint_on_stop = true;    // also write a checkpoint when the run stops normally or is interrupted
  std::uint64_t max_steps = 0;       // stop when the model's step counter reaches this (0: no limit)
  double progress_interval_wall_s = 1.0;
  double quasi_static_speed = 0.0;   // stop when max speed < this after quasi_static_min_time (0: off)
  double quasi_static_min_time = 0.0;
};

struct RunCallbacks {
  std::function<void(const Progress&)> progress;  // called every progress_interval_wall_s
  std::function<bool()> interrupt;                // polled every step; true stops the run ("interrupted")
};

struct RunSummary {
  std::size_t particles = 0, soil_particles = 0;
  std::uint64_t steps = 0;          // steps taken in this call
  std::uint64_t total_steps = 0;    // model step counter at the end
  double simulated_time = 0;        // model time at the end [s]
  double wall_seconds = 0;
  double particle_steps_per_second = 0;  // soil particles x steps / wall seconds
  std::string stopped_because;      // "end_time" | "blow_up" | "interrupted" | "quasi_static" | "step_limit"
  std::string diagnostic;           // blow-up diagnostic (particle id, field, step)
  std::uint64_t frames_written = 0;
  double kinetic_energy = 0, potential_energy = 0, plastic_dissipation = 0;  // final [J/m]
};

RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks = {});

}  // namespace sph
