#pragma once
// The discrete pressure Poisson equation of the ISPH fluid (seed eqs. 35-37) and its two solvers: one explicit
// point-Jacobi sweep (the paper's scheme) and an Eigen Krylov solve (CG or BiCGSTAB) to a stated tolerance.
//
// For every particle i that is an unknown:   sum_j B_ij (P_i - P_j) = s_i,
// B_ij <= 0 the Laplacian coefficients of seed eq. 36 and s_i = (rho0 - rho*_i)/(rho0 dt^2) (eq. 35). The other
// particles hold given pressures: free-surface particles P = 0 (Dirichlet), wall particles the pressure the stepper
// extrapolates to them from the fluid (decision D7 in docs/isph.md).
#include <cstdint>
#include <memory>
#include <vector>

#include "sph/fluid/settings.hpp"

namespace sph::fluid {

enum class PressureRole : std::uint8_t { unknown = 0, given = 1 };

struct PoissonSystem {
  std::vector<std::uint32_t> start;  // per particle (n + 1), as in the pair list
  std::vector<std::uint32_t> col;  // neighbour particle
  std::vector<double> coef;  // B_ij
  std::vector<double> source;  // s_i
  std::vector<PressureRole> role;
  // positions of the particles (for the multigrid preconditioner's aggregates; may be empty otherwise) [m]
  std::vector<double> x, y;
  double aggregate_size = 0;  // the width of the first level's aggregation cells [m] (2 dx)
  std::size_t size() const { return role.size(); }
};

struct SolveReport {
  int iterations = 0;  // Krylov iterations (explicit mode: 1 sweep)
  double relative_residual = 0;  // |b - M p| / |b| over the unknowns after the solve
  bool converged = true;  // iterative: the tolerance was reached within the iteration limit
  std::size_t unknowns = 0;
  int multigrid_levels = 0;
  bool fell_back = false;  // the multigrid-preconditioned solve failed; the diagonal preconditioner solved it  // levels of the multigrid preconditioner (0: diagonal preconditioner or explicit)
};

// One Jacobi sweep (seed eq. 37) from the pressures in `pressure` (the previous step's unknowns, the given values);
// writes the unknowns' new pressures, keeps the given ones.
SolveReport jacobi_sweep(const PoissonSystem& system, std::vector<double>& pressure);

// How the iterative mode solves: Eigen's CG or BiCGSTAB with a preconditioner, to a relative residual.
struct SolverChoice {
  LinearSolver solver = LinearSolver::conjugate_gradient;
  Preconditioner preconditioner = Preconditioner::multigrid;
  double tolerance = 1e-8;
  int max_iterations = 2000;
};

// The iterative mode's solver of one step: the matrix and its preconditioner set up once (prepare), then solved
// for as many right-hand sides as the step has wall passes (the walls' given pressures change between them, the
// matrix does not).
class PressureSolver {
 public:
  PressureSolver();
  ~PressureSolver();
  PressureSolver(const PressureSolver&) = delete;
  PressureSolver& operator=(const PressureSolver&) = delete;
  // Numbers the unknowns, assembles the matrix and sets the preconditioner up.
  void prepare(const PoissonSystem& system, const SolverChoice& choice);
  // Solves with the system's current sources and the given values held in `pressure` (the unknowns' values there
  // are the first guess) to `tolerance` (0: the choice's); a multigrid-preconditioned solve that fails is done
  // again with the diagonal one.
  SolveReport solve(const PoissonSystem& system, std::vector<double>& pressure, double tolerance = 0.0);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Solves the system to `tolerance` (relative residual |b - M p| / |b|), starting from `pressure` (which also holds
// the given values). CG needs the symmetric matrix that equal particle masses give (every particle rho0 dx^2). The
// multigrid preconditioner needs the system's positions and aggregate size.
SolveReport solve_pressure(const PoissonSystem& system, const SolverChoice& choice, std::vector<double>& pressure);

// |b - M p| / |b| of a pressure field (the explicit mode's remaining error).
double relative_residual(const PoissonSystem& system, const std::vector<double>& pressure);

}  // namespace sph::fluid
