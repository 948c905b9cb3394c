#include "coupling/compare/failure_surface.hpp"

// GCC 12 reports -Wmaybe-uninitialized inside its own AVX-512 intrinsics (the deliberately undefined registers of
// _mm512_undefined_pd) when Eigen's SVD is compiled for an AVX-512 CPU; the warning is about the compiler's header,
// not this code, so it is silenced for Eigen's headers only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <Eigen/Dense>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#include <algorithm>
#include <cmath>
#include <limits>

namespace coupling {

namespace {

// A connected run of band particles up a bin's column (a gap wider than 1.5 spacings ends a run).
struct BandRun {
  std::size_t first = 0, last = 0;  // range in `band`
  double weight = 0.0, weighted_x = 0.0, weighted_y = 0.0, top_y = 0.0;
  int count = 0;
};

// The band particles of one column (sorted by height), as connected runs; their indices are appended to `band`.
std::vector<BandRun> column_runs(const std::vector<std::size_t>& column, const ParticleSnapshot& particles,
                                 const std::vector<double>& xs, const std::vector<double>& ys, double threshold,
                                 double gap, std::vector<std::size_t>& band) {
  std::vector<BandRun> runs;
  for (std::size_t i : column) {
    if (particles.plastic_strain[i] < threshold) continue;
    if (runs.empty() || ys[i] - runs.back().top_y > gap) runs.push_back(BandRun{band.size(), band.size(), 0, 0, 0, 0, 0});
    BandRun& run = runs.back();
    const double w = particles.plastic_strain[i];
    run.weight += w;
    run.weighted_x += w * xs[i];
    run.weighted_y += w * ys[i];
    run.top_y = ys[i];
    run.last = band.size() + 1;
    ++run.count;
    band.push_back(i);
  }
  return runs;
}

// The band is the run with the most plastic strain, preferring runs below the free surface: a zone at the surface
// (a crest tension zone) is not the slip surface unless the column has nothing else.
const BandRun* choose_run(const std::vector<BandRun>& runs, double column_top, double gap, int min_particles) {
  const BandRun* chosen = nullptr;
  bool chosen_at_surface = true;
  for (const BandRun& run : runs) {
    if (run.count < min_particles) continue;
    const bool at_surface = column_top - run.top_y <= gap;
    if (!chosen || (chosen_at_surface && !at_surface) ||
        (chosen_at_surface == at_surface && run.weight > chosen->weight)) {
      chosen = &run;
      chosen_at_surface = at_surface;
    }
  }
  return chosen;
}

// The band's points before the chain and centring steps: one per bin that holds a band, with the particles of
// the chosen runs in `band` (point k's particles start at point_band_start[k]).
struct BandPoints {
  std::vector<slope::Point> points;
  std::vector<int> point_bin;                 // bin of each point
  std::vector<std::size_t> point_band_start;  // first entry of `band` that belongs to each point
  std::vector<std::size_t> band;              // particles of the chosen runs that made a point
};

BandPoints band_points_per_bin(const ParticleSnapshot& particles, const BandOptions& options,
                               const std::vector<double>& xs, const std::vector<double>& ys, double bin_width) {
  const auto [x_lo, x_hi] = std::minmax_element(xs.begin(), xs.end());
  const double x_min = *x_lo;
  const int bins = static_cast<int>(std::floor((*x_hi - x_min) / bin_width)) + 1;

  // Particles of each bin, sorted by height.
  std::vector<std::vector<std::size_t>> members(static_cast<std::size_t>(bins));
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const int b = std::clamp(static_cast<int>((xs[i] - x_min) / bin_width), 0, bins - 1);
    members[static_cast<std::size_t>(b)].push_back(i);
  }
  const double gap = 1.5 * particles.spacing;
  BandPoints out;
  std::vector<std::size_t>& band = out.band;
  for (int b = 0; b < bins; ++b) {
    auto& column = members[static_cast<std::size_t>(b)];
    std::sort(column.begin(), column.end(), [&](std::size_t a, std::size_t c) { return ys[a] < ys[c]; });
    const std::size_t band_start = band.size();
    const std::vector<BandRun> runs =
        column_runs(column, particles, xs, ys, options.plastic_strain_threshold, gap, band);
    const double column_top = column.empty() ? 0.0 : ys[column.back()];
    const BandRun* chosen = choose_run(runs, column_top, gap, options.min_particles_per_bin);
    if (!chosen || chosen->weight <= 0.0) {
      band.resize(band_start);
      continue;
    }
    const double weight = chosen->weight, weighted_x = chosen->weighted_x, weighted_y = chosen->weighted_y;
    // Keep only the chosen run's particles.
    std::vector<std::size_t> kept(band.begin() + static_cast<std::ptrdiff_t>(chosen->first),
                                  band.begin() + static_cast<std::ptrdiff_t>(chosen->last));
    band.resize(band_start);
    band.insert(band.end(), kept.begin(), kept.end());
    out.points.push_back({weighted_x / weight, weighted_y / weight});
    out.point_bin.push_back(b);
    out.point_band_start.push_back(band_start);
  }
  return out;
}

// Keep the longest chain of bins without a gap wider than one bin: isolated plastic spots (a wall corner, say)
// are not part of the slip surface.
void keep_longest_chain(BandPoints& found) {
  if (found.points.empty()) return;
  std::size_t best_first = 0, best_last = 0, first = 0;
  for (std::size_t k = 1; k <= found.points.size(); ++k) {
    if (k == found.points.size() || found.point_bin[k] - found.point_bin[k - 1] > 2) {
      if (k - 1 - first > best_last - best_first) {
        best_first = first;
        best_last = k - 1;
      }
      first = k;
    }
  }
  const std::vector<std::size_t>& starts = found.point_band_start;
  const std::size_t band_end = best_last + 1 < starts.size() ? starts[best_last + 1] : found.band.size();
  found.band = std::vector<std::size_t>(found.band.begin() + static_cast<std::ptrdiff_t>(starts[best_first]),
                                        found.band.begin() + static_cast<std::ptrdiff_t>(band_end));
  found.points = std::vector<slope::Point>(found.points.begin() + static_cast<std::ptrdiff_t>(best_first),
                                           found.points.begin() + static_cast<std::ptrdiff_t>(best_last + 1));
}

// A column centre is off the band's centre line where the band is steep (its vertical extent is not symmetric
// about the line). Move every point along the local normal to the plastic-strain-weighted mean offset of the band
// particles beside it (within half a bin along the tangent); twice, as the normals move.
void centre_on_band(const std::vector<std::size_t>& band, const ParticleSnapshot& particles,
                    const std::vector<double>& xs, const std::vector<double>& ys, FailureSurface& surface) {
  const std::size_t m = surface.points.size();
  for (int pass = 0; pass < 2 && m >= 3; ++pass) {
    std::vector<slope::Point> moved = surface.points;
    for (std::size_t k = 0; k < m; ++k) {
      const auto& before = surface.points[k == 0 ? 0 : k - 1];
      const auto& after = surface.points[k + 1 == m ? m - 1 : k + 1];
      double tx = after.x - before.x, ty = after.y - before.y;
      const double length = std::hypot(tx, ty);
      if (length <= 0.0) continue;
      tx /= length;
      ty /= length;
      const double nx = -ty, ny = tx;
      double weight = 0.0, offset = 0.0;
      for (std::size_t i : band) {
        const double dx = xs[i] - surface.points[k].x, dy = ys[i] - surface.points[k].y;
        if (std::abs(dx * tx + dy * ty) > 0.5 * surface.bin_width) continue;
        const double normal = dx * nx + dy * ny;
        if (std::abs(normal) > 4.0 * surface.bin_width) continue;  // another branch of the band
        weight += particles.plastic_strain[i];
        offset += particles.plastic_strain[i] * normal;
      }
      if (weight <= 0.0) continue;
      // At most one bin per pass: the correction is a centring, not a jump to another part of the band.
      const double shift = std::clamp(offset / weight, -surface.bin_width, surface.bin_width);
      moved[k] = {surface.points[k].x + nx * shift, surface.points[k].y + ny * shift};
    }
    surface.points = std::move(moved);
  }
}

// The surface is a graph y(x): drop points that fall back in x behind their predecessor.
std::vector<slope::Point> monotone_in_x(const std::vector<slope::Point>& points) {
  std::vector<slope::Point> monotone;
  for (const auto& p : points)
    if (monotone.empty() || p.x > monotone.back().x) monotone.push_back(p);
  return monotone;
}

}  // namespace

FailureSurface plastic_band_surface(const ParticleSnapshot& particles, const BandOptions& options) {
  FailureSurface surface;
  surface.plastic_strain_threshold = options.plastic_strain_threshold;
  surface.bin_width = options.bin_width > 0.0 ? options.bin_width : 2.0 * particles.spacing;
  const std::vector<double>& xs = options.initial_configuration ? particles.x0 : particles.x;
  const std::vector<double>& ys = options.initial_configuration ? particles.y0 : particles.y;
  if (xs.empty() || surface.bin_width <= 0.0) return surface;

  BandPoints found = band_points_per_bin(particles, options, xs, ys, surface.bin_width);
  keep_longest_chain(found);
  surface.points = std::move(found.points);
  surface.band_particles = found.band.size();
  centre_on_band(found.band, particles, xs, ys, surface);
  surface.points = monotone_in_x(surface.points);
  return surface;
}

std::optional<CircleFit> fit_circle(const std::vector<slope::Point>& points) {
  const std::size_t n = points.size();
  if (n < 3) return std::nullopt;
  // Work relative to the centroid for conditioning.
  double mx = 0.0, my = 0.0;
  for (const auto& p : points) {
    mx += p.x;
    my += p.y;
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);

  // Algebraic (Kasa) fit: x^2 + y^2 + D x + E y + F = 0.
  Eigen::MatrixXd a(static_cast<Eigen::Index>(n), 3);
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double u = points[i].x - mx, v = points[i].y - my;
    const auto r = static_cast<Eigen::Index>(i);
    a(r, 0) = u;
    a(r, 1) = v;
    a(r, 2) = 1.0;
    rhs(r) = -(u * u + v * v);
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const auto& sv = svd.singularValues();
  if (sv(2) <= 1e-12 * sv(0)) return std::nullopt;
  const Eigen::Vector3d def = svd.solve(rhs);
  double cu = -0.5 * def(0), cv = -0.5 * def(1);
  double radius_sq = cu * cu + cv * cv - def(2);
  if (!(radius_sq > 0.0)) return std::nullopt;
  double radius = std::sqrt(radius_sq);

  // Gauss-Newton on the orthogonal residuals d_i = |p_i - c| - R.
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::MatrixXd jacobian(static_cast<Eigen::Index>(n), 3);
    Eigen::VectorXd residual(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
      const double du = points[i].x - mx - cu, dv = points[i].y - my - cv;
      const double dist = std::max(std::hypot(du, dv), 1e-300);
      const auto r = static_cast<Eigen::Index>(i);
      residual(r) = dist - radius;
      jacobian(r, 0) = -du / dist;
      jacobian(r, 1) = -dv / dist;
      jacobian(r, 2) = -1.0;
    }
    const Eigen::Vector3d step = jacobian.colPivHouseholderQr().solve(-residual);
    cu += step(0);
    cv += step(1);
    radius += step(2);
    if (step.norm() <= 1e-12 * std::max(1.0, radius)) break;
  }
  if (!std::isfinite(radius) || radius <= 0.0) return std::nullopt;

  CircleFit fit;
  fit.circle = {cu + mx, cv + my, radius};
  double sum_sq = 0.0;
  for (const auto& p : points) {
    const double d = std::abs(std::hypot(p.x - fit.circle.xc, p.y - fit.circle.yc) - radius);
    sum_sq += d * d;
    fit.max_residual = std::max(fit.max_residual, d);
  }
  fit.rms_residual = std::sqrt(sum_sq / static_cast<double>(n));
  return fit;
}

}  // namespace coupling
