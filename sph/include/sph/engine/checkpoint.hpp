#pragma once
// Binary checkpoints of a particle set and its run state: every array the set's registry marks as checkpointed
// (the rates a physics carries between steps included), so that resuming gives bitwise the same trajectory as an
// uninterrupted run.
//
// Layout (little-endian host order, checked by an endianness marker):
//   "SPHSLOPE-CKPT\0\0\0" (16 bytes) | u32 version | u32 0x01020304 | u64 particle count | u32 double arrays |
//   u32 materials | f64 dx | f64 h_over_dx | run state | the double arrays' names (u32 length + bytes each) |
//   the checkpointed double arrays of the particle set's registry, then id, material, kind |
//   u64 FNV-1a checksum of all before. Version 2: arrays by registry (version 1 had a fixed list of 25).
// Written with sph::write_file_atomically: a killed run leaves the previous checkpoint or the new one, never a
// torn file (the checksum would reject it anyway).
#include <cstdint>
#include <string>

#include "sph/engine/particle_set.hpp"
#include "sph/engine/stepper.hpp"

namespace sph {

constexpr std::uint32_t checkpoint_version = 2;

// What ties a checkpoint to the model it came from, besides the particle count and the array names.
struct CheckpointFingerprint {
  std::uint32_t materials = 0;
  double particle_spacing = 0;  // [m]
  double h_over_dx = 0;
  // Particles may have left the model since it was built (a physics that removes particles leaving its domain):
  // the checkpoint's particle count is then taken as it is, not compared with the model's.
  bool particles_may_leave = false;
};

void write_checkpoint(const std::string& path, const ParticleSet& particles, const RunState& state,
                      const CheckpointFingerprint& fingerprint);

// Replaces the checkpointed arrays of `particles` and the run state with the checkpoint's (arrays that are not
// checkpointed, a stepper's workspace, are sized and zeroed). Throws std::runtime_error when the checkpoint does
// not belong to this model (particle count, array names or the fingerprint differ) or is truncated or corrupt.
void read_checkpoint(const std::string& path, ParticleSet& particles, RunState& state,
                     const CheckpointFingerprint& expected);

// The same in memory, for a file that holds more than one particle set (sph/coupled/model.hpp): the bytes
// write_checkpoint writes, and the restore read_checkpoint makes from them (`path` names the file in messages).
std::string checkpoint_bytes(const ParticleSet& particles, const RunState& state,
                             const CheckpointFingerprint& fingerprint);
void restore_checkpoint(const std::string& bytes, const std::string& path, ParticleSet& particles, RunState& state,
                        const CheckpointFingerprint& expected);
// A checkpoint file's bytes. Throws std::runtime_error when it cannot be opened.
std::string read_checkpoint_file(const std::string& path);

}  // namespace sph
