#pragma once
// A coupled run's model: the soil (sph/soil) and the water (sph/fluid) in one domain, run through the engine's run
// loop with the coupled step (coupled_step.hpp), and their checkpoint. To resume, call read_checkpoint(path, model)
// first, then run() again with the same options.
//
// The run's clock is the water's (water.state): its frames, energy rows and step counter. Observers see the water's
// particle set (the soil's twins in it are walls). Frames hold both phases, with a point array "phase": 0 soil,
// 1 water, 2 the walls (the soil's wall particles; the water's, at the same places, and the twins are left out).
//
// Checkpoint layout: "SPHSLOPE-COUPLED" (16 bytes) | u64 n | the soil's checkpoint (n bytes, the engine's format,
// sph/engine/checkpoint.hpp) | u64 m | the water's (m bytes), written with sph::write_file_atomically, so that both
// phases are always of the same step.
#include <functional>
#include <string>

#include "sph/coupled/coupled_step.hpp"
#include "sph/engine/run_loop.hpp"
#include "sph/fluid/model.hpp"
#include "sph/soil/model.hpp"

namespace sph::coupled {

struct Model {
  Model(soil::Model soil_model, fluid::Model water_model)
      : soil(std::move(soil_model)), water(std::move(water_model)) {}
  soil::Model soil;
  fluid::Model water;
};

// The frame's "phase" values.
enum class Phase : int { soil = 0, water = 1, wall = 2 };

// Called after every step with the coupled step (its sub-steps, the water's solver diagnostics).
using StepWatcher = std::function<void(const CoupledStep&, const RunState&)>;

// Runs the model to the water's settings' end time. The water's settings give the output interval, the soil's the
// wall-clock checkpoint interval; the blow-up guard's floor is the sum of the two phases' floors.
RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks = {},
               const StepWatcher& watcher = {});

void write_checkpoint(const std::string& path, const Model& model);
// Adds the soil's twins to the water first when it has none (as the coupled step does). Throws std::runtime_error
// when the file is not a coupled checkpoint, is truncated, or either phase's part belongs to another model.
void read_checkpoint(const std::string& path, Model& model);

// A frame with both phases (the layout above).
void write_frame(const std::string& path, const Model& model, const CoupledStep& step, double time);

}  // namespace sph::coupled
