#pragma once
// Runs a soil model to its end time through the engine's run loop (sph/engine/run_loop.hpp: frames, energy
// history, checkpoints, progress, blow-up guard, observers). To resume, call read_checkpoint(path, model) first,
// then run() with the same options.
#include "sph/engine/run_loop.hpp"
#include "sph/soil/model.hpp"

namespace sph::soil {

RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks = {});

}  // namespace sph::soil
