#pragma once
// Settings of the explicit three-step incompressible SPH (ISPH) fluid (Hosseini, Manzari & Hannani 2007, as used
// by the seed paper, Hosseini Mobarra & Ghobadian 2020). SI units, 2-D. What every physics shares (kernel,
// dx, h/dx and its range, gravity and its ramp, CFL factor, end time, output and checkpoint cadence, blow-up guard)
// comes from sph::EngineSettings; this struct adds the fluid's options and its own defaults for two engine
// settings (h = 1.5 dx and CFL 0.1, the seed's values; the Wendland C2 kernel, decision D16). docs/isph.md lists the
// equations, the decisions where the paper is wrong or silent, and every default below with its source.
#include <limits>
#include <string>

#include "sph/engine/settings.hpp"
#include "sphslope/names.hpp"

namespace sph::fluid {

// How the pressure Poisson equation (seed eq. 35) is solved each step.
enum class PressureMode {
  explicit_jacobi,  // "explicit": one point-Jacobi sweep from the previous step's pressures (seed eq. 37)
  iterative,  // "iterative": the same discrete equation solved to `solver_tolerance` (Eigen CG or BiCGSTAB)
};

enum class LinearSolver { conjugate_gradient, bicgstab };

// The preconditioner of the Krylov solve: the diagonal (Jacobi), or one V-cycle of aggregation multigrid (its
// iteration count does not grow with the particle count; docs/isph.md section 3).
enum class Preconditioner { diagonal, multigrid };

struct Settings : EngineSettings {
  static constexpr double default_h_over_dx = 1.5;  // h = 1.5 dx (seed, dam break)
  static constexpr double default_cfl = 0.1;  // seed eq. 48 (Shao & Lo 2003)
  static constexpr double max_cfl = 0.5;      // at most half a spacing per step (the engine allows each physics (0, 2])
  // Wendland C2, not the seed's cubic spline: at h = 1.5 dx the spline puts the nearest neighbours at the
  // inflection of W (q = 2/3) and a checkerboard displacement of the particles grows (decision D16)
  static constexpr KernelType default_kernel = KernelType::wendland_c2;

  Settings();

  double rest_density = 1000.0;  // rho0 [kg/m^3]
  double viscosity = 1.0e-3;  // dynamic viscosity mu [Pa s] (water at 20 C; the seed's 1e-4 is doubted, A10)
  double eta_over_h = 0.1;  // eta = 0.1 h in the Laplacians (seed eqs. 9, 22, 36)
  // free surface where the normalised kernel-sum density < beta rho0 (seed eq. 43, beta in 0.8-0.9; decision D4)
  double surface_beta = 0.9;
  bool surface_mirror = false;  // seed eq. 46: double the pressure gradient at free-surface particles (D6)
  bool compression_correction = false;  // add the kernel-sum compression to rho* (D3; false: eq. 32 as printed)

  // time step: dt = min(cfl dx / v_max, cfl sqrt(dx/|g|), viscous_alpha dx^2 rho0 / mu, max_time_step), with the
  // engine's `cfl` (default 0.1 here)
  double viscous_alpha = 0.1;  // seed eq. 49
  double max_time_step = 0.0;  // [s] an upper bound of the user's (0: none)

  PressureMode pressure_mode = PressureMode::iterative;
  LinearSolver solver = LinearSolver::conjugate_gradient;
  Preconditioner preconditioner = Preconditioner::multigrid;
  double solver_tolerance = 1.0e-8;  // relative residual |b - M p| / |b| of the iterative mode (D10)
  int solver_max_iterations = 2000;
  // iterative mode: solves of the fluid's equation per step, each after a new wall-pressure extrapolation (the
  // explicit mode does one extrapolation and one sweep)
  int wall_passes = 2;
  // the relative residual of the solves before the last one of a step, which only update the walls' pressures
  // (decision D22; at 1e-3 the dam break's front at 0.5 s moves by 9 %, at 1e-4 by 0.6 %)
  double wall_pass_tolerance = 1.0e-4;

  // false: the unknowns' negative pressures are set to 0 after each solve (no tension, decision D21); true: the
  // pressure equation's solution as it is
  bool tension = false;
  // The nearest a fluid particle's centre may come to a wall or body particle's, as a fraction of the spacing
  // (decision D23): closer at the end of a step, it is moved out along the walls' normal to this distance and its
  // velocity into the wall removed. 0 turns it off. At rest the fluid is one spacing from the walls' first row.
  double wall_clearance = 0.5;
  static constexpr double max_wall_clearance = 1.0;  // [spacings], excluded

  int wall_layers = 3;

  // The domain: fluid particles that leave it are removed (the seed paper deletes them; docs/isph.md D11) [m].
  // Unbounded by default.
  double domain_x_min = -std::numeric_limits<double>::infinity();
  double domain_x_max = std::numeric_limits<double>::infinity();
  double domain_y_min = -std::numeric_limits<double>::infinity();
  double domain_y_max = std::numeric_limits<double>::infinity();  // fixed wall particle rows (seed: 3); at least ceil(2h/dx)

  double eta() const { return eta_over_h * smoothing_length(); }
  double particle_mass() const { return rest_density * particle_spacing * particle_spacing; }  // [kg/m]

  // The engine's checks (validate_engine), then the fluid's. Throws std::invalid_argument naming the first
  // setting out of its range.
  void validate() const;
};

// The names of the choices in scene files and reports; the _from functions throw std::invalid_argument on other
// names, naming the allowed ones.
inline constexpr sphslope::NameTable<PressureMode, 2> pressure_mode_names{
    {{"explicit", PressureMode::explicit_jacobi}, {"iterative", PressureMode::iterative}}};
inline constexpr sphslope::NameTable<LinearSolver, 2> linear_solver_names{
    {{"cg", LinearSolver::conjugate_gradient}, {"bicgstab", LinearSolver::bicgstab}}};
inline constexpr sphslope::NameTable<Preconditioner, 2> preconditioner_names{
    {{"diagonal", Preconditioner::diagonal}, {"multigrid", Preconditioner::multigrid}}};

PressureMode pressure_mode_from(const std::string& key);
const char* pressure_mode_key(PressureMode mode);
LinearSolver linear_solver_from(const std::string& key);
const char* linear_solver_key(LinearSolver solver);
Preconditioner preconditioner_from(const std::string& key);
const char* preconditioner_key(Preconditioner preconditioner);

}  // namespace sph::fluid
