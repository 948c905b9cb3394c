#include "coupling/analyses/isph_waves.hpp"

#include <algorithm>
#include <cmath>

namespace coupling {

namespace {

// The first sample that is a maximum over +-window and at least `least` high.
void leading_crest(const std::vector<std::pair<double, double>>& series, double least, GaugeWave& w) {
  for (std::size_t k = 0; k < series.size(); ++k) {
    const auto [t, eta] = series[k];
    if (eta < least) continue;
    bool peak = true;
    for (std::size_t m = 0; m < series.size() && peak; ++m)
      if (m != k && std::abs(series[m].first - t) <= crest_window_s && series[m].second > eta) peak = false;
    const bool window_ends_in_run = t + crest_window_s <= series.back().first;
    if (peak && window_ends_in_run) {
      w.crest = eta;
      w.crest_at = t;
      return;
    }
  }
}

}  // namespace

GaugeWaves gauge_waves(const MonitorTable& monitors, const TankMonitors& setup, const Tank& tank, double g) {
  GaugeWaves out;
  out.depth = setup.still_water - tank.y_min;
  out.long_wave_celerity = out.depth > 0 ? std::sqrt(g * out.depth) : 0.0;
  for (const Gauge& gauge : setup.gauges) {
    auto series = monitor_column(monitors, gauge.name + "_m");
    if (series.empty()) continue;
    GaugeWave w;
    w.name = gauge.name;
    w.x = gauge.x;
    w.initial = series.front().second;
    for (auto& sample : series) sample.second -= w.initial;
    w.highest = w.lowest = series.front().second;
    for (const auto& [t, eta] : series) {
      if (eta > w.highest) {
        w.highest = eta;
        w.highest_at = t;
      }
      w.lowest = std::min(w.lowest, eta);
    }
    leading_crest(series, crest_fraction * out.depth, w);
    out.gauges.push_back(w);
  }
  for (std::size_t k = 1; k < out.gauges.size(); ++k) {
    const GaugeWave &a = out.gauges[k - 1], &b = out.gauges[k];
    if (!a.crest_at || !b.crest_at || !(*b.crest_at > *a.crest_at) || !(out.long_wave_celerity > 0)) continue;
    WaveCelerity c;
    c.from = a.name;
    c.to = b.name;
    c.speed = std::abs(b.x - a.x) / (*b.crest_at - *a.crest_at);
    c.ratio = c.speed / out.long_wave_celerity;
    out.celerity.push_back(c);
  }
  return out;
}

}  // namespace coupling
