#pragma once
// A WC-MPS model (issue 12; docs/mps.md): the particle set (moving particles of kind 0, fixed wall particles of
// kind 1, the outer wall layers marked as dummy particles), its run state, the settings, the materials and the MPS
// state block; and the builders that fill it. Each material is a phase with its own reference density (seed eq. 26:
// water rho_f, sediment the bulk density rho_b); one material, or all of one density, is the single-phase model
// with the settings' rest density rho0 unless the material sets its own. SI units, 2-D.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sph/engine/particle_set.hpp"
#include "sph/engine/stepper.hpp"
#include "sph/mps/fields.hpp"
#include "sph/mps/rheology.hpp"
#include "sph/mps/settings.hpp"

namespace sph::mps {

// What a particle's viscosity follows.
struct Material {
  enum class Type { water, granular };
  Type type = Type::water;
  double viscosity = 1.0e-3;  // [Pa s] constant viscosity of the water type (water at 20 C)
  HerschelBulkley granular;  // the regularised Herschel-Bulkley law of the granular type (rheology.hpp)
  // The phase's reference density [kg/m^3] (seed eq. 26: rho_f for water, the bulk density
  // rho_b = phi0 rho_g + (1 - phi0) rho_f for saturated sediment, phi0 rho_g for dry grains); 0: the settings'
  // rest_density. It is the particles' mass over dx^2, the EOS prefactor and the rho_i of the momentum equation.
  double density = 0.0;
  // phi0, the grains' share of the volume (granular type; water 0): the volume fraction phi = sum phi0_j w / sum w
  // written to the frames (seed 2.10). Default 0.6 (seed A12, A22: the dry collapse's packing).
  double grain_volume_fraction = 0.6;

  static Material water(double mu = 1.0e-3);
  static Material granular_material(const HerschelBulkley& hb = {});
  // Throws std::invalid_argument naming the parameter when a value is out of its range.
  void validate() const;
};
// The material types' names in scene files (analyses.mps.materials[i].type).
inline constexpr sphslope::NameTable<Material::Type, 2> material_type_names{
    {{"granular", Material::Type::granular}, {"water", Material::Type::water}}};

struct Model {
  // Validates the settings and the materials (at least one). Throws std::invalid_argument.
  Model(const Settings& s, std::vector<Material> m);
  Settings settings;
  std::vector<Material> materials;
  ParticleSet particles;
  RunState state;
  Fields fields;
  FieldId dummy;  // 1 for the dummy wall particles (number density only), else 0 (checkpointed)
  FieldId gate;  // 1 for the particles of the gate (add_gate), else 0 (checkpointed)

  Arrays arrays() { return Arrays(particles, fields); }
  // The reference density of material m [kg/m^3] (Material::density, or the settings' rest_density when 0).
  double density_of(std::size_t m) const;
  // phi0 of material m (0 for water).
  double grain_fraction_of(std::size_t m) const;
  // The first water material, if any (the pore water of PorePressure::hydrostatic).
  std::optional<std::size_t> water_material() const;
  // True when every material has the same reference density: the single-phase model (no mixture density).
  bool single_density() const;
  // The mass of a particle of material m [kg per m of depth]: its density times dx^2.
  double particle_mass(std::size_t m) const {
    return density_of(m) * settings.particle_spacing * settings.particle_spacing;
  }
};

// Moving particles on the cell-centred lattice (anchor at the origin) inside [x_min, x_max] x [y_min, y_max], at
// rest, mass rho0 dx^2, of material `material`. Returns the count.
std::size_t add_block(Model& model, double x_min, double y_min, double x_max, double y_max, std::uint16_t material);

// Fixed wall particles around the box [x_min, x_max] x [y_min, y_min + height] (bottom and both sides): ceil(r_e/dx)
// layers (seed 2.7: the dummy layers cover r_e). The layer next to the box is made of wall particles (EOS pressure
// on their own number density); the outer layers are dummy particles (number density and viscous term only,
// pressure 0, out of the pressure gradient). Returns the count of all of them.
std::size_t add_box(Model& model, double x_min, double x_max, double y_min, double height, std::uint16_t material);

// A gate: fixed wall particles in a vertical slab ceil(r_e/dx) spacings thick from x_min to the right, from y_min up
// `height`, on the lattice of the blocks; its two faces are wall particles (EOS pressure), the layers between them
// dummy particles, so that material on either side sees a full neighbourhood. It rises as settings.gate_rise says
// (the stepper moves it; no-slip: its velocity enters the viscous sums). Returns the count.
std::size_t add_gate(Model& model, double x_min, double y_min, double height, std::uint16_t material);
// The gate's thickness [m] (ceil(r_e/dx) spacings).
double gate_thickness(const Settings& s);

}  // namespace sph::mps
