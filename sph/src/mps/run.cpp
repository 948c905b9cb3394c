#include "sph/mps/run.hpp"

#include "sph/engine/checkpoint.hpp"

namespace sph::mps {

namespace {

CheckpointFingerprint fingerprint(const Model& model) {
  CheckpointFingerprint f;
  f.materials = static_cast<std::uint32_t>(model.materials.size());
  f.particle_spacing = model.settings.particle_spacing;
  f.h_over_dx = model.settings.re_over_dx;  // the MPS's radius in spacings takes the place of h/dx
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

}  // namespace sph::mps
