#pragma once
// The neighbour pairs of every particle at its current positions, with the pair geometry the ISPH equations need
// (x_ij, r^2, F = W'(r)/r, W). A step needs them twice: at r^n (viscous step) and at r* (density, free surface,
// pressure, correction). Both are drawn from one list of candidates per step: the pairs closer than the kernel
// support plus a skin at r^n, gathered from the cells after the step's one sort. The temporary move r* - r^n is
// V** dt, a tenth of a spacing at the default CFL number; while no particle moves more than half the skin, every
// pair within the support at r* is among the candidates (the stepper checks, and sorts and lists again if not).
// Self pairs are not listed.
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

// The candidate pairs: every j != i closer than `radius` at the positions of the listing, in the cells' order.
struct CandidateList {
  std::vector<std::uint32_t> start;  // candidates of particle i: [start[i], start[i+1])
  std::vector<std::uint32_t> j;
  double radius = 0;

  void list(const ParticleSet& particles, const CellSortedSet& sorted, double radius);
};

struct PairList {
  std::vector<std::uint32_t> start;  // pairs of particle i: [start[i], start[i+1])
  std::vector<std::uint32_t> j;
  std::vector<double> dx, dy, r2, F, W;

  // The candidates closer than the kernel's support at the particles' current positions, in the candidates' order.
  void build(const ParticleSet& particles, const CandidateList& candidates, const FluidKernel& kernel);
  std::size_t pair_count() const { return j.size(); }
};

}  // namespace sph::fluid
