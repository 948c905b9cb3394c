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
  return run_model<Step>(model, options, callbacks, watcher,
                         [](const std::string& path, const Model& m) { write_checkpoint(path, m); });
}

void write_checkpoint(const std::string& path, const Model& model) {
  sph::write_checkpoint(path, model.particles, model.state, fingerprint(model));
}

void read_checkpoint(const std::string& path, Model& model) {
  sph::read_checkpoint(path, model.particles, model.state, fingerprint(model));
}

std::string checkpoint_bytes(const Model& model) {
  return sph::checkpoint_bytes(model.particles, model.state, fingerprint(model));
}

void restore_checkpoint(const std::string& bytes, const std::string& path, Model& model) {
  sph::restore_checkpoint(bytes, path, model.particles, model.state, fingerprint(model));
}

}  // namespace sph::fluid
