#pragma once
// The rigid bodies of an isph run and its energy budget, followed step by step (coupling/analyses/isph_stage.cpp):
// each body's travel, speed and the work the fluid's pressure did on it, the time it stopped, and the fluid's
// mechanical energy, so that the report can set the energy the fluid gained beside the work the bodies did on it.
#include <optional>
#include <string>
#include <vector>

#include "coupling/scene/isph_analysis.hpp"
#include "sph/fluid/stepper.hpp"

namespace coupling {

struct BodyRecord {
  std::string name;
  double mass = 0;  // [kg/m] density x area
  double travel = 0, speed = 0;  // at the end [m], [m/s]
  double max_speed = 0;  // [m/s]
  std::optional<double> stopped_at;  // [s] when it reached stop_after_m
  double work_on_fluid = 0;  // [J/m] -(fluid force . direction) x travel, summed over the steps
};

class BodyTracker {
 public:
  BodyTracker(const IsphAnalysis& analysis, const sph::fluid::Model& model);
  // After every step (the stepper's diagnostics carry the fluid's force on each body at r*).
  void after_step(const sph::fluid::Step& step, const sph::fluid::Model& model);
  const std::vector<BodyRecord>& bodies() const { return bodies_; }
  // On --resume: the records of the run before the checkpoint (report.json's isph.bodies), the fluid's energy at
  // the start of the run, and the bodies' travel and speed in the model read from the checkpoint.
  void restore(const std::vector<BodyRecord>& earlier, double fluid_energy_start, const sph::fluid::Model& model);
  double fluid_energy_start() const { return fluid_energy_start_; }

 private:
  std::vector<BodyRecord> bodies_;
  double fluid_energy_start_ = 0;
};

// The fluid's mechanical energy, kinetic plus potential (-sum m g.x over the fluid particles) [J/m].
double fluid_energy(const sph::fluid::Model& model);

}  // namespace coupling
