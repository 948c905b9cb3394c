#pragma once
// The settings every particle physics shares: kernel and resolution, gravity, time-step safety factors, the run's
// end, output and checkpoint cadence, and the blow-up guard. A physics derives its own settings from this struct and
// adds its options (sph/soil/model.hpp: Settings). Defaults and allowed ranges live here only; the scene reader
// takes them from here.
#include "sph/engine/kernel.hpp"
#include "sphslope/units.hpp"

namespace sph {

enum class GravityMode {
  sudden,  // zero initial stress, full gravity from t = 0 (the thesis)
  geostatic_k0,  // soil: sigma_yy = -rho g depth below the local free surface, sigma_xx = sigma_zz = K0 sigma_yy
  ramped,  // zero initial stress, gravity grows linearly from 0 to full over gravity_ramp_time
};
// The gravity modes' names in scene files and reports.
inline constexpr sphslope::NameTable<GravityMode, 3> gravity_mode_names{{{"sudden", GravityMode::sudden},
                                                                       {"geostatic_k0", GravityMode::geostatic_k0},
                                                                       {"ramped", GravityMode::ramped}}};

struct EngineSettings {
  static constexpr double h_over_dx_min = 1.0;  // allowed range of h / dx
  static constexpr double h_over_dx_max = 2.0;

  KernelType kernel = KernelType::cubic_spline;
  double particle_spacing = 0;  // dx [m] (required; lattice spacing used to build the bodies)
  double h_over_dx = 1.2;  // smoothing length h = h_over_dx * dx
  double gravity_x = 0.0, gravity_y = -sphslope::standard_gravity;  // [m/s^2]
  GravityMode gravity_mode = GravityMode::sudden;
  double gravity_ramp_time = 0.0;  // [s] ramped mode: g(t) = min(t / gravity_ramp_time, 1) g (> 0 required)
  double cfl = 0.2;  // dt <= cfl * h / (c + |v|max); each physics sets its default and limit within (0, 2]
  double acceleration_safety = 0.25;  // dt <= acceleration_safety * sqrt(h / |a|max)
  double end_time = 1.0;  // [s]
  double output_interval = 0.1;  // [s] simulated time between frames / energy rows (<= 0: none)
  double checkpoint_interval_wall_s = 300.0;  // wall-clock seconds between checkpoints (<= 0: none)
  double blow_up_speed_factor = 1.0;  // stop if any speed > factor * max sound speed
  double blow_up_energy_factor = 10.0;  // stop if KE > factor * (released potential energy + elastic floor)

  double smoothing_length() const { return h_over_dx * particle_spacing; }
  // Fraction of the full gravity acting at simulated time t: 1, or min(t / gravity_ramp_time, 1) when ramped.
  // A function of the time alone, so a resumed run sees the same gravity as an uninterrupted one.
  double gravity_factor(double t) const;
  // Throws std::invalid_argument with a message naming the setting and the allowed range.
  void validate_engine() const;
};

}  // namespace sph
