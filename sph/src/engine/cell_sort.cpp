#include "sph/engine/cell_sort.hpp"

namespace sph {

namespace {
using Index = std::int64_t;
}  // namespace

void CellSortedSet::reserve(ParticleSet& particles) {
  const std::size_t n = particles.size();
  back_.assign(static_cast<std::size_t>(particles.double_array_count()), std::vector<double>(n, 0.0));
  back_id_.assign(n, 0);
  back_material_.assign(n, 0);
  back_kind_.assign(n, 0);
  moved_.reserve(n);
}

CellSortedSet::Change CellSortedSet::sort(ParticleSet& p, double cell_size) {
  const std::size_t n = p.size();
  cells_.build(p.x.data(), p.y.data(), n, cell_size);
  const std::uint32_t* order = cells_.order().data();
  front_.clear();
  p.for_each_double_array([&](std::vector<double>& a) { front_.push_back(&a); });
  back_.resize(front_.size());
  src_.resize(front_.size());
  dst_.resize(front_.size());
  for (std::size_t k = 0; k < front_.size(); ++k) {
    back_[k].resize(n);
    src_[k] = front_[k]->data();
    dst_[k] = back_[k].data();
  }
  back_id_.resize(n);
  back_material_.resize(n);
  back_kind_.resize(n);
  // Only the entries whose position changes need moving: the stable sort of a state sorted at the previous step
  // is mostly the identity, and the set of moved indices is closed under the permutation.
  moved_.clear();
  for (std::size_t k = 0; k < n; ++k)
    if (order[k] != k) moved_.push_back(static_cast<std::uint32_t>(k));
  if (moved_.empty()) return Change::none;  // same order: every array is unchanged
  if (2 * moved_.size() < n) return sort_sparse(p, order);
  sort_dense(p, order);
  return Change::kinds_moved;
}

// Few moved: gather the moved entries into the back buffers (compact), then scatter them back in place.
CellSortedSet::Change CellSortedSet::sort_sparse(ParticleSet& p, const std::uint32_t* order) {
  const int nd = static_cast<int>(front_.size());
  double* const* src = src_.data();
  double* const* dst = dst_.data();
  const Index nm = static_cast<Index>(moved_.size());
  const std::uint32_t* moved = moved_.data();
  // index lists by kind only change if a moved position changes kind
  bool kinds_change = false;
  for (Index jj = 0; jj < nm && !kinds_change; ++jj) kinds_change = p.kind[moved[jj]] != p.kind[order[moved[jj]]];
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (Index jj = 0; jj < nm; ++jj) {
      const auto j = static_cast<std::size_t>(jj);
      const std::uint32_t o = order[moved[j]];
      for (int a = 0; a < nd; ++a) dst[a][j] = src[a][o];
      back_id_[j] = p.id[o];
      back_material_[j] = p.material[o];
      back_kind_[j] = p.kind[o];
    }
#pragma omp for schedule(static)
    for (Index jj = 0; jj < nm; ++jj) {
      const auto j = static_cast<std::size_t>(jj);
      const std::uint32_t k = moved[j];
      for (int a = 0; a < nd; ++a) src[a][k] = dst[a][j];
      p.id[k] = back_id_[j];
      p.material[k] = back_material_[j];
      p.kind[k] = back_kind_[j];
    }
  }
  return kinds_change ? Change::kinds_moved : Change::moved;
}

// Many moved: gather everything into the back buffers, then swap.
void CellSortedSet::sort_dense(ParticleSet& p, const std::uint32_t* order) {
  const int nd = static_cast<int>(front_.size());
  double* const* src = src_.data();
  double* const* dst = dst_.data();
  const Index nn = static_cast<Index>(p.size());
  const std::uint32_t* src_id = p.id.data();
  const std::uint16_t* src_mat = p.material.data();
  const std::uint8_t* src_kind = p.kind.data();
  std::uint32_t* dst_id = back_id_.data();
  std::uint16_t* dst_mat = back_material_.data();
  std::uint8_t* dst_kind = back_kind_.data();
#pragma omp parallel for schedule(static)
  for (Index kk = 0; kk < nn; ++kk) {
    const auto k = static_cast<std::size_t>(kk);
    const std::uint32_t o = order[k];
    for (int a = 0; a < nd; ++a) dst[a][k] = src[a][o];
    dst_id[k] = src_id[o];
    dst_mat[k] = src_mat[o];
    dst_kind[k] = src_kind[o];
  }
  for (std::size_t k = 0; k < front_.size(); ++k) front_[k]->swap(back_[k]);
  p.id.swap(back_id_);
  p.material.swap(back_material_);
  p.kind.swap(back_kind_);
}

}  // namespace sph
