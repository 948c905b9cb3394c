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

// frames: (time, file name relative to the .pvd's folder)
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames);

}  // namespace sph
