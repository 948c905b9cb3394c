#pragma once
// An aggregation multigrid preconditioner for the ISPH pressure equation (docs/isph.md section 3), usable as the
// preconditioner of Eigen's ConjugateGradient and BiCGSTAB.
//
// The pressure matrix is a symmetric M-matrix with one row per unknown particle and about 28 entries per row; its
// condition number grows like (L/dx)^2, so the diagonal preconditioner needs a number of iterations that grows like
// L/dx (about 120 per solve at 5,000 particles, 180 at 20,000). Multigrid removes that growth: the unknowns are
// grouped into aggregates by square cells of the plane (2 dx wide at the first level, twice as wide at each level
// below), the coarse matrix is the Galerkin product P^T A P with P the piecewise-constant prolongation of the
// aggregates (unsmoothed aggregation, Vanek, Mandel & Brezina 1996 without the smoothing of P; Notay 2010 for its
// use as a Krylov preconditioner), and one symmetric cycle (one coarse correction from the finest level, two from
// each level below) with damped Jacobi smoothing and a scaled coarse correction is applied per Krylov iteration.
// The coarsest level is solved by a dense Cholesky factorisation.
//
// Everything is deterministic and independent of the thread count: the smoother is Jacobi (each row reads only the
// previous sweep), the aggregates come from the geometry, and the Galerkin sums run in a fixed order.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <vector>

namespace sph::fluid {

// A square sparse matrix in compressed rows.
struct CsrMatrix {
  std::vector<int> start;  // n + 1
  std::vector<int> col;
  std::vector<double> value;
  int rows() const { return static_cast<int>(start.size()) - 1; }
};

class AggregationMultigrid {
 public:
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };

  struct Options {
    // damped Jacobi; omega times the largest eigenvalue of D^-1 A (at most 2 for this diagonally dominant matrix)
    // must stay below 2. Measured on the 20,000-particle dam break (CG iterations to 1e-8 at t = 0.03 s): 0.6 and
    // 0.8 with one or two sweeps all give 23-24 iterations without the over-correction below; the cheaper choice
    double smoother_weight = 0.8;
    int sweeps = 1;  // pre- and post-smoothing sweeps (the same count keeps the V-cycle symmetric for CG)
    // The coarse correction's scale: a piecewise-constant prolongation undershoots smooth errors, and scaling its
    // correction (below 2, so the cycle stays a contraction and the preconditioner positive definite) makes up
    // for it. Same case with V-cycles: 1.0 -> 23.4 iterations, 1.3 -> 16.1, 1.6 -> 14.2, 1.9 -> 15.8; with
    // W-cycles: 1.0 -> 10.8, 1.25 -> 8.6, 1.4 -> 8.2.
    double coarse_scale = 1.4;
    // Visits of each coarser level per visit of the finer, below the finest level (which makes one): 1 a V-cycle,
    // 2 a W-cycle under it. The V-cycle's iterations grow with the particle count (unsmoothed aggregation: 16 -> 23
    // CG iterations from 5,000 to 20,000 particles), the W-cycle's do not (8.4 -> 8.2 with the scale below, two
    // coarse corrections from the finest level too). One correction from the finest level and W below it takes
    // 11.6 iterations at 20,000 particles against the full W-cycle's 8.5, but 4 % fewer instructions per step
    // (callgrind, bench-isph 0.01 iterative 0.03).
    int cycles = 2;
    int coarsest_rows = 128;  // solved directly at or below this size
    int max_levels = 12;
  };

  AggregationMultigrid() = default;
  template <class M>
  explicit AggregationMultigrid(const M& matrix) {
    compute(matrix);
  }

  // The cells of the first aggregation (integer coordinates of each row's cell, e.g. floor(x / 2dx)); must be set
  // before compute. Rows without cells (an empty vector) are aggregated in pairs of consecutive rows.
  void set_cells(std::vector<std::int32_t> cell_x, std::vector<std::int32_t> cell_y);
  void set_options(const Options& options) { options_ = options; }

  template <class M>
  AggregationMultigrid& analyzePattern(const M&) {
    return *this;
  }
  template <class M>
  AggregationMultigrid& factorize(const M& matrix) {
    CsrMatrix a;
    copy_rows(matrix, a);
    build(std::move(a));
    return *this;
  }
  template <class M>
  AggregationMultigrid& compute(const M& matrix) {
    return factorize(matrix);
  }

  // One V-cycle from a zero guess: z = B r, B symmetric positive definite.
  template <class Rhs>
  Eigen::VectorXd solve(const Eigen::MatrixBase<Rhs>& r) const {
    Eigen::VectorXd b = r;
    Eigen::VectorXd z(b.size());
    apply(b.data(), z.data());
    return z;
  }

  Eigen::ComputationInfo info() const { return ok_ ? Eigen::Success : Eigen::NumericalIssue; }
  Eigen::Index rows() const { return levels_.empty() ? 0 : levels_.front().a.rows(); }
  Eigen::Index cols() const { return rows(); }
  int level_count() const { return static_cast<int>(levels_.size()); }
  std::size_t rows_at(int level) const { return static_cast<std::size_t>(levels_[level].a.rows()); }

 private:
  struct Level {
    CsrMatrix a;
    std::vector<double> inv_diag;
    std::vector<int> aggregate;  // row -> row of the next level (empty at the coarsest)
    std::vector<std::int32_t> cx, cy;  // the cell of each row at this level's aggregation
    mutable std::vector<double> x, b, r;  // work vectors of the cycle
  };

  // The compressed rows of a square matrix (Eigen's row-major compressed storage: copied as arrays).
  template <class M>
  static void copy_rows(const M& m, CsrMatrix& a) {
    const auto n = static_cast<std::size_t>(m.outerSize());
    if (m.isCompressed()) {
      const auto nnz = static_cast<std::size_t>(m.outerIndexPtr()[n]);
      a.start.assign(m.outerIndexPtr(), m.outerIndexPtr() + n + 1);
      a.col.assign(m.innerIndexPtr(), m.innerIndexPtr() + nnz);
      a.value.assign(m.valuePtr(), m.valuePtr() + nnz);
      return;
    }
    a.start.assign(n + 1, 0);
    a.col.clear();
    a.value.clear();
    for (Eigen::Index k = 0; k < m.outerSize(); ++k) {
      for (typename M::InnerIterator it(m, k); it; ++it) {
        a.col.push_back(static_cast<int>(it.index()));
        a.value.push_back(it.value());
      }
      a.start[static_cast<std::size_t>(k) + 1] = static_cast<int>(a.col.size());
    }
  }

  void build(CsrMatrix fine);
  static int aggregate(Level& fine, Level& coarse);  // returns the coarse row count
  static void galerkin(const Level& fine, int coarse_rows, CsrMatrix& coarse);
  void apply(const double* r, double* z) const;
  void cycle(std::size_t level) const;
  bool factor_coarsest();
  void solve_coarsest(const double* b, double* x) const;

  Options options_;
  std::vector<std::int32_t> cell_x_, cell_y_;
  std::vector<Level> levels_;
  // The coarsest level's Cholesky factor L (row-major, lower triangle): solved exactly by two substitutions.
  std::vector<double> coarsest_factor_;
  bool ok_ = false;
};

}  // namespace sph::fluid
