// A coupled run's slide impact against Heller & Hager (2010) (coupling/analyses/coupled_impact.hpp).
#include "coupling/analyses/coupled_impact.hpp"

#include <cmath>

namespace coupling {

namespace {

// The first time the centroid is at or below the still water, with the speed and thickness there (linear between
// the rows either side); false with the reason when it starts below it or never gets there.
bool impact_row(const MonitorTable& slide, double still_water, CoupledImpact& out) {
  const auto y = monitor_column(slide, "centroid_y_m"), v = monitor_column(slide, "centroid_speed_m_s"),
             s = monitor_column(slide, slide_thickness_column);
  if (y.empty() || y.size() != v.size() || y.size() != s.size()) {
    out.missing = "slide.csv lacks the centroid or the thickness";
    return false;
  }
  if (y[0].second <= still_water) {
    out.missing = "the slide's centroid starts at or below the still water (a submarine slide has no impact)";
    return false;
  }
  for (std::size_t k = 1; k < y.size(); ++k)
    if (y[k].second <= still_water) {
      const double f = (y[k - 1].second - still_water) / (y[k - 1].second - y[k].second);
      out.time = y[k - 1].first + f * (y[k].first - y[k - 1].first);
      out.slide.speed = v[k - 1].second + f * (v[k].second - v[k - 1].second);
      out.slide.thickness = s[k - 1].second + f * (s[k].second - s[k - 1].second);
      return true;
    }
  out.missing = "the slide's centroid never reached the still water";
  return false;
}

}  // namespace

CoupledImpact coupled_impact(const MonitorTable& slide, const MonitorTable& monitors, const SlideImpactSetup& setup,
                             const TankMonitors& gauges, const Tank& tank, double mass_per_width, double g,
                             double rho_w) {
  CoupledImpact out;
  if (!impact_row(slide, gauges.still_water, out)) return out;
  out.slide.mass_per_width = mass_per_width;
  out.slide.angle_deg = setup.ramp_angle_deg;
  out.slide.depth = gauges.still_water - tank.y_min;
  out.predicted = heller_hager_impulse_wave(out.slide, g, rho_w);
  const GaugeWaves waves = gauge_waves(monitors, gauges, tank, g);
  for (const GaugeWave& w : waves.gauges)
    if (out.largest_crest_gauge.empty() || w.highest > out.largest_crest) {
      out.largest_crest_gauge = w.name;
      out.largest_crest = w.highest;
      out.largest_crest_at = w.highest_at;
      out.largest_crest_distance = w.x - setup.shoreline_x;
    }
  for (std::size_t k = 0; k + 1 < waves.gauges.size(); ++k) {
    const GaugeWave &a = waves.gauges[k], &b = waves.gauges[k + 1];
    if (!a.crest || !b.crest || !(*b.crest_at > *a.crest_at)) continue;
    const double amplitude = 0.5 * (*a.crest + *b.crest);
    out.celerity.push_back({a.name, b.name, (b.x - a.x) / (*b.crest_at - *a.crest_at),
                            std::sqrt(g * (out.slide.depth + amplitude))});
  }
  return out;
}

}  // namespace coupling
