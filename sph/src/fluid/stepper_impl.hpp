#pragma once
// The fluid stepper's private state (sph/fluid/stepper.hpp), shared by its two source files: stepper.cpp (the
// three steps of the scheme) and stepper_boundaries.cpp (rigid bodies, the wall clearance, particle removal).
#include <cstdint>
#include <vector>

#include "pair_list.hpp"
#include "sph/engine/cell_sort.hpp"
#include "sph/fluid/pressure.hpp"
#include "sph/fluid/stepper.hpp"

namespace sph::fluid {

namespace detail {
using Index = std::int64_t;
constexpr std::uint8_t kFluid = static_cast<std::uint8_t>(ParticleKind::material);
// The candidates of a step reach this many spacings beyond the kernel support: complete at r* while no particle
// moves more than half of it in the temporary move (V** dt, about cfl dx).
constexpr double kSkinOverDx = 0.5;
}  // namespace detail

struct Step::Impl {
  Impl(KernelType type, double h) : kernel(type, h) {}
  FluidKernel kernel;
  CellSortedSet sorted;
  CandidateList candidates;  // pairs within the support plus the skin at r^n
  PairList pairs;
  PoissonSystem system;
  PressureSolver solver;  // the iterative mode's matrix and preconditioner of the step
  std::vector<double> ax, ay;  // viscous accelerations
  // at r*: the inverse of each particle's kernel moment matrix M_i = -sum_j V_j F_ij x_ij x_ij^T (the identity
  // for a full lattice support), 0 where M_i is too far from it (renormalisation refused)
  std::vector<double> lxx, lxy, lyy;
  std::vector<double> bx, by;  // b_i = sum_j B_ij x_ij (decision D14)
  std::vector<double> source0;  // the density-invariance source before the consistency term
  std::vector<std::uint8_t> dry;  // wall particles with no pressure (above the water): out of the moment matrices
  double lattice_kernel_sum = 1;  // sum_j W_ij dx^2 over a full square lattice (the kernel sum of a particle at rest)
};

}  // namespace sph::fluid
