#pragma once
// One time step of the explicit three-step ISPH (Hosseini, Manzari & Hannani 2007; seed paper section 2-6):
//   1  V*  = V^n + g dt                                      body force (eqs. 24-25)
//   2  V** = V* + dt (mu/rho lap V*)                         viscous step (eqs. 22, 26-28)
//      r*  = r^n + V** dt                                    temporary positions (eqs. 29-30)
//      rho* = rho0 + dt sum m_j V**_ij . grad W (eq. 32); free surface by the kernel-sum density
//   3  sum_j B_ij (P_i - P_j) = (rho0 - rho*_i)/(rho0 dt^2)  pressure (eqs. 35-37: one Jacobi sweep, or solved)
//      V^{n+1} = V** - dt sum m_j (P_i/rho*_i^2 + P_j/rho*_j^2) grad W   correction (eqs. 38-40, 46)
//      r^{n+1} = r^n + dt/2 (V^n + V^{n+1})                  trapezoidal rule (eqs. 31, 41-42)
//      rigid bodies moved (prescribed or by gravity and the fluid's pressure force); fluid that left the domain removed
// Wall particles are fixed (velocity 0), belong to a rigid body (its velocity) or to another physics of a coupled run
// (coupled_wall_material: the velocity the coupling gives them), and take part in the continuity
// sums and the viscous term (no-slip); their pressure is extrapolated from the fluid with the hydrostatic difference
// (and the body's acceleration) and enters the fluid's pressure equation and gradient as a given value.
// docs/isph.md gives the decisions.
#include <functional>
#include <memory>
#include <vector>

#include "sph/engine/stepper.hpp"
#include "sph/fluid/model.hpp"
#include "sph/fluid/pressure.hpp"

namespace sph::fluid {

// What the last step did (for reports and tests).
struct StepDiagnostics {
  SolveReport solve;  // the last solve of the step
  int solve_iterations = 0;  // Krylov iterations of all the step's solves
  int fallbacks = 0;  // solves of the step the diagonal preconditioner finished (SolveReport::fell_back)
  double max_density_error = 0;  // max over fluid of |rho* - rho0| / rho0
  double mean_density_error = 0;  // mean over fluid of |rho* - rho0| / rho0
  std::size_t surface_particles = 0;
  std::size_t wall_passes = 0;  // wall extrapolations + solves of the last step
  double time_step = 0;
  std::size_t removed_particles = 0;  // fluid particles that left the domain in the last step
  std::size_t tension_clamped = 0;  // unknowns whose negative pressure was set to 0 in the last solve (D21)
  std::size_t wall_contacts = 0;  // fluid particles the last step put back at the wall clearance (D23)
  std::vector<double> body_force_x, body_force_y;  // the fluid's pressure force on each rigid body [N/m]
  // The fluid's pressure force on each coupled wall particle (coupled_wall_material) in excess of the force the
  // reference pressure (Step::set_reference_pressure) gives, by particle index [N/m]; 0 at other particles; empty
  // when the model has no coupled walls or no reference is set.
  std::vector<double> coupled_force_x, coupled_force_y;
};

class Step : public Stepper {
 public:
  explicit Step(Model& model);
  ~Step() override;
  Step(const Step&) = delete;
  Step& operator=(const Step&) = delete;

  void initialise() override;
  // min(cfl dx / v_max, cfl sqrt(dx/|g|), viscous_alpha dx^2 rho0/mu, max_time_step) (eqs. 48-49 + a body-force
  // limit for the start from rest).
  double stable_time_step() const override;
  void advance(double dt) override;
  Energies energies() const override;
  Health check_health() const override;

  const StepDiagnostics& diagnostics() const { return diag_; }

  // A coupled run's reference pressure field p_ref(x, y) [Pa] (the water table's hydrostatic pressure, which the
  // other physics carries itself): each step then gives, in diagnostics().coupled_force_x/y, the reaction of the
  // pressure-gradient pair forces on each coupled wall particle with P - p_ref in place of P (at r*, as the bodies'
  // force, D19). Empty: none.
  void set_reference_pressure(std::function<double(double x, double y)> reference) { reference_ = std::move(reference); }

  struct Impl;

 private:
  double gravity_x() const;
  double gravity_y() const;
  void list_candidates();
  bool moved_beyond_half_skin() const;
  void viscous_step(double dt);
  void provisional_density(double dt);
  void moment_matrices();
  void renormalised_gradient(std::size_t i, const double* f, double& gx, double& gy) const;
  void mark_roles();
  void extrapolate_wall_pressure();
  void mark_dry_walls();
  void assemble_pressure_equation(double dt);
  void add_consistency_term();
  void solve_pressure_equation(double dt);
  void clamp_tension(std::vector<double>& pressure);
  void correct(double dt);
  void finish_positions(double dt);
  void body_forces();
  void coupled_wall_forces();
  void move_bodies(double dt);
  void keep_off_walls();
  void remove_escaped();
  bool is_body(std::size_t i) const;

  Model& model_;
  StepDiagnostics diag_;
  std::function<double(double, double)> reference_;  // set_reference_pressure
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph::fluid
