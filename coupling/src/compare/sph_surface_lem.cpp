// The SPH failure surface as a limit-equilibrium slip surface (sph_surface_lem.hpp).
//
// The band line of the comparison runs from the bin nearest the entry to the bin nearest the exit; its ends are
// carried vertically up to the initial ground (SphFailure::entry, exit). At the upper end that vertical step is the
// open scarp of the graben the SPH model forms behind the crest: LE practice calls it a tension crack. Here:
//   1. the band vertices, ordered from the upper end; those within half a bin (in x) of the lower end are dropped,
//      so that the surface rises to the exit point on the ground instead of meeting it vertically;
//   2. walking down from the upper end, the vertices reached by segments steeper than the Rankine active plane
//      45 deg + phi'/2 belong to the scarp; the crack bottom is the first vertex after which the band is flatter, the
//      crack depth is the ground's height above it (dry: the SPH model carries no water);
//   3. from the crack bottom a segment at 45 deg + phi'/2 up to the ground gives the surface an entry on the ground
//      (slope::slice_polyline then cuts it at the crack: at the crack bottom where the ground above is straight);
//   4. interior vertices are kept just below the ground (1 % of a bin) and not below the rigid base;
//   5. convex kinks of the band are accepted (convex_tolerance just under 90 deg): the band is analysed as the SPH
//      model found it, not made concave;
//   6. except a reversal: a band vertex that makes the surface turn back on itself by more than that (a spike of the
//      band's scatter, such as a bin point a metre below both neighbours) is dropped, the one whose removal leaves
//      the smallest reversal first, at most a tenth of the vertices; how many is reported.
#include "coupling/compare/sph_surface_lem.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "sphslope/units.hpp"

namespace coupling {

namespace {

// Friction angle of the soil at the ground surface at x: the lowest profile line at the ground there is the top of
// that soil.
double surface_friction_angle(const slope::Section& section, double x) {
  const double g = section.ground_y(x);
  std::size_t material = section.profile_lines.front().material;
  for (const slope::ProfileLine& line : section.profile_lines)
    if (slope::polyline_y(line.points, x) >= g - 1e-9 * (1.0 + std::fabs(g))) material = line.material;
  return section.materials.at(material).friction_angle;
}

// Where the line from `bottom` rising at `angle` toward the upslope side `toward` (-1: -x, +1: +x) meets the ground.
std::optional<slope::Point> up_to_ground(const slope::Section& section, slope::Point bottom, double angle, int toward) {
  double x = bottom.x;
  for (int it = 0; it < 100; ++it) {  // fixed point: converges where the ground is flatter than the line
    const double next = bottom.x + toward * (section.ground_y(x) - bottom.y) / std::tan(angle);
    if (next < section.x_min() || next > section.x_max()) return std::nullopt;
    if (std::fabs(next - x) < 1e-9 * (1.0 + std::fabs(x))) return slope::Point{next, section.ground_y(next)};
    x = next;
  }
  return std::nullopt;
}

// The largest increase of the driving inclination from one segment to the next, from the upper end (rad, >= 0).
double largest_convex_kink(const std::vector<slope::Point>& s, int toward_upper) {
  double largest = 0.0, previous = 0.0;
  for (std::size_t j = 0; j + 1 < s.size(); ++j) {
    const std::size_t k = toward_upper < 0 ? j : s.size() - 2 - j;
    const double drop = toward_upper < 0 ? s[k].y - s[k + 1].y : s[k + 1].y - s[k].y;
    const double angle = std::atan2(drop, s[k + 1].x - s[k].x);
    if (j > 0) largest = std::max(largest, angle - previous);
    previous = angle;
  }
  return largest;
}

// The largest amount by which a segment steepens over the one before it, in the direction of sliding, beyond
// `tolerance` (rad; 0: none), and the index of the vertex where it does (points left to right, `dir` = +1: sliding
// toward +x).
std::pair<double, std::size_t> worst_reversal(const std::vector<slope::Point>& s, int dir, double tolerance) {
  double worst = 0.0, previous = 0.0;
  std::size_t at = 0;
  const std::size_t n = s.size() - 1;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t k = dir > 0 ? j : n - 1 - j;  // segments from the entry
    const double angle = std::atan2(-dir * (s[k + 1].y - s[k].y), std::fabs(s[k + 1].x - s[k].x));
    if (j > 0 && angle - previous - tolerance > worst) {
      worst = angle - previous - tolerance;
      at = dir > 0 ? k : k + 1;
    }
    previous = angle;
  }
  return {worst, at};
}

// 6. Drops interior vertices at reversals (beyond `tolerance`): at each, the vertex before, at or after the turn
// whose removal leaves the smallest worst reversal. Returns how many were dropped.
int drop_reversals(std::vector<slope::Point>& s, int dir, double tolerance) {
  const std::size_t limit = std::max<std::size_t>(1, s.size() / 10);
  int dropped = 0;
  for (auto [worst, at] = worst_reversal(s, dir, tolerance); worst > 0.0 && s.size() > 3 &&
                                                             static_cast<std::size_t>(dropped) < limit;
       std::tie(worst, at) = worst_reversal(s, dir, tolerance)) {
    std::size_t best = 0;
    double best_worst = INFINITY;
    for (std::size_t k = std::max<std::size_t>(at, 2) - 1; k <= at + 1 && k + 1 < s.size(); ++k) {
      if (k == 0) continue;  // the entry and exit points stay
      std::vector<slope::Point> trial = s;
      trial.erase(trial.begin() + static_cast<std::ptrdiff_t>(k));
      const double w = worst_reversal(trial, dir, tolerance).first;
      if (w < best_worst) best_worst = w, best = k;
    }
    if (best == 0) break;
    s.erase(s.begin() + static_cast<std::ptrdiff_t>(best));
    ++dropped;
  }
  return dropped;
}

}  // namespace

SphSurfaceForLem sph_surface_for_lem(const slope::Section& section, const SphFailure& sph) {
  SphSurfaceForLem out;
  if (!sph.entry || !sph.exit || sph.band.points.size() < 2) {
    out.reason = "the SPH band has no entry and exit on the ground";
    return out;
  }
  const slope::Point entry = *sph.entry, exit = *sph.exit;
  const int toward_upper = entry.x < exit.x ? -1 : 1;  // the upslope side
  const double bin = sph.band.bin_width > 0.0 ? sph.band.bin_width : 1.0;
  // 1. band vertices from the upper end, none within half a bin of the exit
  // (kept just below the ground, 1 % of a bin, and not below the base: 4.)
  std::vector<slope::Point> band;
  const double margin = 0.01 * bin;
  for (slope::Point p : sph.band.points) {
    if (!(std::fabs(p.x - exit.x) > 0.5 * bin && (p.x - entry.x) * (exit.x - entry.x) >= 0.0)) continue;
    p.y = std::max(section.bottom_y, std::min(p.y, section.ground_y(p.x) - margin));
    band.push_back(p);
  }
  std::sort(band.begin(), band.end(), [&](const slope::Point& a, const slope::Point& b) {
    return toward_upper < 0 ? a.x < b.x : a.x > b.x;
  });
  if (band.empty()) {
    out.reason = "the SPH band has no vertex between its entry and exit";
    return out;
  }
  // 2. the scarp
  out.scarp_angle = 0.25 * sphslope::pi + 0.5 * surface_friction_angle(section, entry.x);
  std::size_t bottom = 0;
  while (bottom + 1 < band.size()) {
    const slope::Point& a = band[bottom];
    const slope::Point& b = band[bottom + 1];
    if (std::atan2(a.y - b.y, std::fabs(b.x - a.x)) <= out.scarp_angle) break;
    ++bottom;
  }
  const slope::Point crack_bottom = band[bottom];
  const double depth = section.ground_y(crack_bottom.x) - crack_bottom.y;
  // 3. the entry on the ground
  const auto top = up_to_ground(section, crack_bottom, out.scarp_angle, toward_upper);
  if (!top || !(depth > 0.0)) {
    out.reason = "the upper end of the SPH band cannot be joined to the ground at the scarp angle";
    return out;
  }
  // the surface, left to right
  std::vector<slope::Point> points{*top};
  points.insert(points.end(), band.begin() + static_cast<std::ptrdiff_t>(bottom), band.end());
  points.push_back(exit);
  if (toward_upper > 0) std::reverse(points.begin(), points.end());
  const double convex_tolerance = 0.5 * sphslope::pi - 1e-3;  // 5.
  out.dropped_vertices = drop_reversals(points, -toward_upper, convex_tolerance);  // 6.
  slope::SlipPolyline polyline;
  polyline.points = std::move(points);
  polyline.tension_crack = slope::TensionCrack{depth, false};
  polyline.convex_tolerance = convex_tolerance;
  out.mass = slope::slice_polyline(section, polyline, slope::SliceOptions{}, &out.reason);
  if (out.mass) out.largest_convex_kink = largest_convex_kink(out.mass->surface, toward_upper);
  out.polyline = std::move(polyline);
  return out;
}

}  // namespace coupling
