#pragma once
// ParaView output: one .vtu (XML UnstructuredGrid, binary appended raw data) per frame and a .pvd series.
// Point data: velocity, displacement, stress_xx/yy/zz/xy [Pa], pressure = -I1/3 [Pa], plastic_strain,
// density, material, kind (0 soil, 1 wall), id. For walls velocity and stress are the ghost values seen by soil.
// All files are written with sph::write_file_atomically (atomic_file.hpp).
#include <string>
#include <utility>
#include <vector>

#include "sph/particles.hpp"

namespace sph {

void write_vtu(const std::string& path, const Particles& particles, double time);

// frames: (time, file name relative to the .pvd's folder)
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames);

}  // namespace sph
