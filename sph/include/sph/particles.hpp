#pragma once
// Particle storage: structure of arrays, one contiguous std::vector per field.
// Units: SI (m, s, kg, Pa). 2-D plane strain; "mass" is per metre of out-of-plane width (kg/m).
// Stress is the total Cauchy stress, tension positive; sigma_zz is the out-of-plane normal stress.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sph {

enum class ParticleKind : std::uint8_t { soil = 0, wall = 1 };

struct Particles {
  // --- state (checkpointed) -------------------------------------------------------------
  std::vector<double> x, y;           // position [m]
  std::vector<double> vx, vy;         // velocity [m/s]; for walls: the ghost velocity seen by soil
  std::vector<double> rho;            // density [kg/m^3]
  std::vector<double> mass;           // [kg/m]
  std::vector<double> sxx, syy, szz, sxy;  // stress [Pa]; for walls: extrapolated from the soil
  std::vector<double> plastic_strain;      // accumulated equivalent plastic strain [-]
  std::vector<double> plastic_work;        // accumulated plastic work per unit mass [J/kg]
  std::vector<double> x0, y0;              // initial position [m] (displacement = x - x0)
  std::vector<double> wall_nx, wall_ny;    // unit normal of a wall particle pointing into the domain (0 for soil)
  // rates evaluated at the current state (needed by the integrator; checkpointed for exact resume)
  std::vector<double> ax, ay, drho, dsxx, dsyy, dszz, dsxy, dplastic_strain, dplastic_work;
  std::vector<std::uint32_t> id;        // original index, stable across reordering
  std::vector<std::uint16_t> material;  // index into Model::materials
  std::vector<std::uint8_t> kind;       // ParticleKind

  std::size_t size() const { return x.size(); }

  // Appends one particle at rest with zero stress.
  void add(double px, double py, double particle_mass, double density, std::uint16_t material_id,
           ParticleKind particle_kind, double normal_x = 0.0, double normal_y = 0.0);

  void reserve(std::size_t n);

  // Calls f(std::vector<T>&) for every per-particle array (doubles first, then integer arrays).
  template <class F>
  void for_each_array(F&& f) {
    for_each_double_array(f);
    f(id);
    f(material);
    f(kind);
  }
  template <class F>
  void for_each_double_array(F&& f) {
    f(x); f(y); f(vx); f(vy); f(rho); f(mass); f(sxx); f(syy); f(szz); f(sxy);
    f(plastic_strain); f(plastic_work); f(x0); f(y0); f(wall_nx); f(wall_ny);
    f(ax); f(ay); f(drho); f(dsxx); f(dsyy); f(dszz); f(dsxy); f(dplastic_strain); f(dplastic_work);
  }
  static constexpr int double_array_count = 25;

  std::size_t count(ParticleKind k) const;
};

}  // namespace sph
