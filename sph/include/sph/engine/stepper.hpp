#pragma once
// The interface between a particle physics and the engine's run loop (run_loop.hpp). A stepper advances one
// particle set in time; the run loop owns the clock, output cadence, checkpoints, progress, the health guard and
// the observers, the same for every physics.
#include <cstdint>
#include <string>
#include <vector>

#include "sph/engine/particle_set.hpp"
#include "sph/engine/vtk_output.hpp"

namespace sph {

struct Energies {
  double kinetic = 0;              // [J/m]
  double potential = 0;            // -sum m g.x over the moving particles, datum x = 0 [J/m]
  double plastic_dissipation = 0;  // energy dissipated by the material model [J/m] (soil: plastic work)
  double max_speed = 0;            // [m/s]
};

struct Health {
  bool ok = true;
  std::string diagnostic;  // names the particle (original id), field and step when !ok
};

// Simulation clock and output bookkeeping; part of every checkpoint.
struct RunState {
  double time = 0.0;
  std::uint64_t step = 0;
  bool rates_valid = false;             // the physics' carried rates belong to the current state
  bool initial_stress_applied = false;  // the soil's geostatic start has been applied
  double next_output_time = 0.0;
  std::uint64_t frames_written = 0;
  std::vector<double> frame_times;
  double initial_potential_energy = 0.0;
  std::uint64_t energy_csv_bytes = 0;  // bytes of energy.csv that belong to this state
};

class Stepper {
 public:
  virtual ~Stepper() = default;
  // Prepares the state at the current time (first evaluation, or the stored order of a resumed run).
  virtual void initialise() = 0;
  // The largest stable time step at the current state [s].
  virtual double stable_time_step() const = 0;
  // Advances the particles by dt, the RunState's time and step counter included.
  virtual void advance(double dt) = 0;
  virtual Energies energies() const = 0;
  // NaN/Inf or runaway values, naming the particle, field and step.
  virtual Health check_health() const = 0;
  // Per-particle quantities the physics derives for the frames (not stored in the set).
  virtual std::vector<DerivedField> derived_outputs() const { return {}; }
};

}  // namespace sph
