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
#include <memory>
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

// M p = b with M_ii = -S_B, M_ij = B_ij (unknown j): symmetric positive definite for equal masses. Written straight
// into the compressed rows, one row per unknown in parallel, the diagonal first and then the neighbours in the pair
// list's order: the columns of a row are not sorted, which the matrix-vector products of the Krylov solvers and
// the preconditioners do not need.
void assemble_matrix(const PoissonSystem& s, const std::vector<std::uint32_t>& row,
                     const std::vector<std::uint32_t>& particle_of_row, SparseMatrix& m) {
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
#pragma omp parallel for schedule(static)
  for (Eigen::Index r = 0; r < nu; ++r) {
    const std::uint32_t i = particle_of_row[static_cast<std::size_t>(r)];
    int at = row_start[static_cast<std::size_t>(r)];
    const int diagonal_at = at++;
    double diag = 0;
    for (std::uint32_t k = s.start[i]; k < s.start[i + 1]; ++k) {
      const std::uint32_t j = s.col[k];
      diag -= s.coef[k];
      if (s.role[j] != PressureRole::unknown) continue;
      cols[at] = static_cast<int>(row[j]);
      values[at++] = s.coef[k];
    }
    cols[diagonal_at] = static_cast<int>(r);
    values[diagonal_at] = diag;
  }
}

// b_i = -s_i - sum_{j given} B_ij P_j.
void assemble_rhs(const PoissonSystem& s, const std::vector<double>& given,
                  const std::vector<std::uint32_t>& particle_of_row, Eigen::VectorXd& b) {
  const auto nu = static_cast<Eigen::Index>(particle_of_row.size());
  b.resize(nu);
#pragma omp parallel for schedule(static)
  for (Eigen::Index r = 0; r < nu; ++r) {
    const std::uint32_t i = particle_of_row[static_cast<std::size_t>(r)];
    double rhs = -s.source[i];
    for (std::uint32_t k = s.start[i]; k < s.start[i + 1]; ++k)
      if (s.role[s.col[k]] != PressureRole::unknown) rhs -= s.coef[k] * given[s.col[k]];
    b[r] = rhs;
  }
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

template <class Solver>
SolveReport run_solver(Solver& solver, const Eigen::VectorXd& b, Eigen::VectorXd& p, const SolverChoice& choice) {
  solver.setTolerance(choice.tolerance);
  solver.setMaxIterations(choice.max_iterations);
  p = solver.solveWithGuess(b, p);
  SolveReport rep;
  rep.iterations = static_cast<int>(solver.iterations());
  rep.converged = solver.info() == Eigen::Success && p.allFinite();
  rep.relative_residual = solver.error();  // |b - M p| / |b| of the unknowns' system
  return rep;
}

}  // namespace

struct PressureSolver::Impl {
  SolverChoice choice;
  std::vector<std::uint32_t> row, particle_of_row;
  SparseMatrix m;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, AggregationMultigrid> cg_multigrid;
  Eigen::BiCGSTAB<SparseMatrix, AggregationMultigrid> bicgstab_multigrid;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg_diagonal;
  Eigen::BiCGSTAB<SparseMatrix> bicgstab_diagonal;
  bool diagonal_ready = false;  // the diagonal solver set up on m (the choice, or a fallback)

  void prepare_diagonal() {
    if (diagonal_ready) return;
    if (choice.solver == LinearSolver::conjugate_gradient)
      cg_diagonal.compute(m);
    else
      bicgstab_diagonal.compute(m);
    diagonal_ready = true;
  }

  // The solve with the chosen solver (preconditioner: the diagonal, or else the multigrid).
  SolveReport solve(const Eigen::VectorXd& b, Eigen::VectorXd& p, bool diagonal) {
    const bool cg = choice.solver == LinearSolver::conjugate_gradient;
    if (diagonal) {
      prepare_diagonal();
      return cg ? run_solver(cg_diagonal, b, p, choice) : run_solver(bicgstab_diagonal, b, p, choice);
    }
    SolveReport rep = cg ? run_solver(cg_multigrid, b, p, choice) : run_solver(bicgstab_multigrid, b, p, choice);
    rep.multigrid_levels =
        cg ? cg_multigrid.preconditioner().level_count() : bicgstab_multigrid.preconditioner().level_count();
    return rep;
  }
};

PressureSolver::PressureSolver() : impl_(std::make_unique<Impl>()) {}
PressureSolver::~PressureSolver() = default;

void PressureSolver::prepare(const PoissonSystem& s, const SolverChoice& choice) {
  Impl& x = *impl_;
  x.choice = choice;
  x.row = number_unknowns(s, x.particle_of_row);
  assemble_matrix(s, x.row, x.particle_of_row, x.m);
  x.diagonal_ready = false;
  if (x.particle_of_row.empty()) return;
  if (choice.preconditioner == Preconditioner::diagonal) {
    x.prepare_diagonal();
  } else if (choice.solver == LinearSolver::conjugate_gradient) {
    set_aggregation_cells(s, x.particle_of_row, x.cg_multigrid.preconditioner());
    x.cg_multigrid.compute(x.m);
  } else {
    set_aggregation_cells(s, x.particle_of_row, x.bicgstab_multigrid.preconditioner());
    x.bicgstab_multigrid.compute(x.m);
  }
}

// A multigrid-preconditioned solve that does not converge (or breaks down) is done again from the same first
// guess with the diagonal preconditioner, whose positive definiteness does not depend on the cycle.
SolveReport PressureSolver::solve(const PoissonSystem& s, std::vector<double>& pressure, double tolerance) {
  Impl& x = *impl_;
  const double chosen = x.choice.tolerance;
  if (tolerance > 0) x.choice.tolerance = tolerance;
  SolveReport rep;
  if (!x.particle_of_row.empty()) {
    Eigen::VectorXd b, p(static_cast<Eigen::Index>(x.particle_of_row.size()));
    assemble_rhs(s, pressure, x.particle_of_row, b);
    for (Eigen::Index r = 0; r < p.size(); ++r) p[r] = pressure[x.particle_of_row[static_cast<std::size_t>(r)]];
    const Eigen::VectorXd guess = p;
    const bool diagonal = x.choice.preconditioner == Preconditioner::diagonal;
    rep = x.solve(b, p, diagonal);
    if (!diagonal && !rep.converged) {
      p = guess;
      const int tried = rep.iterations, levels = rep.multigrid_levels;
      rep = x.solve(b, p, true);
      rep.iterations += tried;
      rep.multigrid_levels = levels;
      rep.fell_back = true;
    }
    for (Eigen::Index r = 0; r < p.size(); ++r) pressure[x.particle_of_row[static_cast<std::size_t>(r)]] = p[r];
  }
  x.choice.tolerance = chosen;
  rep.unknowns = x.particle_of_row.size();
  return rep;
}

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
  PressureSolver solver;
  solver.prepare(s, choice);
  return solver.solve(s, pressure);
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
