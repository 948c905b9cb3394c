#pragma once
// One time step of the WC-MPS (seed 2.11, eqs. 27-30), on the engine's Stepper interface:
//   a  the neighbours within r_e at r^m (below)
//   b  p' = Shepard-smoothed p^m (eq. 20, clamped >= 0) or the hydrostatic weight above (eqs. 18-19), or the
//      smoothed p' with the weight above as its floor where the neighbourhood is incomplete (the setting
//      effective_pressure), the strain rate D (eq. 17)
//   c  mu_i: the material's constant viscosity (water) or the capped regularised Herschel-Bulkley law (granular)
//   d  <div tau>^m (eq. 22, or eq. 23 with stress_divergence indirect) and <grad p>^m (eq. 24)
//   e  u* = u^m + (dt/rho_i)(rho_i g + <div tau>^m - (1 - alpha) <grad p>^m) (eq. 28), rho_i the particle's phase
//      density (eqs. 25-26); r* = r^m + u* dt
//   f  the neighbours within r_e at r*; n*; the mixture density <rho> (seed 2.10); p^{m+1} = Tait(n*) with the
//      prefactor <rho> c0^2 / gamma, 0 at the free surface n* <= beta n0 (eqs. 13, 15)
//   g  u^{m+1} = u* - alpha (dt/rho_i) <grad p>^{m+1} (eqs. 27, 29)
//   h  r^{m+1} = r^m + u^{m+1} dt (A24)
//   i  collision with the wall particles: a moving particle closer than wall_collision_distance dx to a wall or
//      dummy particle and approaching it (relative to its velocity) loses (1 + e) times its normal velocity towards
//      it (docs/mps.md, S7)
// Wall particles (kind wall) are fixed, at zero velocity (no-slip), but for the gate's, which rise as
// Settings::gate_rise says (at r* and r^{m+1} at the new height, their velocity the rise over dt); the layer next to
// the flow carries the EOS pressure of its own number density, the outer (dummy) layers only complete the number
// density and the viscous sums (pressure 0, out of the pressure gradient). docs/mps.md gives the decisions.
// Neighbour lists: every pass reads the list of the pairs within r_e at the current positions with their weights
// w_ij, refreshed at r^m and at r* from a list of candidates within r_e + s (s = list_skin dx). The candidates are
// listed again, after a sort by cells of side r_e + s, only when a particle has moved more than s/2 since they
// were listed (then no pair within r_e can be missing). The listing positions are part of the checkpoint: a
// resumed run lists the same candidates in the same order and continues bit for bit.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "sph/engine/stepper.hpp"
#include "sph/mps/model.hpp"
#include "sph/mps/operators.hpp"

namespace sph::mps {

class Step : public Stepper {
 public:
  explicit Step(Model& model);
  ~Step() override;
  Step(const Step&) = delete;
  Step& operator=(const Step&) = delete;

  void initialise() override;
  // eq. 30: C_r min(dx/(c0 + |u|max), rho0 dx^2/(2 d mu_max)), |u|max and mu_max = max mu_i rho0/rho_i over the
  // moving particles (and
  // |u|max at least the gate's speed while it rises).
  double stable_time_step() const override;
  void advance(double dt) override;
  Energies energies() const override;
  Health check_health() const override;
  // log10_viscosity = log10 of each particle's viscosity [log10(Pa s)] for the frames (a viscosity spanning orders of
  // magnitude, seed Fig. 14); -inf where the viscosity is 0.
  std::vector<DerivedField> derived_outputs() const override;

  const LatticeConstants& lattice() const { return lattice_; }
  // How often the candidates were listed (each time after a sort) since this stepper was made.
  std::uint64_t candidate_listings() const;
  // The pairs within r_e with their weights w_ij as the last step left them: listed at r*, in the particles' order
  // (for checks: n* of the step is each particle's sum of them).
  const NeighbourList& pairs_at_predicted_positions() const;

  struct Impl;

 private:
  Neighbourhood neighbourhood() const;
  void list_neighbours(bool number_density = false);
  void list_candidates();
  void near_fixed_particles();
  void relist_candidates_at_stored_positions();
  bool moved_beyond_half_skin() const;
  double skin() const;
  void viscosities();
  void depths_below_surface();
  void hydrostatic_pressures();
  double weight_above(std::size_t i, double h) const;
  void surface_strips();
  double thin_layer_pressure(std::size_t i, const PressureAndStrainRate& ps) const;
  double pore_pressure(std::size_t i) const;
  void mixture_densities();
  std::size_t material_of(std::size_t i) const;
  void predict(double dt);
  void equation_of_state();
  void correct(double dt);
  void collide_with_walls(double dt);
  PressureAndStrainRate pressure_and_strain_rate(std::size_t i, bool hydrostatic, bool needs_rate) const;
  double gradient_base(std::size_t i, const double* p) const;
  Vector2 pressure_gradient(std::size_t i, const double* p) const;
  struct Forces {
    Vector2 viscous;  // [N/m^3]
    Vector2 pressure_gradient;  // [Pa/m]
  };
  template <bool Full>
  Forces viscous_and_pressure_forces(std::size_t i, const double* p) const;
  double gate_rise(double dt) const;
  double gravity_x() const;
  double gravity_y() const;

  Model& model_;
  LatticeConstants lattice_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph::mps
