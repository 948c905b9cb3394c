#pragma once
// One time step of the elasto-plastic soil SPH (Bui et al. 2008), assembled once from the model settings.
//
// Integration (second order, one rate evaluation per step; "velocity Verlet with predicted rates"):
//   half:      v_h = v + dt/2 a,   rho_h = rho + dt/2 drho,   sigma_h = sigma + dt/2 dsigma
//   drift:     x  += dt v_h
//   predict:   v* = v + dt a, rho* = rho + dt drho, sigma* = R(sigma + dt dsigma)     (R = return to yield)
//   evaluate:  sort by cell, wall extrapolation, rates a, drho, dsigma at (x, v*, rho*, sigma*)
//   correct:   v = v_h + dt/2 a,  rho = rho_h + dt/2 drho,  sigma = R(sigma_h + dt/2 dsigma)
// The rates of the evaluation are kept with the particles (and in checkpoints) for the next step.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sph/engine/stepper.hpp"
#include "sph/soil/model.hpp"
#include "sph/engine/neighbour_search.hpp"

namespace sph::soil {

class SoilStep : public Stepper {
 public:
  // Validates the model, derives material constants and allocates all work arrays.
  explicit SoilStep(Model& model);
  ~SoilStep() override;
  SoilStep(const SoilStep&) = delete;
  SoilStep& operator=(const SoilStep&) = delete;

  // Prepares the state at the current time: applies the geostatic stress (once, if requested),
  // sorts particles by cell and evaluates the rates if the model does not carry valid rates.
  void initialise() override;

  // Stable time step from the current rates: min(cfl h / (c(1 + 1.2 alpha) + |v|max (1 + 2.4 beta)),
  // acceleration_safety sqrt(h / |a|max)).
  double stable_time_step() const override;

  // Advances the model by dt (time and step counter included).
  void advance(double dt) override;

  Energies energies() const override;
  Health check_health() const override;  // NaN/Inf in soil fields, speed above blow_up_speed_factor * c
  std::vector<DerivedField> derived_outputs() const override;  // pressure = -I1/3 [Pa] for the frames

  double smoothing_length() const { return h_; }
  double max_sound_speed() const { return c_max_; }
  const std::vector<MaterialConstants>& material_constants() const { return mc_; }
  bool artificial_stress_enabled() const { return artificial_stress_; }

  // Evaluates the rates at the current state without advancing (sort + walls + rates), with the gravity of the
  // current time (evaluate) or of the given time (evaluate_at; ramped gravity).
  void evaluate();
  void evaluate_at(double time);

  // Sets sigma_yy = -g sum(rho dx) over the soil above each particle in its lattice column,
  // sigma_xx = sigma_zz = K0 sigma_yy. Requires gravity along -y.
  void apply_geostatic_stress();

  struct Impl;

  // Registers the stepper's workspace arrays (half-step values) in a particle set, or finds them; with `impl`,
  // records their ids there. Public so that the memory estimate counts them.
  static void register_workspace(ParticleSet& particles, Impl* impl = nullptr);

 private:
  void advance_predictor_corrector(double dt);
  void advance_verlet(double dt);
  void update_stress_in_substeps(const SoilArrays& sa, std::size_t i, double dt, int n_max) const;

  Model& model_;
  double h_ = 0;
  double c_max_ = 0;
  bool artificial_stress_ = false;
  std::vector<MaterialConstants> mc_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph::soil
