#include "sph/soil/checkpoint.hpp"

namespace sph::soil {

namespace {
CheckpointFingerprint fingerprint(const Model& model) {
  return {static_cast<std::uint32_t>(model.materials.size()), model.settings.particle_spacing,
          model.settings.h_over_dx};
}
}  // namespace

void write_checkpoint(const std::string& path, const Model& model) {
  sph::write_checkpoint(path, model.particles, model.state, fingerprint(model));
}

void read_checkpoint(const std::string& path, Model& model) {
  restore_checkpoint(sph::read_checkpoint_file(path), path, model);
}

std::string checkpoint_bytes(const Model& model) {
  return sph::checkpoint_bytes(model.particles, model.state, fingerprint(model));
}

void restore_checkpoint(const std::string& bytes, const std::string& path, Model& model) {
  if (model.settings.wall_slip == WallSlip::frictional) register_wall_friction_state(model.particles);
  sph::restore_checkpoint(bytes, path, model.particles, model.state, fingerprint(model));
}

}  // namespace sph::soil
