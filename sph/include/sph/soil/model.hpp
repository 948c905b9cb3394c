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
#include "sph/engine/settings.hpp"
#include "sph/engine/stepper.hpp"
#include "sph/soil/fields.hpp"
#include "sph/soil/loads.hpp"

namespace sph::soil {

enum class WallSlip {
  no_slip,     // wall ghost velocity = -(Shepard average of neighbouring soil velocity)
  free_slip,   // wall ghost velocity = soil average mirrored in the wall normal (tangential part kept)
  frictional,  // free-slip ghosts, and Coulomb friction tan(delta) times the walls' normal push on each soil
               // particle, against its sliding (Settings::wall_friction_angle_deg; docs/sph.md, "Walls")
};
// The conditions' names in scene files (analyses.sph.walls.slip).
inline constexpr sphslope::NameTable<WallSlip, 3> wall_slip_names{
    {{"no_slip", WallSlip::no_slip}, {"free_slip", WallSlip::free_slip}, {"frictional", WallSlip::frictional}}};

enum class ArtificialStressMode { off, on, automatic /* on iff some plastic material has cohesion > 0 */ };
// The modes' names in scene files (analyses.sph.artificial_stress.mode).
inline constexpr sphslope::NameTable<ArtificialStressMode, 3> artificial_stress_mode_names{
    {{"auto", ArtificialStressMode::automatic}, {"on", ArtificialStressMode::on}, {"off", ArtificialStressMode::off}}};

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

// The time integration of the soil model (sph/src/soil/soil_step.cpp; docs/sph.md, "Time step").
enum class TimeIntegration {
  predictor_corrector,  // one rate evaluation per step, rates of the predicted state (Bui et al. 2008)
  verlet,               // kick-drift-kick (Stormer-Verlet): kinematic rates at the half-step velocity, then forces
};
// The time integrations' names in scene files and reports.
inline constexpr sphslope::NameTable<TimeIntegration, 2> time_integration_names{
    {{"predictor_corrector", TimeIntegration::predictor_corrector}, {"verlet", TimeIntegration::verlet}}};

// The default and the largest accepted cfl of each time integration (docs/sph.md, "Time step"). Verlet: the dispersion
// relation of the SPH operators bounds the step at cfl ~ 2.0 (h omega_max / c_P = 1.06-1.14 for both kernels and
// h/dx in [1, 2]); the default 0.8 is the largest at which the granular-collapse series is converged in the step
// (with 16 stress sub-steps; at 1.2 and 1.6 the a = 4 run-out moves 3 % further, docs/accuracy.md). Predictor-corrector: unstable for undamped waves at any step, held
// by the artificial viscosity up to cfl 0.7-0.8 on the column collapse; Bui et al. (2008) used 0.2.
double default_cfl(TimeIntegration integration);
double max_cfl(TimeIntegration integration);
// The default stress sub-step count of each time integration (Settings::stress_substeps; docs/sph.md, "Time step"):
// verlet 16, the predictor-corrector 1 (it takes no sub-steps).
int default_stress_substeps(TimeIntegration integration);

// The kernel gradient of the pair sums. standard: grad_i W_ij. corrected: B_i grad_i W_ij with
// B_i = (sum_j V_j (x_j - x_i) (x) grad_i W_ij)^-1 (Randles & Libersky 1996; Bonet & Lok 1999), so the velocity
// gradient, the continuity sum and the stress divergence are exact for linear fields; the momentum sum stays
// antisymmetric in i and j (linear momentum conserved). Only where the support is nearly full (the moment matrix
// M_i = B_i^-1 has its smaller eigenvalue at least 0.8, against 1 inside and 0.5 at a free surface) is B_i used;
// elsewhere the standard gradient is kept: corrected free-surface particles (down to 0.25) blew up the granular
// collapse at its front (non-positive density) and changed nothing in the elastic column (docs/accuracy.md).
enum class KernelGradient { standard, corrected };
// The kernel gradients' names in scene files and reports.
inline constexpr sphslope::NameTable<KernelGradient, 2> kernel_gradient_names{
    {{"standard", KernelGradient::standard}, {"corrected", KernelGradient::corrected}}};

struct Xsph {
  bool enabled = false;
  double chi = 0.5;  // Monaghan (2002)
};

// The soil model's settings: the engine's (sph/engine/settings.hpp) and the soil's options.
struct Settings : EngineSettings {
  ArtificialViscosity viscosity;
  ArtificialStress artificial_stress;
  Xsph xsph;
  KernelGradient kernel_gradient = KernelGradient::standard;
  WallSlip wall_slip = WallSlip::no_slip;
  double wall_friction_angle_deg = 0.0;  // delta of WallSlip::frictional, in [0, 90) [deg]; 0 with the others
  double damping = 0.0;          // optional linear velocity damping [1/s] (a -= damping * v), 0 = none
  // The default is the sub-stepped Verlet step (docs/sph.md, "Time step": the predictor-corrector at its default
  // step runs a granular collapse about 9 % further than at a step eight times smaller).
  TimeIntegration integration = TimeIntegration::verlet;
  // The Verlet step's stress update in up to this many equal sub-steps, each with its own stress rate and return
  // from the step's velocity gradient (docs/sph.md, "Time step": one return per step lets a granular flow run further
  // as the step grows); a particle that stays elastic takes one, a yielding one as many as its strain increment
  // needs (SoilStep::update_stress_in_substeps). 1 = one update per step. Only with the verlet integration.
  int stress_substeps = default_stress_substeps(TimeIntegration::verlet);

  Settings() { cfl = default_cfl(integration); }

  // Selects a time integration with its default cfl and stress sub-step count.
  void use_integration(TimeIntegration chosen) {
    integration = chosen;
    cfl = default_cfl(chosen);
    stress_substeps = default_stress_substeps(chosen);
  }

  // The engine's checks, then the soil's.
  void validate() const;
};

struct Model {
  ParticleSet particles;
  SoilFields fields = SoilFields::register_in(particles);  // the soil's state block in `particles`
  std::vector<Material> materials;
  Settings settings;
  SoilLoads loads;  // pore water, seismic, surface forces (none by default); the stress is effective with water
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

}  // namespace sph::soil
