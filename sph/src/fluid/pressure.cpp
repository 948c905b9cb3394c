#include "sph/fluid/pressure.hpp"

// g++ 12 reports a false "may be used uninitialized" inside its own AVX-512 intrinsics (avx512fintrin.h,
// _mm512_undefined_pd) when Eigen's conjugate gradient is compiled for an AVX-512 CPU (x86-64-v4); the warning is
// silenced for this file only (docs/reliability.md).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <utility>

#include "multigrid.hpp"
#include "terms.hpp"

namespace sph::fluid {

namespace {

using Index = std::int64_t;
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
constexpr std::uint32_t kNone = 0xffffffffu;

// Row i of the equation as sums: S_B = sum_j B_ij, S_BP = sum_j B_ij P_j (unknowns and given values alike).
void row_sums(const PoissonSystem& s, std::size_t i, const std::vector<double>& p, double& sum_b, double& sum_bp) {
  sum_b = 0;
  sum_bp = 0;
  for (std::uint32_t k = s.start[i]; k < s.start[i + 1]; ++k) {
    sum_b += s.coef[k];
    sum_bp += s.coef[k] * p[s.col[k]];
  }
}

// Numbering of the unknowns (particle -> row), and back.
std::vector<std::uint32_t> number_unknowns(const PoissonSystem& s, std::vector<std::uint32_t>& particle_of_row) {
  std::vector<std::uint32_t> row(s.size(), kNone);
  particle_of_row.clear();
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.role[i] == PressureRole::unknown) {
      row[i] = static_cast<std::uint32_t>(particle_of_row.size());
      particle_of_row.push_back(static_cast<std::uint32_t>(i));
    }
  return row;
}

// M p = b with M_ii = -S_B, M_ij = B_ij (unknown j), b_i = -s_i - sum_{j given} B_ij P_j: symmetric positive
// definite for equal masses. Written straight into the compressed rows, one row per unknown in parallel, the
// diagonal first and then the neighbours in the pair list's order: the columns of a row are not sorted, which the
// matrix-vector products of the Krylov solvers and the preconditioners do not need.
void assemble(const PoissonSystem& s, const std::vector<double>& given, const std::vector<std::uint32_t>& row,
              const std::vector<std::uint32_t>& particle_of_row, SparseMatrix& m, Eigen::VectorXd& b) {
  const auto nu = static_cast<Eigen::Index>(particle_of_row.size());
  std::vector<int> row_start(static_cast<std::size_t>(nu) + 1, 0);
#pragma omp parallel for schedule(static)
  for (Eigen::Index r = 0; r < nu; ++r) {
    const std::uint32_t i = particle_of_row[static_cast<std::size_t>(r)];
    int count = 1;  // the diagonal
    for (std::uint32_t k = s.start[i]; k < s.start[i + 1]; ++k) count += s.role[s.col[k]] == PressureRole::unknown;
    row_start[static_cast<std::size_t>(r) + 1] = count;
  }
  for (std::size_t r = 0; r < static_cast<std::size_t>(nu); ++r) row_start[r + 1] += row_start[r];
  m.resize(nu, nu);
  m.resizeNonZeros(row_start.back());
  std::copy(row_start.begin(), row_start.end(), m.outerIndexPtr());
  int* cols = m.innerIndexPtr();
  double* values = m.valuePtr();
  b.resize(nu);
#pragma omp parallel for schedule(static)
  for (Eigen::Index r = 0; r < nu; ++r) {
    const std::uint32_t i = particle_of_row[static_cast<std::size_t>(r)];
    int at = row_start[static_cast<std::size_t>(r)];
    const int diagonal_at = at++;
    double diag = 0, rhs = -s.source[i];
    for (std::uint32_t k = s.start[i]; k < s.start[i + 1]; ++k) {
      const std::uint32_t j = s.col[k];
      diag -= s.coef[k];
      if (s.role[j] == PressureRole::unknown) {
        cols[at] = static_cast<int>(row[j]);
        values[at++] = s.coef[k];
      } else {
        rhs -= s.coef[k] * given[j];
      }
    }
    cols[diagonal_at] = static_cast<int>(r);
    values[diagonal_at] = diag;
    b[r] = rhs;
  }
}

template <class Solver>
SolveReport run_solver(Solver& solver, const SparseMatrix& m, const Eigen::VectorXd& b, Eigen::VectorXd& p,
                       const SolverChoice& choice) {
  solver.setTolerance(choice.tolerance);
  solver.setMaxIterations(choice.max_iterations);
  solver.compute(m);
  p = solver.solveWithGuess(b, p);
  SolveReport rep;
  rep.iterations = static_cast<int>(solver.iterations());
  rep.converged = solver.info() == Eigen::Success;
  return rep;
}

// The multigrid's first aggregation cells of the unknowns: squares of the system's aggregate size.
void set_aggregation_cells(const PoissonSystem& s, const std::vector<std::uint32_t>& particle_of_row,
                           AggregationMultigrid& mg) {
  std::vector<std::int32_t> cx(particle_of_row.size()), cy(particle_of_row.size());
  if (s.x.size() != s.size() || !(s.aggregate_size > 0)) {
    mg.set_cells({}, {});
    return;
  }
  for (std::size_t r = 0; r < particle_of_row.size(); ++r) {
    cx[r] = static_cast<std::int32_t>(std::floor(s.x[particle_of_row[r]] / s.aggregate_size));
    cy[r] = static_cast<std::int32_t>(std::floor(s.y[particle_of_row[r]] / s.aggregate_size));
  }
  mg.set_cells(std::move(cx), std::move(cy));
}

// The Krylov solve with the chosen solver and preconditioner.
SolveReport krylov_solve_once(const PoissonSystem& s, const std::vector<std::uint32_t>& particle_of_row,
                              const SolverChoice& choice, const SparseMatrix& m, const Eigen::VectorXd& b,
                              Eigen::VectorXd& p) {
  const bool cg = choice.solver == LinearSolver::conjugate_gradient;
  if (choice.preconditioner == Preconditioner::diagonal) {
    if (cg) {
      Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> solver;
      return run_solver(solver, m, b, p, choice);
    }
    Eigen::BiCGSTAB<SparseMatrix> solver;
    return run_solver(solver, m, b, p, choice);
  }
  SolveReport rep;
  if (cg) {
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, AggregationMultigrid> solver;
    set_aggregation_cells(s, particle_of_row, solver.preconditioner());
    rep = run_solver(solver, m, b, p, choice);
    rep.multigrid_levels = solver.preconditioner().level_count();
  } else {
    Eigen::BiCGSTAB<SparseMatrix, AggregationMultigrid> solver;
    set_aggregation_cells(s, particle_of_row, solver.preconditioner());
    rep = run_solver(solver, m, b, p, choice);
    rep.multigrid_levels = solver.preconditioner().level_count();
  }
  return rep;
}

// A multigrid-preconditioned solve that does not converge (or breaks down) is done again from the same first
// guess with the diagonal preconditioner, whose positive definiteness does not depend on the cycle.
SolveReport krylov_solve(const PoissonSystem& s, const std::vector<std::uint32_t>& particle_of_row,
                         const SolverChoice& choice, const SparseMatrix& m, const Eigen::VectorXd& b,
                         Eigen::VectorXd& p) {
  const Eigen::VectorXd guess = p;
  SolveReport rep = krylov_solve_once(s, particle_of_row, choice, m, b, p);
  if (choice.preconditioner == Preconditioner::multigrid && (!rep.converged || !p.allFinite())) {
    p = guess;
    SolverChoice fallback = choice;
    fallback.preconditioner = Preconditioner::diagonal;
    const int tried = rep.iterations;
    rep = krylov_solve_once(s, particle_of_row, fallback, m, b, p);
    rep.iterations += tried;
    rep.fell_back = true;
  }
  return rep;
}

}  // namespace

SolveReport jacobi_sweep(const PoissonSystem& s, std::vector<double>& pressure) {
  const Index n = static_cast<Index>(s.size());
  std::vector<double> next(pressure);
  SolveReport rep;
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (s.role[i] != PressureRole::unknown) continue;
    double sum_b, sum_bp;
    row_sums(s, i, pressure, sum_b, sum_bp);
    // sum_bp holds B_ii P_i = 0 for no i (no self pairs): the sweep reads only the neighbours' values
    next[i] = sum_b < 0 ? terms::jacobi_pressure(s.source[i], sum_b, sum_bp) : 0.0;
  }
  for (std::size_t i = 0; i < s.size(); ++i) rep.unknowns += s.role[i] == PressureRole::unknown ? 1 : 0;
  pressure.swap(next);
  rep.iterations = 1;
  rep.relative_residual = relative_residual(s, pressure);
  return rep;
}

SolveReport solve_pressure(const PoissonSystem& s, const SolverChoice& choice, std::vector<double>& pressure) {
  std::vector<std::uint32_t> particle_of_row;
  const std::vector<std::uint32_t> row = number_unknowns(s, particle_of_row);
  SparseMatrix m;
  Eigen::VectorXd b;
  assemble(s, pressure, row, particle_of_row, m, b);
  Eigen::VectorXd p(b.size());
  for (Eigen::Index r = 0; r < b.size(); ++r) p[r] = pressure[particle_of_row[static_cast<std::size_t>(r)]];
  SolveReport rep;
  if (b.size() > 0) rep = krylov_solve(s, particle_of_row, choice, m, b, p);
  for (Eigen::Index r = 0; r < b.size(); ++r) pressure[particle_of_row[static_cast<std::size_t>(r)]] = p[r];
  rep.unknowns = particle_of_row.size();
  rep.relative_residual = relative_residual(s, pressure);
  return rep;
}

double relative_residual(const PoissonSystem& s, const std::vector<double>& p) {
  double rr = 0, bb = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.role[i] != PressureRole::unknown) continue;
    double sum_b, sum_bp;
    row_sums(s, i, p, sum_b, sum_bp);
    const double lhs = sum_b * p[i] - sum_bp;  // sum_j B_ij (P_i - P_j)
    rr += (lhs - s.source[i]) * (lhs - s.source[i]);
    bb += s.source[i] * s.source[i];
  }
  return bb > 0 ? std::sqrt(rr / bb) : std::sqrt(rr);
}

}  // namespace sph::fluid
