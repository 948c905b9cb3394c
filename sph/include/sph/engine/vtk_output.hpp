#pragma once
// ParaView output: one .vtu (XML UnstructuredGrid, binary appended raw data) per frame and a .pvd series.
// Point data: velocity, displacement, every registered field marked write_vtu (the soil: stress_xx/yy/zz/xy [Pa],
// plastic_strain), the physics' derived quantities (the soil: pressure = -I1/3 [Pa]), density, material, kind
// (0 moving material, 1 wall), id. All files are written with sph::write_file_atomically (atomic_file.hpp).
#include <string>
#include <utility>
#include <vector>

#include "sph/engine/particle_set.hpp"

namespace sph {

// A per-particle quantity a physics computes for output only (not stored in the set).
struct DerivedField {
  std::string name;
  std::vector<double> values;
};

void write_vtu(const std::string& path, const ParticleSet& particles, double time,
               const std::vector<DerivedField>& derived = {});

// One particle set's share of a frame that shows several (a coupled run's soil and water): phase[i] is particle i's
// value in the frame's "phase" array, or -1 to leave it out. A registered or derived field one set lacks is NaN for
// its particles.
struct FramePart {
  const ParticleSet* particles = nullptr;
  std::vector<DerivedField> derived;
  std::vector<int> phase;  // one per particle of the set
};
void write_vtu(const std::string& path, const std::vector<FramePart>& parts, double time);

// frames: (time, file name relative to the .pvd's folder)
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames);

}  // namespace sph
