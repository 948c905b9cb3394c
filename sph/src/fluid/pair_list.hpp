#pragma once
// The neighbour pairs of every particle of a cell-sorted set at its current positions, with the pair geometry the
// ISPH equations need (x_ij, r^2, F = W'(r)/r, W). Built twice per step: at r^n (viscous step) and at r*
// (density, free surface, pressure, correction), through the engine's for_each_neighbour. Self pairs are not
// listed.
#include <cstdint>
#include <vector>

#include "sph/engine/cell_sort.hpp"
#include "sph/engine/kernel.hpp"
#include "sph/engine/particle_set.hpp"

namespace sph::fluid {

// The kernel the settings name (EngineSettings::kernel), behind one interface.
class FluidKernel {
 public:
  FluidKernel(KernelType type, double h) : type_(type), cubic_(h), wendland_(h) {}
  double support() const { return cubic_.support(); }  // 2h for both kernels
  double value(double r) const { return type_ == KernelType::cubic_spline ? cubic_.value(r) : wendland_.value(r); }
  double gradient_factor(double r) const {
    return type_ == KernelType::cubic_spline ? cubic_.gradient_factor(r) : wendland_.gradient_factor(r);
  }

 private:
  KernelType type_;
  CubicSplineKernel cubic_;
  WendlandC2Kernel wendland_;
};

struct PairList {
  std::vector<std::uint32_t> start;  // pairs of particle i: [start[i], start[i+1])
  std::vector<std::uint32_t> j;
  std::vector<double> dx, dy, r2, F, W;

  void build(const ParticleSet& particles, const CellSortedSet& sorted, const FluidKernel& kernel);
  std::size_t pair_count() const { return j.size(); }
};

}  // namespace sph::fluid
