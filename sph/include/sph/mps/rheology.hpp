#pragma once
// The granular rheology of the WC-MPS (seed section 2.2 and 2.8): a Herschel-Bulkley viscoplastic continuum whose
// yield stress follows Mohr-Coulomb / Drucker-Prager on the smoothed pressure, regularised by an exponential
// (Papanastasiou 1987; Zhu, Kim & De Kee 2005), capped. SI units; angles in degrees in the struct (as the soil's
// material, sphslope/units.hpp), radians inside the equations. The equations are in sph/mps/terms.hpp [M15-M19].
#include "sph/mps/settings.hpp"

namespace sph::mps {

struct HerschelBulkley {
  // The dry collapse of the seed (section 3.0): mu0 = 1.5 Pa s^N, N = 0.25, m = 50 s, phi = 22 deg (A16), c = 0.
  double consistency = 1.5;  // mu0 [Pa s^N], the consistency index
  double flow_index = 0.25;  // N [-]: 1 Bingham-like, < 1 shear thinning
  double growth = 50.0;  // m [s], the exponential regularisation's growth of stress
  double friction_angle_deg = 22.0;  // phi [deg]
  double cohesion = 0.0;  // c [Pa]

  // Throws std::invalid_argument naming the parameter, its value and the allowed range.
  void validate() const;
};

// tau_y = c cos(phi) + max(p', 0) sin(phi) [Pa] for the smoothed pressure p' [Pa] (seed eq. 3, 20; [M15]).
double yield_stress(const HerschelBulkley& material, double p_smoothed);

// The effective viscosity [Pa s] of a granular particle with smoothed pressure p' [Pa] and strain-rate norm
// |D| [1/s] (seed eq. 16), in the chosen form of the regularisation (A2), capped at mu_cap (A3): where the law is
// infinite (|D| = 0 with N < 1) the cap is returned.
double effective_viscosity(const HerschelBulkley& material, double p_smoothed, double norm_d, Regularisation form,
                           double mu_cap);

}  // namespace sph::mps
