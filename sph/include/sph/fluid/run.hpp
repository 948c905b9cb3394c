#pragma once
// Runs an ISPH fluid model to its end time through the engine's run loop (frames, energy history, checkpoints,
// progress, blow-up guard, observers). To resume, call read_checkpoint(path, model) first, then run() again.
#include <string>

#include "sph/engine/run_loop.hpp"
#include "sph/fluid/model.hpp"
#include "sph/fluid/stepper.hpp"

namespace sph::fluid {

// Called after every step with the stepper (its diagnostics: solver iterations, density error).
using StepWatcher = std::function<void(const Step&, const RunState&)>;

RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks = {},
               const StepWatcher& watcher = {});

void write_checkpoint(const std::string& path, const Model& model);
// Throws std::runtime_error when the checkpoint belongs to another model.
void read_checkpoint(const std::string& path, Model& model);
// The same in memory (a coupled run's checkpoint holds the soil and the water, sph/coupled/model.hpp).
std::string checkpoint_bytes(const Model& model);
void restore_checkpoint(const std::string& bytes, const std::string& path, Model& model);

}  // namespace sph::fluid
