#include "sph/fluid/pressure.hpp"

// g++ 12 reports a false "may be used uninitialized" inside its own AVX-512 intrinsics (avx512fintrin.h,
// _mm512_undefined_pd) when Eigen's conjugate gradient is compiled for an AVX-512 CPU (x86-64-v4); the warning is
// silenced for this file only (docs/reliability.md).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <cmath>

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
// definite for equal masses.
void assemble(const PoissonSystem& s, const std::vector<double>& given, const std::vector<std::uint32_t>& row,
              const std::vector<std::uint32_t>& particle_of_row, SparseMatrix& m, Eigen::VectorXd& b) {
  const auto nu = static_cast<Eigen::Index>(particle_of_row.size());
  m.resize(nu, nu);
  Eigen::VectorXi per_row(nu);
  for (Eigen::Index r = 0; r < nu; ++r) {
    const std::uint32_t i = particle_of_row[static_cast<std::size_t>(r)];
    per_row[r] = static_cast<int>(s.start[i + 1] - s.start[i]) + 1;
  }
  m.reserve(per_row);
  b.resize(nu);
  for (Eigen::Index r = 0; r < nu; ++r) {
    const std::uint32_t i = particle_of_row[static_cast<std::size_t>(r)];
    double diag = 0, rhs = -s.source[i];
    for (std::uint32_t k = s.start[i]; k < s.start[i + 1]; ++k) {
      const std::uint32_t j = s.col[k];
      diag -= s.coef[k];
      if (s.role[j] == PressureRole::unknown)
        m.insert(r, row[j]) = s.coef[k];
      else
        rhs -= s.coef[k] * given[j];
    }
    m.insert(r, r) = diag;
    b[r] = rhs;
  }
  m.makeCompressed();
}

template <class Solver>
SolveReport run_solver(Solver& solver, const SparseMatrix& m, const Eigen::VectorXd& b, Eigen::VectorXd& p,
                       double tolerance, int max_iterations) {
  solver.setTolerance(tolerance);
  solver.setMaxIterations(max_iterations);
  solver.compute(m);
  p = solver.solveWithGuess(b, p);
  SolveReport rep;
  rep.iterations = static_cast<int>(solver.iterations());
  rep.converged = solver.info() == Eigen::Success;
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

SolveReport solve_pressure(const PoissonSystem& s, LinearSolver which, double tolerance, int max_iterations,
                           std::vector<double>& pressure) {
  std::vector<std::uint32_t> particle_of_row;
  const std::vector<std::uint32_t> row = number_unknowns(s, particle_of_row);
  SparseMatrix m;
  Eigen::VectorXd b;
  assemble(s, pressure, row, particle_of_row, m, b);
  Eigen::VectorXd p(b.size());
  for (Eigen::Index r = 0; r < b.size(); ++r) p[r] = pressure[particle_of_row[static_cast<std::size_t>(r)]];
  SolveReport rep;
  if (b.size() > 0) {
    if (which == LinearSolver::conjugate_gradient) {
      Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg;
      rep = run_solver(cg, m, b, p, tolerance, max_iterations);
    } else {
      Eigen::BiCGSTAB<SparseMatrix> bicg;
      rep = run_solver(bicg, m, b, p, tolerance, max_iterations);
    }
  }
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
