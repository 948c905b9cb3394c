#pragma once
// Keeps a particle set sorted by cell (the cell list's stable row-major order), so that the neighbours of a
// particle lie in three contiguous index ranges and the per-particle loops read memory in order. Every array of the
// set is reordered (core fields and every registered field), through back buffers that are reused between steps.
#include <cstdint>
#include <vector>

#include "sph/engine/particle_set.hpp"
#include "sph/engine/neighbour_search.hpp"

namespace sph {

class CellSortedSet {
 public:
  enum class Change { none, moved, kinds_moved };

  // Sizes the back buffers for the set as it is now (its registry and particle count).
  void reserve(ParticleSet& particles);

  // Bins the particles into cells of side `cell_size` (>= the kernel support), then reorders every array of the
  // set by the stable cell order. Returns what changed: nothing; some particles moved, but every moved position
  // keeps its kind; or the kinds at some positions changed (index lists by kind must be rebuilt). Raw pointers
  // into the set's arrays are invalid afterwards (buffers may have been swapped).
  Change sort(ParticleSet& particles, double cell_size);

  const CellList& cells() const { return cells_; }

 private:
  Change sort_sparse(ParticleSet& p, const std::uint32_t* order);
  void sort_dense(ParticleSet& p, const std::uint32_t* order);

  CellList cells_;
  std::vector<std::vector<double>> back_;  // one per double array of the set, in registry order
  std::vector<std::uint32_t> back_id_;
  std::vector<std::uint16_t> back_material_;
  std::vector<std::uint8_t> back_kind_;
  std::vector<std::uint32_t> moved_;         // sorted positions whose particle changes in this sort
  std::vector<std::vector<double>*> front_;  // the set's double arrays (rebuilt per sort)
  std::vector<double*> src_, dst_;
};

}  // namespace sph
