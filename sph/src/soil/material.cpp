#include "sph/soil/material.hpp"

#include <stdexcept>
#include "sph/engine/require.hpp"
#include "sphslope/units.hpp"

namespace sph::soil {

void Material::validate() const {
  const std::string m = "material '" + name + "': ";
  require(std::isfinite(density) && density > 0, m + "density must be > 0 kg/m^3");
  require(std::isfinite(youngs_modulus) && youngs_modulus > 0, m + "youngs_modulus must be > 0 Pa");
  require(std::isfinite(poisson_ratio) && poisson_ratio > -1.0 && poisson_ratio < 0.5,
          m + "poisson_ratio must lie in (-1, 0.5)");
  require(std::isfinite(cohesion) && cohesion >= 0, m + "cohesion must be >= 0 Pa");
  require(std::isfinite(friction_angle_deg) && friction_angle_deg >= 0 && friction_angle_deg < 90,
          m + "friction_angle_deg must lie in [0, 90)");
  require(std::isfinite(dilatancy_angle_deg) && dilatancy_angle_deg >= 0 &&
              dilatancy_angle_deg <= friction_angle_deg,
          m + "dilatancy_angle_deg must lie in [0, friction_angle_deg]");
  require(!plastic || cohesion > 0 || friction_angle_deg > 0,
          m + "a plastic material needs cohesion > 0 or friction_angle_deg > 0");
  require(std::isnan(k0) || (k0 > 0 && k0 < 10), m + "k0 must lie in (0, 10) (or be unset)");
}

MaterialConstants MaterialConstants::from(const Material& m) {
  m.validate();
  MaterialConstants c;
  c.density = m.density;
  c.bulk_modulus = m.youngs_modulus / (3.0 * (1.0 - 2.0 * m.poisson_ratio));
  c.shear_modulus = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
  c.lame_lambda = c.bulk_modulus - 2.0 * c.shear_modulus / 3.0;
  c.plastic = m.plastic;
  if (m.plastic) {
    const double tphi = std::tan(sphslope::radians(m.friction_angle_deg));
    const double tpsi = std::tan(sphslope::radians(m.dilatancy_angle_deg));
    c.alpha_phi = tphi / std::sqrt(9.0 + 12.0 * tphi * tphi);
    c.k_c = 3.0 * m.cohesion / std::sqrt(9.0 + 12.0 * tphi * tphi);
    c.alpha_psi = tpsi / std::sqrt(9.0 + 12.0 * tpsi * tpsi);
  } else {
    c.alpha_phi = 0.0;
    c.k_c = std::numeric_limits<double>::infinity();
    c.alpha_psi = 0.0;
  }
  c.sound_speed = std::sqrt((c.bulk_modulus + 4.0 * c.shear_modulus / 3.0) / m.density);
  c.k0 = std::isnan(m.k0) ? m.poisson_ratio / (1.0 - m.poisson_ratio) : m.k0;
  c.lambda_denominator = 9.0 * c.alpha_phi * c.alpha_psi * c.bulk_modulus + c.shear_modulus;
  c.plastic_strain_per_lambda = std::sqrt(2.0 * c.alpha_psi * c.alpha_psi + 1.0 / 3.0);
  c.half_inv_shear = 0.5 / c.shear_modulus;
  c.inv_9_bulk = 1.0 / (9.0 * c.bulk_modulus);
  c.apex_i1 = c.alpha_phi > 0.0 ? c.k_c / c.alpha_phi : std::numeric_limits<double>::infinity();
  return c;
}

}  // namespace sph::soil
