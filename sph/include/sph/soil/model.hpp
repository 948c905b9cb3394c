#pragma once
// Model = particles + materials + numerical settings + run state (time, step, output bookkeeping).
// The caller (coupling layer) builds particles with fill.hpp, sets materials and settings, then calls run().
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sph/engine/kernel.hpp"
#include "sph/soil/material.hpp"
#include "sph/engine/particle_set.hpp"
#include "sph/engine/stepper.hpp"
#include "sph/soil/fields.hpp"

namespace sph {

enum class GravityMode {
  sudden,        // zero initial stress, full gravity from t = 0 (the thesis)
  geostatic_k0,  // sigma_yy = -rho g depth below the local free surface, sigma_xx = sigma_zz = K0 sigma_yy
  ramped,        // zero initial stress, gravity grows linearly from 0 to full over gravity_ramp_time
};

enum class WallSlip {
  no_slip,    // wall ghost velocity = -(Shepard average of neighbouring soil velocity)
  free_slip,  // wall ghost velocity = soil average mirrored in the wall normal (tangential part kept)
};

enum class ArtificialStressMode { off, on, automatic /* on iff some plastic material has cohesion > 0 */ };

struct ArtificialViscosity {
  double alpha = 0.1;  // Monaghan alpha_Pi (Bui et al. 2008 used 0.1 for soil)
  double beta = 0.2;   // Monaghan beta_Pi
  double eta_factor = 0.01;  // eta^2 = eta_factor h^2
};

struct ArtificialStress {
  ArtificialStressMode mode = ArtificialStressMode::automatic;
  double epsilon = 0.5;   // Gray, Monaghan & Swift (2001); Bui et al. (2008) used 0.5
  double exponent = 2.55; // n in f_ij^n, f_ij = W(r_ij)/W(dx)
};

struct Xsph {
  bool enabled = false;
  double chi = 0.5;  // Monaghan (2002)
};

struct Settings {
  KernelType kernel = KernelType::cubic_spline;
  double particle_spacing = 0;   // dx [m] (required; lattice spacing used to build the bodies)
  double h_over_dx = 1.2;        // smoothing length h = h_over_dx * dx
  ArtificialViscosity viscosity;
  ArtificialStress artificial_stress;
  Xsph xsph;
  double gravity_x = 0.0, gravity_y = -9.81;  // [m/s^2]
  GravityMode gravity_mode = GravityMode::sudden;
  double gravity_ramp_time = 0.0;  // [s] ramped mode: g(t) = min(t / gravity_ramp_time, 1) g (> 0 required)
  WallSlip wall_slip = WallSlip::no_slip;
  double damping = 0.0;          // optional linear velocity damping [1/s] (a -= damping * v), 0 = none
  double cfl = 0.2;              // dt <= cfl * h / (c + |v|max)
  double acceleration_safety = 0.25;  // dt <= acceleration_safety * sqrt(h / |a|max)
  double end_time = 1.0;         // [s]
  double output_interval = 0.1;  // [s] simulated time between frames / energy rows (<= 0: none)
  double checkpoint_interval_wall_s = 600.0;  // wall-clock seconds between checkpoints (<= 0: none)
  double blow_up_speed_factor = 1.0;  // stop if any speed > factor * max sound speed
  double blow_up_energy_factor = 10.0;  // stop if KE > factor * (released potential energy + elastic floor)

  double smoothing_length() const { return h_over_dx * particle_spacing; }
  // Fraction of the full gravity acting at simulated time t: 1, or min(t / gravity_ramp_time, 1) when ramped.
  // A function of the time alone, so a resumed run sees the same gravity as an uninterrupted one.
  double gravity_factor(double t) const;
  // Throws std::invalid_argument with a message naming the setting and the allowed range.
  void validate() const;
};

struct Model {
  ParticleSet particles;
  SoilFields fields = SoilFields::register_in(particles);  // the soil's state block in `particles`
  std::vector<Material> materials;
  Settings settings;
  RunState state;

  // Validates settings, materials and particles (material ids in range, positive masses, ...).
  void validate() const;
  bool uses_artificial_stress() const;
  SoilArrays soil() { return SoilArrays(particles, fields); }
  ConstSoilArrays soil() const { return ConstSoilArrays(particles, fields); }
};

// Time step of the model at rest (the CFL bound of SoilStep::stable_time_step with |v| = 0, |a| = 0):
// cfl h / (c_max (1 + 1.2 alpha)), c_max the largest P-wave speed of the materials. Use it to plan runs.
double time_step_estimate(const Model& model);

// Upper estimate of the memory (bytes) needed to simulate n particles (the registered arrays of a soil model and
// its step workspace, neighbour search, output buffers). Use it to refuse a case before allocating.
std::size_t estimate_memory_bytes(std::size_t n_particles);

}  // namespace sph
