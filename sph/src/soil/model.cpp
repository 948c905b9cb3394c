#include "sph/soil/model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sph/engine/neighbour_search.hpp"
#include "sph/engine/require.hpp"
#include "sph/soil/soil_step.hpp"
#include "terms.hpp"

namespace sph::soil {

double default_cfl(TimeIntegration integration) {
  return integration == TimeIntegration::verlet ? 0.8 : 0.2;
}

int default_stress_substeps(TimeIntegration integration) { return integration == TimeIntegration::verlet ? 16 : 1; }

double max_cfl(TimeIntegration integration) { return integration == TimeIntegration::verlet ? 1.6 : 0.5; }

void Settings::validate() const {
  validate_engine();
  if (!(cfl <= max_cfl(integration))) {
    std::ostringstream os;
    os << "settings.cfl = " << cfl << " is above " << max_cfl(integration) << ", the largest stable value of the "
       << sphslope::name_of(time_integration_names, integration) << " time integration (default "
       << default_cfl(integration) << "; docs/sph.md, \"Time step\")";
    throw std::invalid_argument(os.str());
  }
  require(std::isfinite(viscosity.alpha) && viscosity.alpha >= 0, "settings.viscosity.alpha must be >= 0");
  require(std::isfinite(viscosity.beta) && viscosity.beta >= 0, "settings.viscosity.beta must be >= 0");
  require(finite_positive(viscosity.eta_factor), "settings.viscosity.eta_factor must be > 0 (typical 0.01)");
  require(std::isfinite(artificial_stress.epsilon) && artificial_stress.epsilon >= 0 && artificial_stress.epsilon <= 1,
          "settings.artificial_stress.epsilon must lie in [0, 1] (typical 0.3-0.5)");
  require(finite_positive(artificial_stress.exponent),
          "settings.artificial_stress.exponent must be > 0 (typical 2.55-4)");
  require(std::isfinite(xsph.chi) && xsph.chi >= 0 && xsph.chi <= 1, "settings.xsph.chi must lie in [0, 1]");
  require(std::isfinite(damping) && damping >= 0, "settings.damping must be >= 0 1/s");
  require(std::isfinite(wall_friction_angle_deg) && wall_friction_angle_deg >= 0 && wall_friction_angle_deg < 90,
          "settings.wall_friction_angle_deg must lie in [0, 90) degrees");
  require(wall_friction_angle_deg == 0 || wall_slip == WallSlip::frictional,
          "settings.wall_friction_angle_deg is used only with the frictional wall condition (wall_slip)");
  require(stress_substeps >= 1 && stress_substeps <= 64, "settings.stress_substeps must lie in [1, 64]");
  require(stress_substeps == 1 || integration == TimeIntegration::verlet,
          "settings.stress_substeps > 1 needs the verlet time integration (the predictor-corrector updates the stress "
          "twice per step)");
}

void Model::validate() const {
  settings.validate();
  require(!materials.empty(), "model: at least one material is required");
  require(materials.size() <= 65535, "model: at most 65535 materials");
  for (const auto& m : materials) m.validate();
  const auto& p = particles;
  const std::size_t n = p.size();
  bool sizes_ok = true;
  const_cast<ParticleSet&>(p).for_each_array([&](auto& a) { sizes_ok = sizes_ok && a.size() == n; });
  require(sizes_ok, "model: particle arrays have inconsistent sizes");
  require(p.count(ParticleKind::material) > 0, "model: no soil particles");
  if (loads.water) {
    const std::string why = loads.water->error();
    require(why.empty(), "model.loads.water: " + why);
  }
  require(std::isfinite(loads.seismic_coefficient), "model.loads.seismic_coefficient must be finite");
  require(std::isfinite(loads.vertical_seismic_coefficient) && std::fabs(loads.vertical_seismic_coefficient) < 1.0,
          "model.loads.vertical_seismic_coefficient must lie in (-1, 1)");
  for (std::size_t i = 0; i < n; ++i) {
    if (p.material[i] >= materials.size())
      throw std::invalid_argument("model: particle " + std::to_string(p.id[i]) + " has material " +
                                  std::to_string(p.material[i]) + " but only " + std::to_string(materials.size()) +
                                  " materials exist");
    if (!finite_positive(p.mass[i]) || !finite_positive(p.rho[i]) || !std::isfinite(p.x[i]) || !std::isfinite(p.y[i]))
      throw std::invalid_argument("model: particle " + std::to_string(p.id[i]) +
                                  " has a non-positive mass/density or a non-finite position");
    if (p.kind[i] > 1)
      throw std::invalid_argument("model: particle " + std::to_string(p.id[i]) + " has an unknown kind");
  }
}

bool Model::uses_artificial_stress() const {
  switch (settings.artificial_stress.mode) {
    case ArtificialStressMode::off: return false;
    case ArtificialStressMode::on: return settings.artificial_stress.epsilon > 0;
    case ArtificialStressMode::automatic:
      for (const auto& m : materials)
        if (m.plastic && m.cohesion > 0) return settings.artificial_stress.epsilon > 0;
      return false;
  }
  return false;
}

double time_step_estimate(const Model& model) {
  double c_max = 0;
  for (const auto& m : model.materials) c_max = std::max(c_max, MaterialConstants::from(m).sound_speed);
  if (!(c_max > 0)) throw std::invalid_argument("model: no materials");
  const Settings& s = model.settings;
  return terms::courant_time_step(s.cfl, s.smoothing_length(), c_max, s.viscosity.alpha, s.viscosity.beta, 0.0);
}

std::size_t estimate_memory_bytes(std::size_t n) {
  // The arrays a soil model carries: the particle set with the soil's state block, and the stepper's half-step
  // values (SoilStep registers them in the set too); both are reordered through back buffers.
  Model prototype;
  const auto state_doubles = static_cast<std::size_t>(prototype.particles.double_array_count());
  SoilStep::register_workspace(prototype.particles);
  const auto workspace_doubles = static_cast<std::size_t>(prototype.particles.double_array_count()) - state_doubles;
  const std::size_t per_particle_state = state_doubles * sizeof(double) + 4 + 2 + 1;
  const std::size_t state = 2 * n * per_particle_state;  // particles + reorder back buffers
  const std::size_t workspace = n * (2 * workspace_doubles + 11) * sizeof(double)  // half-step values (+ back), scratch
                                + n * 2 * sizeof(std::uint32_t);  // index lists, moved list
  const std::size_t output = n * (per_particle_state + 200);  // checkpoint buffer, VTU buffer
  // the Verlet step's recorded pairs: about 30 per particle (Wendland at h = 1.3 dx) of j, r and F, and 3 indices
  const std::size_t pairs = n * (30 * (sizeof(std::uint32_t) + 2 * sizeof(double)) + 3 * sizeof(std::uint32_t));
  return state + workspace + CellList::estimate_bytes(n) + output + pairs + (std::size_t{1} << 20);
}

}  // namespace sph::soil
