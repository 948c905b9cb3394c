#pragma once
// Failure surface read out of a particle state: the shear band of accumulated plastic strain, bin by bin
// along x, and a least-squares circle through it. SI units (m).
#include <optional>
#include <string>
#include <vector>

#include "coupling/scene/analysis_options.hpp"
#include "slope/slices.hpp"

namespace coupling {

// What surface extraction needs from a particle state (soil particles only).
struct ParticleSnapshot {
  std::vector<double> x, y;            // m, current positions
  std::vector<double> x0, y0;          // m, initial positions
  std::vector<double> plastic_strain;  // accumulated equivalent plastic strain (-)
  std::vector<double> stress_xx, stress_yy;  // Pa, tension positive (empty when not recorded)
  double spacing = 0.0;                // m, initial particle spacing
};

struct FailureSurface {
  std::vector<slope::Point> points;  // band centre per bin, left to right, m
  double plastic_strain_threshold = 0.0;
  double bin_width = 0.0;            // m
  std::size_t band_particles = 0;    // particles in the band
};

// Band centre per x-bin: in each bin the connected run of particles at or above the threshold (a gap larger
// than 1.5 spacings ends a run) with the most plastic strain, preferring runs that do not reach the free
// surface, and its plastic-strain-weighted mean position, then centred along the band's normal. Bins without
// a band are skipped; the longest chain of bins without a gap is kept.
FailureSurface plastic_band_surface(const ParticleSnapshot& particles, const BandOptions& options);

struct CircleFit {
  slope::Circle circle;
  double rms_residual = 0.0;  // m, root mean square of (distance to centre - radius)
  double max_residual = 0.0;  // m
};

// Geometric least-squares circle (algebraic Kasa fit refined by Gauss-Newton on the orthogonal distances).
// Empty for fewer than three points or (nearly) collinear points.
std::optional<CircleFit> fit_circle(const std::vector<slope::Point>& points);

}  // namespace coupling
