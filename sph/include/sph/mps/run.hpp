#pragma once
// Runs a WC-MPS model to its end time through the engine's run loop (frames, energy history, checkpoints,
// progress, blow-up guard, observers). To resume, call read_checkpoint(path, model) first, then run() again.
#include <functional>
#include <string>

#include "sph/engine/run_loop.hpp"
#include "sph/mps/model.hpp"
#include "sph/mps/stepper.hpp"

namespace sph::mps {

// Called after every healthy step with the stepper and the run state (never stops the run).
using StepWatcher = std::function<void(const Step&, const RunState&)>;

RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks = {},
               const StepWatcher& watcher = {});

void write_checkpoint(const std::string& path, const Model& model);
// Throws std::runtime_error when the checkpoint belongs to another model.
void read_checkpoint(const std::string& path, Model& model);

}  // namespace sph::mps
