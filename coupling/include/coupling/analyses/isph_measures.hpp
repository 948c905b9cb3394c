#pragma once
// What the isph stage measures on the particles besides the monitors: fluid particles that went past the tank's
// walls (every step), particle snapshots at the times of analyses.isph.snapshots_s, and, for a still tank, the
// hydrostatic pressure at the floor and the largest speed at the end.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "coupling/scene/isph_analysis.hpp"
#include "sph/engine/run_loop.hpp"
#include "sph/fluid/model.hpp"

namespace coupling {

// Fluid particles (kind 0) whose centres lie beyond the first row of wall particles (dx/2 outside the inner faces)
// of the left, right or bottom wall, at any height: particles the walls did not hold.
std::size_t fluid_past_walls(const sph::ParticleSet& p, const Tank& tank, double dx);

// fluid_past_walls after every step: the most at any step and the first time there was one.
class WallCrossingObserver : public sph::Observer {
 public:
  WallCrossingObserver(const Tank& tank, double dx) : tank_(tank), dx_(dx) {}
  std::string after_step(const sph::ParticleSet& p, const sph::RunState& state, const sph::Energies&) override;
  // On --resume: the figures of the run before the checkpoint.
  void restore(std::size_t most, std::optional<double> first_time);
  std::size_t most() const { return most_; }
  std::optional<double> first_time() const { return first_time_; }

 private:
  const Tank& tank_;
  double dx_;
  std::size_t most_ = 0;
  std::optional<double> first_time_;
};

// Every particle at one time: positions [m], pressure [Pa], kind (0 fluid, 1 wall).
struct IsphSnapshot {
  double time = 0;  // [s] of the step it was taken at
  double spacing = 0;  // dx [m]
  std::vector<double> x, y, pressure;
  std::vector<std::uint8_t> kind;
};
IsphSnapshot take_snapshot(const sph::ParticleSet& p, sph::FieldId pressure, double time, double dx);

// "isph_snapshot_<t>s.svg": the figure of the snapshot asked for at t [s], in the run folder's figures/.
std::string snapshot_file_name(double requested_time);

// Snapshots at the first step at or after each requested time; each is handed to `write` with its requested
// time (it writes the figure and returns the file's name, kept in files()).
class SnapshotObserver : public sph::Observer {
 public:
  using Writer = std::function<std::string(double requested, const IsphSnapshot&)>;
  SnapshotObserver(std::vector<double> times, sph::FieldId pressure, double dx, Writer write);
  std::string after_step(const sph::ParticleSet& p, const sph::RunState& state, const sph::Energies&) override;
  // On --resume: the times up to `time` were taken before the checkpoint (their files: `earlier`).
  void restore(double time, std::vector<std::string> earlier);
  const std::vector<double>& times() const { return times_; }
  const std::vector<std::string>& files() const { return files_; }

 private:
  std::vector<double> times_;
  sph::FieldId pressure_;
  double dx_;
  Writer write_;
  std::size_t next_ = 0;
  std::vector<std::string> files_;
};

// The kernel-sum density of a flat free surface's top row and of the row below it on the lattice at rest, as
// fractions of a full lattice's (docs/isph.md D4: 0.748 and 0.981 with the Wendland C2 kernel at h = 1.5 dx). A
// surface_beta between them marks the top row, and only it, as the free surface.
struct SurfaceRows {
  double top = 0, second = 0;
};
SurfaceRows surface_row_kernel_sums(sph::KernelType kernel, double h_over_dx);

// A still tank: one water block spanning the tank's width from its floor. Against hydrostatics (rho0 g H, H the
// block's height): the pressure at the floor from a least-squares line P(y) through the fluid particles that are
// not on the free surface, and its slope; the largest speed at the end against sqrt(g H).
struct StillTankCheck {
  double depth = 0;  // H [m]
  double rho_g_depth = 0;  // rho0 g H [Pa]
  double floor_pressure = 0;  // the fitted line at the floor [Pa]
  double expected_ratio = 0;  // 1 - dx/(2H): P = 0 is imposed at the top row's centres, dx/2 below the surface
  double gradient_ratio = 0;  // -dP/dy / (rho0 g)
  double max_speed_end = 0;  // [m/s]
  double celerity = 0;  // sqrt(g H) [m/s]
};
std::optional<StillTankCheck> still_tank_check(const sph::fluid::Model& model, const IsphAnalysis& analysis);

}  // namespace coupling
