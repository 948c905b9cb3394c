#pragma once
// One time step of a coupled run: the elasto-plastic soil (sph/soil) and the ISPH water (sph/fluid) in one domain,
// each with its own particle set, stepper and time-step bound, and the exchange between them (exchange.hpp).
// A step of the water's size dt (docs/coupled.md):
//   1  the soil's twins in the water take the soil's positions, velocities and accelerations at t;
//   2  the water advances from t to t + dt (the soil's surface a moving wall);
//   3  the water table is read from the water at t + dt and becomes the soil's pore-pressure line, and the water's
//      pressure force on each twin beyond the table's hydrostatic pressure becomes a surface force on its soil
//      particle (an impact, a wave: what the table does not carry);
//   4  the soil advances from t to t + dt in n = ceil(dt / dt_soil) equal sub-steps, dt_soil its own stable step.
// A staggered (Gauss-Seidel) explicit scheme: each physics keeps its own stability bound, the water's being the
// step's and the soil's the sub-steps'. The water's run state is the run's clock.
#include <memory>

#include "sph/coupled/exchange.hpp"
#include "sph/engine/stepper.hpp"
#include "sph/fluid/stepper.hpp"
#include "sph/soil/soil_step.hpp"

namespace sph::coupled {

class CoupledStep : public Stepper {
 public:
  // Adds the soil's twins to the water when it has none. Throws std::invalid_argument when the two models'
  // gravities or particle spacings differ, or when the soil carries surface forces of its own (strip and line loads:
  // not yet in a coupled run).
  CoupledStep(soil::Model& soil, fluid::Model& water);

  // The water table on the soil, then each physics' own start (the soil's geostatic stress with its pore pressure).
  void initialise() override;
  // The water's stable step (the soil sub-cycles inside it).
  double stable_time_step() const override;
  void advance(double dt) override;
  Energies energies() const override;  // the sums of both phases
  Health check_health() const override;  // the soil's, then the water's

  int last_substeps() const { return substeps_; }  // soil sub-steps of the last step
  // Wall-clock seconds spent in each physics' steps since construction (the water's step with the exchange's force,
  // the soil's sub-steps): each phase's particle-steps per second (docs/performance.md).
  double water_seconds() const { return water_seconds_; }
  double soil_seconds() const { return soil_seconds_; }
  double last_soil_time_step() const { return soil_dt_; }  // [s]
  const fluid::StepDiagnostics& water_diagnostics() const { return water_step_.diagnostics(); }
  const SoilBoundary& boundary() const { return boundary_; }
  // The soil's quantities derived for frames (its pressure -I1/3 [Pa]).
  std::vector<DerivedField> soil_outputs() const { return soil_step_.derived_outputs(); }

 private:
  void share_water_table();
  void share_water_forces();

  soil::Model& soil_;
  fluid::Model& water_;
  soil::SoilStep soil_step_;
  SoilBoundary boundary_;
  fluid::Step water_step_;
  FieldId force_x_ = 0, force_y_ = 0;  // the soil's surface-force fields: the water's force beyond the table's
  int substeps_ = 0;
  double soil_dt_ = 0;
  double water_seconds_ = 0, soil_seconds_ = 0;
};

}  // namespace sph::coupled
