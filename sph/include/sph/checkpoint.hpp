#pragma once
// Binary checkpoints: the full particle state (including the rates the integrator carries) and the run
// state, so that resuming gives bitwise the same trajectory as an uninterrupted run.
//
// Layout (little-endian host order, checked by an endianness marker):
//   "SPHSLOPE-CKPT\0\0\0" (16 bytes) | u32 version | u32 0x01020304 | u64 particle count | u32 double arrays |
//   u32 materials | f64 dx | f64 h_over_dx | run state | the double arrays' names (u32 length + bytes each) |
//   the checkpointed double arrays of the particle set's registry, then id, material, kind |
//   u64 FNV-1a checksum of all before. Version 2: arrays by registry (version 1 had a fixed list of 25).
// Written with sph::write_file_atomically: a killed run leaves the previous checkpoint or the new one, never a
// torn file (the checksum would reject it anyway).
#include <string>

#include "sph/model.hpp"

namespace sph {

constexpr std::uint32_t checkpoint_version = 2;

void write_checkpoint(const std::string& path, const Model& model);

// Replaces model.particles and model.state with the checkpoint's. The model must have been built from the
// same scene (same particle count, material count, dx and h/dx); throws std::runtime_error otherwise or
// if the file is truncated/corrupt.
void read_checkpoint(const std::string& path, Model& model);

}  // namespace sph
