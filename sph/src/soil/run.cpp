#include "sph/soil/run.hpp"

#include "sph/soil/checkpoint.hpp"
#include "sph/soil/soil_step.hpp"

namespace sph::soil {

RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks) {
  SoilStep stepper(model);
  RunTarget target = run_target(model.particles, model.state, stepper, model.settings);
  target.write_checkpoint = [&model](const std::string& path) { write_checkpoint(path, model); };
  return run_loop(target, options, callbacks);
}

}  // namespace sph::soil
