#include "coupling/analyses/isph_bodies.hpp"

#include <algorithm>
#include <cmath>

#include "sph/engine/run_loop.hpp"

namespace coupling {

namespace {

// The travel and speed of body b (its particles all hold them); false when it has no particle.
bool body_state(const sph::fluid::Model& model, std::size_t b, double& travel, double& speed) {
  const sph::ParticleSet& p = model.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] != 0 && p.material[i] == b + 1) {
      travel = p.field(model.fields.body_travel)[i];
      speed = p.field(model.fields.body_speed)[i];
      return true;
    }
  return false;
}

}  // namespace

double fluid_energy(const sph::fluid::Model& model) {
  const sph::Energies e = sph::moving_energies(model.particles, model.settings);
  return e.kinetic + e.potential;
}

BodyTracker::BodyTracker(const IsphAnalysis& analysis, const sph::fluid::Model& model)
    : fluid_energy_start_(fluid_energy(model)) {
  for (std::size_t b = 0; b < analysis.bodies.size(); ++b) {
    BodyRecord r;
    r.name = analysis.bodies[b].name;
    r.mass = model.bodies[b].mass();
    body_state(model, b, r.travel, r.speed);
    bodies_.push_back(r);
  }
}

void BodyTracker::after_step(const sph::fluid::Step& step, const sph::fluid::Model& model) {
  const sph::fluid::StepDiagnostics& d = step.diagnostics();
  for (std::size_t b = 0; b < bodies_.size() && b < d.body_force_x.size(); ++b) {
    BodyRecord& r = bodies_[b];
    double travel = r.travel, speed = r.speed;
    if (!body_state(model, b, travel, speed)) continue;
    const sph::fluid::RigidBody& body = model.bodies[b];
    const double force = d.body_force_x[b] * body.direction_x + d.body_force_y[b] * body.direction_y;
    r.work_on_fluid -= force * (travel - r.travel);  // the body pushes the fluid as much as the fluid resists
    r.travel = travel;
    r.speed = speed;
    r.max_speed = std::max(r.max_speed, std::abs(speed));
    if (!r.stopped_at && travel >= body.stop_travel) r.stopped_at = model.state.time;
  }
}

void BodyTracker::restore(const std::vector<BodyRecord>& earlier, double fluid_energy_start,
                          const sph::fluid::Model& model) {
  for (std::size_t b = 0; b < bodies_.size(); ++b) body_state(model, b, bodies_[b].travel, bodies_[b].speed);
  for (std::size_t b = 0; b < bodies_.size() && b < earlier.size(); ++b) {
    bodies_[b].max_speed = earlier[b].max_speed;
    bodies_[b].stopped_at = earlier[b].stopped_at;
    bodies_[b].work_on_fluid = earlier[b].work_on_fluid;
  }
  fluid_energy_start_ = fluid_energy_start;
}

}  // namespace coupling
