#include "sph/mps/rheology.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sph/mps/terms.hpp"
#include "sphslope/units.hpp"

namespace sph::mps {

namespace {

void need(bool ok, const char* name, double value, const char* allowed) {
  if (ok) return;
  std::ostringstream s;
  s << "mps material: " << name << " = " << value << " is out of range; allowed: " << allowed;
  throw std::invalid_argument(s.str());
}

}  // namespace

void HerschelBulkley::validate() const {
  need(std::isfinite(consistency) && consistency >= 0, "consistency (mu0)", consistency, ">= 0 Pa s^N");
  need(std::isfinite(flow_index) && flow_index > 0 && flow_index <= 2, "flow_index (N)", flow_index, "(0, 2]");
  need(std::isfinite(growth) && growth > 0, "growth (m)", growth, "> 0 s");
  need(friction_angle_deg >= 0 && friction_angle_deg < 90, "friction_angle_deg", friction_angle_deg, "[0, 90) deg");
  need(std::isfinite(cohesion) && cohesion >= 0, "cohesion", cohesion, ">= 0 Pa");
}

double yield_stress(const HerschelBulkley& material, double p_smoothed) {
  return terms::yield_stress(material.cohesion, sphslope::radians(material.friction_angle_deg), p_smoothed);
}

double effective_viscosity(const HerschelBulkley& material, double p_smoothed, double norm_d, Regularisation form,
                           double mu_cap) {
  const double tau_y = yield_stress(material, p_smoothed);
  const double mu =
      form == Regularisation::as_printed
          ? terms::viscosity_as_printed(tau_y, norm_d, material.consistency, material.flow_index, material.growth)
          : terms::viscosity_consistent(tau_y, norm_d, material.consistency, material.flow_index, material.growth);
  return terms::capped_viscosity(mu, mu_cap);
}

}  // namespace sph::mps
