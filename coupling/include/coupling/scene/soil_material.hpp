#pragma once
// A soil material of a scene (a section's layer or a particle body), in SI units.
#include <limits>
#include <optional>
#include <string>

#include "slope/strength.hpp"
#include "sphslope/names.hpp"
#include "sphslope/units.hpp"

namespace coupling {

using sphslope::standard_gravity;  // density = unit weight / g

// A soil of the section, SI units. Section::materials holds the strength and weight for limit equilibrium;
// this keeps everything the scene said, including what only SPH needs.
// constitutive_model's names in scene files, each with whether the SPH soil model keeps the material elastic.
inline constexpr sphslope::NameTable<bool, 2> constitutive_model_names{{{"drucker_prager", false}, {"elastic", true}}};

struct SoilMaterial {
  std::string name;
  double unit_weight = 0.0;                // N/m^3
  std::optional<double> saturated_unit_weight;  // N/m^3, limit equilibrium, below the piezometric line
  double cohesion = 0.0;                   // Pa
  double friction_angle = 0.0;             // rad
  std::optional<double> dilatancy_angle;   // rad; absent: SPH uses 0 (non-associated flow)
  std::optional<double> youngs_modulus;    // Pa; needed by SPH only
  std::optional<double> poisson_ratio;     // -; needed by SPH only
  bool elastic = false;                    // SPH: linear elastic, no yield (constitutive_model "elastic")
  double pore_pressure_ratio = 0.0;        // r_u (-), limit equilibrium only: u = r_u x the soil's overburden
  // limit equilibrium only: the cohesion's increase with depth (slope::Material::cohesion_rate has the rule)
  double cohesion_rate = 0.0;                                     // Pa/m; 0: constant cohesion
  std::optional<double> cohesion_datum_y;                         // m; absent: depth below the material's top
  double cohesion_max = std::numeric_limits<double>::infinity();  // Pa
  // limit equilibrium: a non-linear strength envelope (hoek_brown, power_curve or shear_normal_kPa) in place of
  // cohesion and friction_angle; mohr_coulomb: cohesion_kPa and friction_angle_deg were given (always, without an
  // envelope; the SPH soil model needs them)
  std::optional<slope::StrengthEnvelope> envelope;
  bool mohr_coulomb = true;

  double density() const { return unit_weight / standard_gravity; }  // kg/m^3
};

}  // namespace coupling
