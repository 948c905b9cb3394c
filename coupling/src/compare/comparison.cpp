#include "coupling/compare/comparison.hpp"
#include "coupling/compare/sph_surface_lem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "coupling/compare/sliding_mass.hpp"
#include "coupling/scene/json_reader.hpp"
#include "slope/methods.hpp"
#include "slope/slices.hpp"

namespace coupling {

namespace {

// Per x-bin lowest initial height of the particles displaced more than delta.
Polyline displaced_base(const ParticleSnapshot& p, double delta, double bin, std::size_t* count) {
  Polyline base;
  if (p.x0.empty()) return base;
  const auto [lo, hi] = std::minmax_element(p.x0.begin(), p.x0.end());
  const int bins = static_cast<int>(std::floor((*hi - *lo) / bin)) + 1;
  std::vector<double> lowest(static_cast<std::size_t>(bins), std::numeric_limits<double>::infinity());
  std::vector<double> at_x(static_cast<std::size_t>(bins), 0.0);
  *count = 0;
  for (std::size_t i = 0; i < p.x0.size(); ++i) {
    if (std::hypot(p.x[i] - p.x0[i], p.y[i] - p.y0[i]) <= delta) continue;
    ++*count;
    const auto b = static_cast<std::size_t>(std::clamp(static_cast<int>((p.x0[i] - *lo) / bin), 0, bins - 1));
    if (p.y0[i] < lowest[b]) {
      lowest[b] = p.y0[i];
      at_x[b] = *lo + (static_cast<double>(b) + 0.5) * bin;
    }
  }
  for (std::size_t b = 0; b < lowest.size(); ++b)
    if (std::isfinite(lowest[b])) base.push_back({at_x[b], lowest[b] - 0.5 * p.spacing});
  return base;
}

// Top of the particles per x-bin in the current configuration.
Polyline free_surface(const ParticleSnapshot& p, double bin) {
  Polyline top;
  if (p.x.empty()) return top;
  const auto [lo, hi] = std::minmax_element(p.x.begin(), p.x.end());
  const int bins = static_cast<int>(std::floor((*hi - *lo) / bin)) + 1;
  std::vector<double> highest(static_cast<std::size_t>(bins), -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    const auto b = static_cast<std::size_t>(std::clamp(static_cast<int>((p.x[i] - *lo) / bin), 0, bins - 1));
    highest[b] = std::max(highest[b], p.y[i]);
  }
  for (std::size_t b = 0; b < highest.size(); ++b)
    if (std::isfinite(highest[b])) top.push_back({*lo + (static_cast<double>(b) + 0.5) * bin, highest[b] + 0.5 * p.spacing});
  return top;
}

std::string format(const char* pattern, double a, double b = 0.0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, pattern, a, b);
  return buffer;
}

}  // namespace

Polyline lem_surface_polyline(const slope::SlipMass& mass, int segments) {
  if (!mass.surface.empty()) return mass.surface;  // a polyline surface: its own vertices
  const double from = std::min(mass.entry.x, mass.exit.x), to = std::max(mass.entry.x, mass.exit.x);
  return circle_arc(mass.circle, from, to, segments);
}

SphFailure extract_sph_failure(const ParticleSnapshot& particles, const Polyline& initial_ground,
                               const ComparisonOptions& options) {
  SphFailure out;
  out.band = plastic_band_surface(particles, options.band);
  out.fitted_circle = fit_circle(out.band.points);
  if (!out.band.points.empty()) {
    const auto& first = out.band.points.front();
    const auto& last = out.band.points.back();
    out.entry = slope::Point{first.x, polyline_height(initial_ground, first.x)};
    out.exit = slope::Point{last.x, polyline_height(initial_ground, last.x)};
    // Entry is the upper end (behind the crest), exit the lower end (near the toe).
    if (out.entry->y < out.exit->y) std::swap(out.entry, out.exit);
  }
  out.displacement_threshold =
      options.displacement_threshold > 0.0 ? options.displacement_threshold : 2.0 * particles.spacing;
  const double bin = out.band.bin_width > 0.0 ? out.band.bin_width : 2.0 * particles.spacing;
  out.displaced_mass_base = displaced_base(particles, out.displacement_threshold, bin, &out.displaced_particles);
  out.band_vs_displacement = compare_surfaces(out.band.points, out.displaced_mass_base);
  out.final_ground = free_surface(particles, bin);

  // Toe: the lowest point of the initial ground (the first one met going down the slope). Debris beyond it
  // is soil standing more than one spacing above the initial ground.
  if (!initial_ground.empty()) {
    const auto toe = std::min_element(initial_ground.begin(), initial_ground.end(),
                                      [](const auto& a, const auto& b) { return a.y < b.y; });
    const bool descends_right = initial_ground.front().y > initial_ground.back().y;
    const auto toe_point = descends_right ? *toe : *std::min_element(initial_ground.rbegin(), initial_ground.rend(),
                                                                     [](const auto& a, const auto& b) { return a.y < b.y; });
    out.initial_toe_x = toe_point.x;
    for (const auto& p : out.final_ground) {
      if (p.y - polyline_height(initial_ground, p.x) <= particles.spacing) continue;
      const double advance = descends_right ? p.x - out.initial_toe_x : out.initial_toe_x - p.x;
      out.farthest_toe_advance = std::max(out.farthest_toe_advance, advance);
    }
  }
  return out;
}

namespace {

// The SPH fitted circle as a slip mass of the section, on which every LE method is evaluated.
struct SphCircleMass {
  std::optional<slope::SlipMass> mass;
  std::string reason;         // why the circle is not an admissible slip circle
  double raised = 0.0;        // m the circle was raised to clear the base
};

SphCircleMass sph_circle_mass(const slope::Section& section, const SphFailure& sph) {
  SphCircleMass out;
  if (!(sph.fitted_circle && sph.entry && sph.exit)) return out;
  // A band lying on the rigid base gives a fitted circle that dips a little below it, which no slip circle
  // may do. Raise the circle by the dip when it is within one particle spacing (half a bin).
  slope::Circle circle = sph.fitted_circle->circle;
  const double from = std::min(sph.entry->x, sph.exit->x), to = std::max(sph.entry->x, sph.exit->x);
  const double lowest_x = std::clamp(circle.xc, from, to);
  const double lowest_y = circle.yc - std::sqrt(std::max(0.0, circle.radius * circle.radius -
                                                             (lowest_x - circle.xc) * (lowest_x - circle.xc)));
  const double dip = section.bottom_y - lowest_y;
  if (dip > 0.0 && dip <= 0.5 * sph.band.bin_width) {
    out.raised = dip + 1e-6;
    circle.yc += out.raised;
  }
  slope::SliceOptions slicing;
  out.mass = slope::slice_circle(section, circle, slicing, &out.reason);
  return out;
}

// The method's minimum FS next to its FS on the SPH circle and on the SPH surface itself.
void compare_factors(const slope::CriticalSurface& critical, const SphFailure& sph, const SphCircleMass& sph_mass,
                     const SphSurfaceForLem& surface, MethodComparison& m) {
  if (surface.mass) {
    const auto on_surface = slope::factor_of_safety(*surface.mass, critical.method);
    m.factor_of_safety_on_sph_surface = on_surface.factor_of_safety;
    if (!on_surface.factor_of_safety) m.on_sph_surface_error = on_surface.error;
  } else {
    m.on_sph_surface_error = "the SPH surface is not an admissible slip surface: " + surface.reason;
  }
  m.lem_factor_of_safety = critical.result.factor_of_safety;
  if (sph_mass.mass) {
    const auto on_sph = slope::factor_of_safety(*sph_mass.mass, critical.method);
    m.factor_of_safety_on_sph_circle = on_sph.factor_of_safety;
    if (!on_sph.factor_of_safety) m.on_sph_circle_error = on_sph.error;
  } else {
    m.on_sph_circle_error = sph.fitted_circle ? "the SPH circle is not an admissible slip circle: " + sph_mass.reason
                                              : std::string("no circle could be fitted to the SPH surface");
  }
}

// The plain-language verdict against one critical circle.
std::string verdict_text(const std::string& key, const slope::CriticalSurface& critical, const SphFailure& sph,
                         const Polyline& lem_line, const SurfaceDistances& distances, const MassOverlap& overlap) {
  const slope::SlipMass& mass = *critical.mass;
  const double mid_x = 0.5 * (distances.common_from_x + distances.common_to_x);
  const double depth_difference = polyline_height(lem_line, mid_x) - polyline_height(sph.band.points, mid_x);
  std::ostringstream verdict;
  verdict << "Against the " << key << " critical circle (FS = "
          << format("%.3f", critical.result.factor_of_safety.value_or(std::nan(""))) << "): the SPH surface is "
          << format("%.2f m ", std::abs(depth_difference)) << (depth_difference >= 0 ? "deeper" : "shallower")
          << " at mid-span (x = " << format("%.1f m", mid_x) << "), enters "
          << format("%.2f m", std::abs(sph.entry->x - mass.entry.x))
          << (std::abs(sph.entry->x - mass.entry.x) < 2.0 * sph.band.bin_width + 1e-9 ? " (same entry)" : "")
          << " from the LEM entry and exits " << format("%.2f m", std::abs(sph.exit->x - mass.exit.x))
          << " from the LEM exit; mean normal distance " << format("%.2f m", distances.mean_normal_distance)
          << ", sliding masses overlap " << format("%.0f %%", 100.0 * overlap.intersection_over_union)
          << " (intersection over union).";
  return verdict.str();
}

// Where one LE mass lies against the SPH band: offsets, distances, areas, overlap.
struct Placement {
  Polyline lem_line;
  SurfaceDistances distances;
  MassOverlap overlap;
};

Placement place(const slope::SlipMass& mass, const SphFailure& sph, const Polyline& ground,
                const Polyline& sph_polygon, SurfaceGeometry& g) {
  Placement p;
  p.lem_line = lem_surface_polyline(mass);
  p.distances = compare_surfaces(sph.band.points, p.lem_line);
  if (sph.entry) {
    g.entry_offset_m = slope::Point{sph.entry->x - mass.entry.x, sph.entry->y - mass.entry.y};
    g.exit_offset_m = slope::Point{sph.exit->x - mass.exit.x, sph.exit->y - mass.exit.y};
  }
  g.common_from_x_m = p.distances.common_from_x;
  g.common_to_x_m = p.distances.common_to_x;
  g.mean_normal_distance_m = p.distances.mean_normal_distance;
  g.max_normal_distance_m = p.distances.max_normal_distance;
  g.area_between_m2 = p.distances.area_between;
  p.overlap = mass_overlap(sph_polygon, sliding_mass_polygon(ground, p.lem_line));
  g.sph_sliding_mass_area_m2 = p.overlap.area_a;
  g.lem_sliding_mass_area_m2 = p.overlap.area_b;
  g.intersection_area_m2 = p.overlap.intersection_area;
  g.intersection_over_union = p.overlap.intersection_over_union;
  return p;
}

// The comparison with one method's critical surface (and its non-circular one, when given); `verdict` is set when
// this method tells it.
MethodComparison compare_method(const slope::CriticalSurface& critical, const slope::NonCircularSurface* noncircular,
                                const SphFailure& sph, const SphCircleMass& sph_mass,
                                const SphSurfaceForLem& sph_surface, const Polyline& ground,
                                const Polyline& sph_polygon, bool tells_verdict, std::optional<std::string>& verdict) {
  const std::string key(slope::method_key(critical.method));
  MethodComparison m;
  m.method = key;
  compare_factors(critical, sph, sph_mass, sph_surface, m);
  if (!critical.mass || sph.band.points.size() < 2) return m;
  m.has_geometry = true;
  const Placement circle = place(*critical.mass, sph, ground, sph_polygon, m);
  std::optional<std::string> on_polyline;
  if (noncircular != nullptr && noncircular->mass && noncircular->result.factor_of_safety) {
    NonCircularComparison n;
    n.factor_of_safety = *noncircular->result.factor_of_safety;
    n.from_circle = noncircular->from_circle;
    const Placement polyline = place(*noncircular->mass, sph, ground, sph_polygon, n);
    if (!n.from_circle)
      on_polyline = " Against its non-circular critical surface (FS = " + format("%.3f", n.factor_of_safety) +
                    "): mean normal distance " + format("%.2f m", polyline.distances.mean_normal_distance) +
                    ", overlap " + format("%.0f %%", 100.0 * polyline.overlap.intersection_over_union) + ".";
    m.noncircular = n;
  }
  if (!verdict && tells_verdict && sph.entry)
    verdict = verdict_text(key, critical, sph, circle.lem_line, circle.distances, circle.overlap) +
              on_polyline.value_or("");
  return m;
}

// The verdict's sentence on the LE factor of safety of the SPH surface itself (Bishop's, else the first method's).
std::string like_for_like_text(const ComparisonResult& result) {
  const MethodComparison* m = result.find("bishop");
  if (m == nullptr && !result.methods.empty()) m = &result.methods.front();
  if (m == nullptr || !m->factor_of_safety_on_sph_surface || !result.sph_surface_mass) return {};
  std::ostringstream text;
  text << " Limit equilibrium on the SPH surface itself";
  if (result.sph_surface_mass->crack_depth > 0.0)
    text << " (its scarp as a " << format("%.2f m", result.sph_surface_mass->crack_depth) << " tension crack)";
  text << ": FS = " << format("%.3f", *m->factor_of_safety_on_sph_surface) << " (" << m->method << ", against "
       << format("%.3f", m->lem_factor_of_safety.value_or(std::nan(""))) << " on its critical circle).";
  return text.str();
}

// The verdict when there is no SPH surface to set against a critical one: the SPH run shows no plastic band (the
// slope stands in SPH), told against the lowest limit-equilibrium factor of safety; or no method found a surface.
std::string verdict_without_surfaces(const SphFailure& sph, const std::vector<MethodComparison>& methods) {
  const MethodComparison* lowest = nullptr;
  for (const MethodComparison& m : methods)
    if (m.lem_factor_of_safety && (!lowest || *m.lem_factor_of_safety < *lowest->lem_factor_of_safety)) lowest = &m;
  if (!lowest) return "No comparison: no limit-equilibrium method found a critical surface.";
  if (sph.entry) return "No comparison: the SPH plastic band could not be set against a critical surface.";
  std::ostringstream text;
  text << "No surface to compare: the SPH run shows no plastic band above the threshold, so the slope stands in SPH; ";
  if (*lowest->lem_factor_of_safety >= 1.0) {
    text << "limit equilibrium agrees (every method's factor of safety is above 1, the lowest "
         << lowest->method << " " << format_number(*lowest->lem_factor_of_safety) << ").";
  } else {
    text << "limit equilibrium does not (" << lowest->method << " FS = "
         << format_number(*lowest->lem_factor_of_safety)
         << " < 1): the SPH run may be too short for the failure to develop, or the band threshold too high.";
  }
  return text.str();
}

}  // namespace

const MethodComparison* ComparisonResult::find(const std::string& method) const {
  for (const MethodComparison& m : methods)
    if (m.method == method) return &m;
  return nullptr;
}

ComparisonResult compare_with_lem(const slope::Section& section, const SphFailure& sph, const slope::SearchResult& lem,
                                  const ComparisonOptions& options, const slope::NonCircularResult* noncircular) {
  ComparisonResult result;
  result.sph = sph;
  result.initial_configuration = options.band.initial_configuration;
  const Polyline ground = section.profile_lines.front().points;

  // Evaluate every method on the SPH fitted circle.
  const SphCircleMass sph_mass = sph_circle_mass(section, sph);
  result.circle_raised_for_lem_m = sph_mass.raised;
  const Polyline sph_polygon = sliding_mass_polygon(ground, sph.band.points);
  // ... and on the SPH surface itself.
  const SphSurfaceForLem sph_surface = sph_surface_for_lem(section, sph);
  result.sph_surface_for_lem = sph_surface.polyline;
  result.sph_surface_mass = sph_surface.mass;
  result.sph_surface_for_lem_error = sph_surface.mass ? std::string() : sph_surface.reason;
  result.sph_scarp_angle = sph_surface.scarp_angle;
  result.sph_largest_convex_kink = sph_surface.largest_convex_kink;
  result.sph_surface_dropped_vertices = sph_surface.dropped_vertices;

  bool has_bishop = false;
  for (const auto& critical : lem.methods)
    has_bishop = has_bishop || (critical.method == slope::Method::bishop && critical.mass.has_value());
  std::optional<std::string> verdict;
  for (const auto& critical : lem.methods) {
    // The verdict is told against Bishop's circle when Bishop was asked for, else the first method with a surface.
    const bool tells_verdict = critical.method == slope::Method::bishop || !has_bishop;
    const slope::NonCircularSurface* polyline = nullptr;
    if (noncircular != nullptr)
      for (const slope::NonCircularSurface& s : noncircular->methods)
        if (s.method == critical.method) polyline = &s;
    result.methods.push_back(compare_method(critical, polyline, sph, sph_mass, sph_surface, ground, sph_polygon,
                                            tells_verdict, verdict));
  }
  result.verdict = verdict ? *verdict : verdict_without_surfaces(sph, result.methods);
  if (verdict) result.verdict += like_for_like_text(result);
  return result;
}

}  // namespace coupling
