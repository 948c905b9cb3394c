#pragma once
// Settings of the weakly compressible MPS method for granular flows (WC-MPS; Jafari Nodoushan, Shakibaeinia &
// Hosseini 2016; issue 12). SI units, 2-D. What every physics shares
// (dx, gravity, CFL factor, end time, output and checkpoint cadence, blow-up guard) comes from sph::EngineSettings.
// The MPS does not use the engine's SPH kernel or h: its weight w = (1 - r/r_e)^3 has its own radius r_e
// (re_over_dx below), and its neighbour search uses cells of side r_e. docs/mps.md lists the equations, the
// decisions on the seed's ambiguities A1-A24 and the source of every default below.
#include <string>

#include "sph/engine/settings.hpp"
#include "sphslope/names.hpp"

namespace sph::mps {

// How the exponential (Papanastasiou / Zhu et al. 2005) regularisation of Herschel-Bulkley is written (seed
// ambiguity A2; docs/mps.md "Rheology").
enum class Regularisation {
  // "as_printed": seed eq. 16 as printed, mu = tau_y (1 - exp(-m |D|)) / (2 |D|) + mu0 |D|^(N-1);
  // its zero-rate limit (N = 1) is mu0 + m tau_y / 2, not the mu0 + m tau_y the paper states
  as_printed,
  // "consistent" (default): mu = tau_y (1 - exp(-m gdot)) / gdot + mu0 gdot^(N-1) with gdot = 2 |D|; tends to the
  // ideal Herschel-Bulkley law of seed eq. 2 as m -> infinity and to the paper's mu0 + m tau_y at zero rate (N = 1)
  consistent,
};

// The viscosity of a pair in the stress divergence (seed section 6-2, Figs 8-9).
enum class InteractionViscosity {
  harmonic_mean,  // "harmonic_mean" (default): mu_ij = 2 mu_i mu_j / (mu_i + mu_j), eq. 22
  own,  // "own": mu_ij = mu_i (the paper's comparison; steeper deposits)
};

// The effective pressure p' of the yield stress tau_y = c cos(phi) + p' sin(phi) (seed section 2.9, Figs 6-7).
enum class EffectivePressure {
  smoothed,  // "smoothed" (the paper's): the Shepard average of the EOS pressure (eq. 20), clamped at 0
  // "hydrostatic": the weight of the material above, rho0 |g| (h + dx/2), h the depth of the particle's centre below
  // the highest moving particle's centre within dx in x (eqs. 18-19); + dx/2 because the surface is that particle's
  // top edge. Wall particles get the weight above them too (their viscosity is the floor's friction in the
  // harmonic mean). The paper's comparison: it ignores vertical accelerations
  hydrostatic,
  // "smoothed_thin_layer" (default): the smoothed p' where the particle's neighbourhood is complete; where it is not
  // (n_i < (1 - 1e-6) n0 at r^m, within about r_e of a free surface, where the EOS pressure is clipped to 0 and so
  // a layer up to three particles thick carries no yield stress), the larger of the smoothed p' and the hydrostatic
  // one. For the granular particles (their p' sets their yield stress). Not in the paper (docs/mps.md, section 7).
  smoothed_thin_layer,
};

// The pore pressure taken off p' for the granular particles (seed A6: the paper does not say how submerged
// sediment is treated).
enum class PorePressure {
  none,  // "none" (default; the paper as printed): p' of the sediment is the total pressure
  // "hydrostatic": p' - rho_w |g| (h + dx/2) clamped at 0 for the granular particles, h the depth of the particle's
  // centre below the highest moving particle (water or sediment) within dx in x, rho_w the water material's density:
  // the weight of the water column above and in the pores, so that a saturated bed carries its buoyant weight
  // (rho_b - rho_w) g h. Needs a water material.
  hydrostatic,
};

// The divergence of the viscous stress in the momentum equation (seed eqs. 22-23, Figs 10-11).
enum class StressDivergence {
  // "direct" (the paper's): eq. 22, the MPS Laplacian with the pair viscosity, (2d/(lambda n0)) sum mu_ij (u_j - u_i) w;
  // it is div(mu grad u), which is div(2 mu D) only where mu is uniform and the flow divergence-free: it carries
  // the simple-shear stress exactly, half the stress of a pure extension, and a rigid rotation in a viscosity
  // gradient feels a force (docs/mps.md, section 7)
  direct,
  // "indirect": eq. 23, the MPS gradient of each particle's stress tau = 2 mu D (the strain rate of eq. 17),
  // div tau = (d tau_xx/dx + d tau_xy/dy, d tau_xy/dx + d tau_yy/dy): div(2 mu D) for any viscosity field; the
  // paper reports fluctuations of viscosity and velocity with it
  indirect,
  // "full" (default): div(2 mu D) as a pair sum in the manner of eq. 22 (full_viscous_force): (2d/(lambda n0)) sum mu_ij
  // w_ij (du/2 + 2 (e . du) e), du = u_j - u_i, e = r_ij/|r_ij|; exact (to the lattice's isotropy) for a uniform
  // viscosity, divergence included; each pair's forces are equal and opposite and dissipate. Not in the paper
  // (docs/mps.md, section 7).
  full,
};

struct Settings : EngineSettings {
  // r_e = 4.0 dx: the value of the paper's code lineage for weakly compressible 2-D runs (seed 2.3 and A12; the
  // paper gives none). On the square lattice it gives n0 = 4.1983 and lambda = 2.7345 dx^2 and 44 neighbours;
  // 3.1 dx (n0 = 2.2414) is the seed's alternative. Below 2 dx the first ring alone carries the operators.
  static constexpr double default_re_over_dx = 4.0;
  static constexpr double min_re_over_dx = 2.0;
  static constexpr double max_re_over_dx = 6.0;  // beyond: > 108 neighbours per particle for no stated gain
  static constexpr double min_surface_beta = 0.80;  // the paper's range for beta (seed eq. 15)
  static constexpr double max_surface_beta = 0.99;

  Settings();

  double re_over_dx = default_re_over_dx;  // r_e / dx, the weight's support radius in spacings
  double rest_density = 1500.0;  // rho0 [kg/m^3] of the EOS prefactor (dry glass beads, phi0 = 0.6: A22)
  // c0 [m/s], the artificial sound speed; at least 10 x the largest flow speed (seed eq. 13-14; checked against the
  // flow when the run loop exists). 20 m/s: the code lineage's value, >= 10 x 2 sqrt(g h0) for both seed cases (A12)
  double sound_speed = 20.0;
  double tait_gamma = 7.0;  // Tait exponent (lost in the extraction; the standard 7, A11)
  double surface_beta = 0.92;  // free surface where n <= beta n0 (seed eq. 15; code lineage 0.92, A12)
  // cap of the effective viscosity [Pa s] (seed A3: mandatory, N < 1 makes mu0 |D|^(N-1) unbounded at rest); the
  // code lineage's 200 Pa s; its sensitivity is to be studied (issue 12, the stability matrix)
  double viscosity_cap = 200.0;
  Regularisation regularisation = Regularisation::consistent;  // A2
  // smoothed_thin_layer and full: this project's forms, the ones whose dry-collapse front converges (docs/mps.md
  // section 7); the paper's are "smoothed" and "direct"
  EffectivePressure effective_pressure = EffectivePressure::smoothed_thin_layer;
  PorePressure pore_pressure = PorePressure::none;  // A6
  StressDivergence stress_divergence = StressDivergence::full;
  InteractionViscosity interaction_viscosity = InteractionViscosity::harmonic_mean;
  // alpha of eqs. 28-29 (A23): the share of the pressure force taken at the new time level, "typically 0.5"
  double pressure_split = 0.5;
  // The pressure gradient of the stepper: false = the plain difference p_j - p_i of eq. 24 (as printed); true =
  // p_j - min(p_i, p_j over the neighbours) (Koshizuka & Oka 1996: every pair repels; docs/mps.md decision S3)
  bool pressure_gradient_minimum = true;
  // Collision of a moving particle with the wall and dummy particles (docs/mps.md decision S7): closer than
  // wall_collision_distance x dx and approaching, its normal velocity towards the wall particle is reversed times
  // wall_collision_restitution, and its position moved by the velocity change times dt. Where a layer thins to one
  // or two rows its particles and the wall particles under them are free-surface particles at pressure 0 and
  // nothing else holds them up. The distance must exceed 0.5 dx (the half-gap of the wall lattice) and stay below
  // 1 dx (the lattice contact); 0 turns it off. The paper has no collision model; its code lineage has one between
  // all particles (distance 0.5 dx, coefficient 0.5 [X], seed 2.13).
  double wall_collision_distance = 0.75;
  double wall_collision_restitution = 0.0;  // fully inelastic: the code lineage's coefficient 0.5 = (1 + e)/2 [I]
  // The gate (add_gate) rises at gate_lift_speed [m/s] from t = 0 until it has risen gate_lift_distance [m], then
  // stays there; speed 0: it stays where it is. The seed's collapse gate is "lifted vertically and quickly at speed
  // v_g", the value not given (A12: a few m/s).
  double gate_lift_speed = 0.0;
  double gate_lift_distance = 0.0;
  // How far the gate has risen at time t [m]: min(gate_lift_speed t, gate_lift_distance).
  double gate_rise(double t) const;
  // The engine's `cfl` (default 0.2) is the C_r of eq. 30 (the seed: 0.1-0.25); allowed (0, max_cfl] here.
  static constexpr double max_cfl = 1.0;

  double effective_radius() const { return re_over_dx * particle_spacing; }  // r_e [m]

  // The engine's checks (validate_engine), then the MPS's. Throws std::invalid_argument whose message names the
  // setting, its value and the allowed range.
  void validate() const;
};

// The names of each setting's choices in scene files and reports; the _from functions throw std::invalid_argument
// on other names, naming the allowed ones.
inline constexpr sphslope::NameTable<Regularisation, 2> regularisation_names{
    {{"as_printed", Regularisation::as_printed}, {"consistent", Regularisation::consistent}}};
inline constexpr sphslope::NameTable<InteractionViscosity, 2> interaction_viscosity_names{
    {{"harmonic_mean", InteractionViscosity::harmonic_mean}, {"own", InteractionViscosity::own}}};
inline constexpr sphslope::NameTable<EffectivePressure, 3> effective_pressure_names{
    {{"smoothed", EffectivePressure::smoothed},
     {"hydrostatic", EffectivePressure::hydrostatic},
     {"smoothed_thin_layer", EffectivePressure::smoothed_thin_layer}}};
inline constexpr sphslope::NameTable<PorePressure, 2> pore_pressure_names{
    {{"none", PorePressure::none}, {"hydrostatic", PorePressure::hydrostatic}}};
inline constexpr sphslope::NameTable<StressDivergence, 3> stress_divergence_names{
    {{"direct", StressDivergence::direct}, {"indirect", StressDivergence::indirect}, {"full", StressDivergence::full}}};

Regularisation regularisation_from(const std::string& key);
const char* regularisation_key(Regularisation r);
EffectivePressure effective_pressure_from(const std::string& key);
const char* effective_pressure_key(EffectivePressure p);
PorePressure pore_pressure_from(const std::string& key);
const char* pore_pressure_key(PorePressure p);
StressDivergence stress_divergence_from(const std::string& key);
const char* stress_divergence_key(StressDivergence s);
InteractionViscosity interaction_viscosity_from(const std::string& key);
const char* interaction_viscosity_key(InteractionViscosity v);

// The sound-speed rule c0 >= 10 |u|max (seed section 4-2): empty when it holds, else a message naming
// sound_speed, the flow speed and the least c0 that satisfies it.
std::string sound_speed_problem(double c0, double u_max);

}  // namespace sph::mps
