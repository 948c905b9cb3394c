#pragma once
// The monitors of a particle flow in a tank (analyses.isph, analyses.mps; coupling/scene/tank_scene.hpp), sampled
// from the moving particles (kind 0) at t = 0, at the first step at or after each multiple of the interval, and at
// the end of the run (sample() by the caller).
#include <string>
#include <vector>

#include "coupling/analyses/monitor_table.hpp"
#include "coupling/scene/tank_scene.hpp"
#include "sph/engine/run_loop.hpp"

namespace coupling {

class TankMonitorObserver : public sph::Observer {
 public:
  // dx: the particle spacing [m] (a particle's half extent is dx/2).
  TankMonitorObserver(const TankMonitors& monitors, const Tank& tank, double dx);
  std::string after_step(const sph::ParticleSet& p, const sph::RunState& state, const sph::Energies&) override;
  // Adds a row at `time` and moves the next sample to the following multiple of the interval.
  void sample(const sph::ParticleSet& p, double time);
  MonitorTable& table() { return table_; }
  // On --resume: the rows of an earlier monitors.csv up to `time` [s] replace the table, and sampling goes on from
  // the next multiple of the interval. A file with other columns, or none, leaves the table as it is.
  void restore(const std::string& csv, double time);

 private:
  const TankMonitors& monitors_;
  const Tank& tank_;
  double dx_;
  MonitorTable table_;
  double next_ = 0;
};

// The top of the moving material at x: the highest particle centre within dx of x, plus dx/2; the tank floor
// where there is none [m].
double surface_at(const sph::ParticleSet& p, double x, double dx, double floor);
// The largest x of the moving material plus dx/2 [m] (-infinity when there is none).
double front_of(const sph::ParticleSet& p, double dx);
// The farthest of the x positions still in contact with the body: in the order of decreasing x, the first whose
// next one lies within `gap` (stray particles thrown ahead do not count); the smallest when none does. xs not empty.
double farthest_in_contact(std::vector<double> xs, double gap);
// The front of the body of moving material: in the order of decreasing x, the first particle whose next one lies
// within 1.5 dx (stray particles thrown ahead do not count), plus dx/2 [m] (-infinity when there is none).
double contact_front(const sph::ParticleSet& p, double dx);

}  // namespace coupling
