#include "multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace sph::fluid {

namespace {

// Loops shorter than this run on one thread (the coarse levels): the fork costs more than the work.
constexpr int kParallelRows = 2048;

std::int32_t floor_half(std::int32_t c) { return c >= 0 ? c / 2 : -((-c + 1) / 2); }

// r = b - A x over the rows of a.
void residual(const CsrMatrix& a, const double* x, const double* b, double* r) {
  const int n = a.rows();
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (int i = 0; i < n; ++i) {
    double s = b[i];
    for (int k = a.start[i]; k < a.start[i + 1]; ++k) s -= a.value[k] * x[a.col[k]];
    r[i] = s;
  }
}

}  // namespace

void AggregationMultigrid::set_cells(std::vector<std::int32_t> cell_x, std::vector<std::int32_t> cell_y) {
  cell_x_ = std::move(cell_x);
  cell_y_ = std::move(cell_y);
}

// The rows of `fine` grouped by their cells: every distinct cell is one row of the next level, numbered in the
// order of the cells (y, then x), so that the coarse matrix keeps the locality of the fine one.
int AggregationMultigrid::aggregate(Level& fine, Level& coarse) {
  const int n = fine.a.rows();
  std::vector<std::pair<std::int64_t, int>> keyed(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const std::int64_t key = fine.cx.empty() ? i / 2
                                             : (static_cast<std::int64_t>(fine.cy[u]) << 32) +
                                                   static_cast<std::int64_t>(static_cast<std::uint32_t>(fine.cx[u]));
    keyed[u] = {key, i};
  }
  std::sort(keyed.begin(), keyed.end());
  fine.aggregate.assign(static_cast<std::size_t>(n), 0);
  coarse.cx.clear();
  coarse.cy.clear();
  int next = -1;
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    if (k == 0 || keyed[k].first != keyed[k - 1].first) {
      ++next;
      const auto row = static_cast<std::size_t>(keyed[k].second);
      coarse.cx.push_back(fine.cx.empty() ? 0 : floor_half(fine.cx[row]));
      coarse.cy.push_back(fine.cy.empty() ? 0 : floor_half(fine.cy[row]));
    }
    fine.aggregate[static_cast<std::size_t>(keyed[k].second)] = next;
  }
  if (fine.cx.empty()) {
    coarse.cx.clear();
    coarse.cy.clear();
  }
  return next + 1;
}

// coarse(I, J) = sum over the fine rows i of aggregate I and their entries (i, j) with j in aggregate J of a_ij.
void AggregationMultigrid::galerkin(const Level& fine, int coarse_rows, CsrMatrix& coarse) {
  const int n = fine.a.rows();
  const auto nc = static_cast<std::size_t>(coarse_rows);
  // the fine rows of every aggregate, in row order
  std::vector<int> first(nc + 1, 0), members(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) ++first[static_cast<std::size_t>(fine.aggregate[static_cast<std::size_t>(i)]) + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  {
    std::vector<int> at(first.begin(), first.end() - 1);
    for (int i = 0; i < n; ++i) members[static_cast<std::size_t>(at[fine.aggregate[static_cast<std::size_t>(i)]]++)] = i;
  }
  const CsrMatrix& a = fine.a;
  const std::vector<int>& agg = fine.aggregate;
  coarse.start.assign(nc + 1, 0);
  // pass 1: the number of distinct coarse columns of every coarse row
#pragma omp parallel if (coarse_rows > kParallelRows / 4)
  {
    std::vector<int> seen(nc, -1);
#pragma omp for schedule(static)
    for (int c = 0; c < coarse_rows; ++c) {
      int count = 0;
      for (int m = first[c]; m < first[c + 1]; ++m)
        for (int k = a.start[members[m]]; k < a.start[members[m] + 1]; ++k) {
          const int cj = agg[a.col[k]];
          if (seen[cj] != c) {
            seen[cj] = c;
            ++count;
          }
        }
      coarse.start[static_cast<std::size_t>(c) + 1] = count;
    }
  }
  std::partial_sum(coarse.start.begin(), coarse.start.end(), coarse.start.begin());
  coarse.col.assign(static_cast<std::size_t>(coarse.start[nc]), 0);
  coarse.value.assign(static_cast<std::size_t>(coarse.start[nc]), 0.0);
  // pass 2: the sums (slots of a row are above every slot of the rows before it, so `slot < begin` means unseen)
#pragma omp parallel if (coarse_rows > kParallelRows / 4)
  {
    std::vector<int> slot(nc, -1);
#pragma omp for schedule(static)
    for (int c = 0; c < coarse_rows; ++c) {
      const int begin = coarse.start[c];
      int end = begin;
      for (int m = first[c]; m < first[c + 1]; ++m)
        for (int k = a.start[members[m]]; k < a.start[members[m] + 1]; ++k) {
          const int cj = agg[a.col[k]];
          if (slot[cj] < begin) {
            slot[cj] = end;
            coarse.col[end] = cj;
            coarse.value[end] = 0.0;
            ++end;
          }
          coarse.value[slot[cj]] += a.value[k];
        }
    }
  }
}

void AggregationMultigrid::build(CsrMatrix fine) {
  levels_.clear();
  levels_.emplace_back();
  levels_[0].a = std::move(fine);
  if (cell_x_.size() == static_cast<std::size_t>(levels_[0].a.rows())) {
    levels_[0].cx = cell_x_;
    levels_[0].cy = cell_y_;
  }
  ok_ = true;
  for (;;) {
    Level& level = levels_.back();
    const int n = level.a.rows();
    level.inv_diag.assign(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i)
      for (int k = level.a.start[i]; k < level.a.start[i + 1]; ++k)
        if (level.a.col[k] == i && level.a.value[k] > 0) level.inv_diag[static_cast<std::size_t>(i)] = 1.0 / level.a.value[k];
    level.x.assign(static_cast<std::size_t>(n), 0.0);
    level.b.assign(static_cast<std::size_t>(n), 0.0);
    level.r.assign(static_cast<std::size_t>(n), 0.0);
    if (n <= options_.coarsest_rows || static_cast<int>(levels_.size()) >= options_.max_levels) break;
    Level coarse;
    const int nc = aggregate(level, coarse);
    if (nc * 10 > n * 9) {  // the cells no longer group the rows: stop coarsening here
      level.aggregate.clear();
      break;
    }
    galerkin(level, nc, coarse.a);
    levels_.push_back(std::move(coarse));
  }
  levels_.back().aggregate.clear();
  ok_ = factor_coarsest();
}

// Dense Cholesky A = L Lᵀ of the coarsest level (a few hundred rows at most). False when A is not positive
// definite (the caller then falls back to the diagonal preconditioner).
bool AggregationMultigrid::factor_coarsest() {
  const CsrMatrix& last = levels_.back().a;
  const auto n = static_cast<std::size_t>(last.rows());
  if (n > 4096) return false;  // coarsening stalled: a dense factor would not pay (the diagonal is used instead)
  std::vector<double>& l = coarsest_factor_;
  l.assign(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = last.start[i]; k < last.start[i + 1]; ++k) l[i * n + static_cast<std::size_t>(last.col[k])] += last.value[k];
  for (std::size_t j = 0; j < n; ++j) {
    double d = l[j * n + j];
    for (std::size_t k = 0; k < j; ++k) d -= l[j * n + k] * l[j * n + k];
    if (!(d > 0.0)) return false;
    d = std::sqrt(d);
    l[j * n + j] = d;
    for (std::size_t i = j + 1; i < n; ++i) {
      double s = l[i * n + j];
      for (std::size_t k = 0; k < j; ++k) s -= l[i * n + k] * l[j * n + k];
      l[i * n + j] = s / d;
    }
  }
  return true;
}

// x = A⁻¹ b at the coarsest level: L y = b, then Lᵀ x = y.
void AggregationMultigrid::solve_coarsest(const double* b, double* x) const {
  const std::vector<double>& l = coarsest_factor_;
  const std::size_t n = levels_.back().x.size();
  for (std::size_t i = 0; i < n; ++i) {
    double s = b[i];
    for (std::size_t k = 0; k < i; ++k) s -= l[i * n + k] * x[k];
    x[i] = s / l[i * n + i];
  }
  for (std::size_t i = n; i-- > 0;) {
    double s = x[i];
    for (std::size_t k = i + 1; k < n; ++k) s -= l[k * n + i] * x[k];
    x[i] = s / l[i * n + i];
  }
}

// One symmetric V-cycle at `level` for its right-hand side b, from x = 0, into x.
void AggregationMultigrid::cycle(std::size_t level) const {
  const Level& l = levels_[level];
  const int n = l.a.rows();
  if (level + 1 == levels_.size()) {
    solve_coarsest(l.b.data(), l.x.data());
    return;
  }
  const double w = options_.smoother_weight;
  double* x = l.x.data();
  double* r = l.r.data();
  const double* b = l.b.data();
  const double* d = l.inv_diag.data();
  auto smooth = [&]() {
    residual(l.a, x, b, r);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (int i = 0; i < n; ++i) x[i] += w * d[i] * r[i];
  };
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (int i = 0; i < n; ++i) x[i] = w * d[i] * b[i];  // the first sweep from zero
  for (int s = 1; s < options_.sweeps; ++s) smooth();
  const Level& c = levels_[level + 1];
  const int* agg = l.aggregate.data();
  const double alpha = options_.coarse_scale;
  const double* xc = c.x.data();
  // one coarse correction from the finest level, `cycles` below it, one above the coarsest (solved exactly)
  const int visits = level == 0 || level + 2 == levels_.size() ? 1 : options_.cycles;
  for (int v = 0; v < visits; ++v) {
    residual(l.a, x, b, r);
    std::fill(c.b.begin(), c.b.end(), 0.0);
    for (int i = 0; i < n; ++i) c.b[static_cast<std::size_t>(agg[i])] += r[i];
    cycle(level + 1);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (int i = 0; i < n; ++i) x[i] += alpha * xc[agg[i]];
  }
  for (int s = 0; s < options_.sweeps; ++s) smooth();
}

void AggregationMultigrid::apply(const double* r, double* z) const {
  const Level& top = levels_.front();
  std::copy(r, r + top.a.rows(), top.b.begin());
  cycle(0);
  std::copy(top.x.begin(), top.x.end(), z);
}

}  // namespace sph::fluid
