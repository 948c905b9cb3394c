#include "sph/fluid/run.hpp"

#include "sph/engine/checkpoint.hpp"

namespace sph::fluid {

namespace {

CheckpointFingerprint fingerprint(const Model& model) {
  CheckpointFingerprint f;
  f.materials = 1;
  f.particle_spacing = model.settings.particle_spacing;
  f.h_over_dx = model.settings.h_over_dx;
  f.particles_may_leave = true;  // fluid that leaves the domain is removed (docs/isph.md D11)
  return f;
}

}  // namespace

RunSummary run(Model& model, const RunOptions& options, const RunCallbacks& callbacks, const StepWatcher& watcher) {
  Step stepper(model);
  RunTarget target = run_target(model.particles, model.state, stepper, model.settings);
  target.write_checkpoint = [&model](const std::string& path) { write_checkpoint(path, model); };
  RunCallbacks cb = callbacks;
  WatchObserver<Step> watch(stepper, watcher);
  if (watcher) cb.observers.insert(cb.observers.begin(), &watch);
  return run_loop(target, options, cb);
}

void write_checkpoint(const std::string& path, const Model& model) {
  sph::write_checkpoint(path, model.particles, model.state, fingerprint(model));
}

void read_checkpoint(const std::string& path, Model& model) {
  sph::read_checkpoint(path, model.particles, model.state, fingerprint(model));
}

}  // namespace sph::fluid
