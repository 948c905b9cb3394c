#pragma once
// Checkpoints of a soil model (the engine's format, sph/engine/checkpoint.hpp, with the model's materials, dx and
// h/dx as the fingerprint).
#include <string>

#include "sph/engine/checkpoint.hpp"
#include "sph/soil/model.hpp"

namespace sph::soil {

void write_checkpoint(const std::string& path, const Model& model);

// Replaces the model's particle state and run state with the checkpoint's. The model must have been built from
// the same scene (same particle count, material count, dx and h/dx); throws std::runtime_error otherwise or if the
// file is truncated/corrupt.
void read_checkpoint(const std::string& path, Model& model);

// The same in memory (a coupled run's checkpoint holds the soil and the water, sph/coupled/model.hpp).
std::string checkpoint_bytes(const Model& model);
void restore_checkpoint(const std::string& bytes, const std::string& path, Model& model);

}  // namespace sph::soil
