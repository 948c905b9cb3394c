// The figures of an isph run (coupling/output/isph_figures.hpp).
#include "coupling/output/isph_figures.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <tuple>

#include "coupling/output/svg.hpp"
#include "coupling/scene/json_reader.hpp"
#include "sph/fluid/reference_fronts.hpp"

namespace coupling {

namespace {

using Legend = std::vector<std::tuple<std::string, std::string, std::string>>;

const char* const kLineColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf"};

std::string colour_of(std::size_t k) { return kLineColours[k % std::size(kLineColours)]; }

}  // namespace

std::string isph_snapshot_svg(const IsphSnapshot& s, const std::string& title) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0, p0 = 0.0, p1 = 0.0;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    x0 = std::min(x0, s.x[i]);
    x1 = std::max(x1, s.x[i]);
    y0 = std::min(y0, s.y[i]);
    y1 = std::max(y1, s.y[i]);
    if (s.kind[i] != 0) continue;
    p0 = std::min(p0, s.pressure[i] / 1000.0);
    p1 = std::max(p1, s.pressure[i] / 1000.0);
  }
  if (!(p1 > p0)) p1 = p0 + 1e-3;
  SvgCanvas canvas(x0 - s.spacing, x1 + s.spacing, y0 - s.spacing, y1 + s.spacing, 800.0);
  canvas.title(title + ": particles at t = " + format_number(s.time) + " s");
  canvas.axes("x (m)", "y (m)");
  const double radius = std::max(0.8, 0.5 * s.spacing * canvas.scale());
  for (std::size_t i = 0; i < s.x.size(); ++i)
    canvas.dot(s.x[i], s.y[i], radius,
               s.kind[i] == 0 ? to_hex(colour_map((s.pressure[i] / 1000.0 - p0) / (p1 - p0))) : "#b8b8b8");
  canvas.colour_bar(p0, p1, "pressure (kPa)");
  canvas.legend({{"#b8b8b8", "", "wall particles (fixed)"}});
  return canvas.str();
}

std::string isph_gauges_svg(const MonitorTable& monitors, const std::vector<Gauge>& gauges, double still_water,
                            const std::string& title) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<std::vector<std::pair<double, double>>> series;
  for (const Gauge& g : gauges) {
    series.push_back(monitor_column(monitors, g.name + "_m"));
    for (const auto& [t, eta] : series.back()) {
      lo = std::min(lo, eta);
      hi = std::max(hi, eta);
    }
  }
  if (!std::isfinite(lo)) lo = hi = 0.0;
  const double t_end = monitors.times.empty() ? 1.0 : monitors.times.back();
  SvgCanvas canvas = time_canvas(t_end, std::min(lo, 0.0), hi, title + ": surface at the gauges",
                                 "surface elevation above y = " + format_number(still_water) + " m (m)");
  Legend legend;
  for (std::size_t k = 0; k < gauges.size(); ++k) {
    std::vector<slope::Point> line;
    for (const auto& [t, eta] : series[k]) line.push_back({t, eta});
    canvas.polyline(line, colour_of(k), 1.6);
    legend.emplace_back(colour_of(k), "", gauges[k].name + " at x = " + format_number(gauges[k].x) + " m");
  }
  canvas.legend(legend);
  return canvas.str();
}

std::string isph_front_svg(const MonitorTable& monitors, const FrontFigureReferences& r, const std::string& title) {
  const std::vector<std::pair<double, double>> front = monitor_column(monitors, "front_x_m");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& [t, x] : front) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  if (!std::isfinite(lo)) lo = hi = 0.0;
  const double t_end = monitors.times.empty() ? 1.0 : monitors.times.back();
  std::vector<std::pair<double, double>> shown;  // the reference points within the run's time
  for (const auto& p : r.points)
    if (p.first <= t_end) shown.push_back(p);
  for (const auto& [t, x] : shown) hi = std::max(hi, x);
  if (r.far_wall_x) hi = std::max(hi, *r.far_wall_x);
  SvgCanvas canvas = time_canvas(t_end, lo, hi, title + ": surge front", "front x (m)");
  Legend legend;
  std::vector<slope::Point> line;
  for (const auto& [t, x] : front) line.push_back({t, x});
  canvas.polyline(line, colour_of(0), 1.8);
  legend.emplace_back(colour_of(0), "", "computed front (largest x of the water + dx/2)");
  for (const auto& [t, x] : shown) canvas.dot(t, x, 3.5, colour_of(1));
  if (!shown.empty()) legend.emplace_back(colour_of(1), "1,6", r.points_label + " (dots)");
  if (r.ritter_dam_x && r.ritter_depth && r.gravity) {
    // x = x_dam + 2 sqrt(g h0) t, drawn up to the top of the plot
    const double speed = 2.0 * std::sqrt(*r.gravity * *r.ritter_depth), top = hi + 0.05 * (hi - lo);
    const double t_top = std::min(t_end, std::max(0.0, (top - *r.ritter_dam_x) / speed));
    canvas.polyline({{0.0, *r.ritter_dam_x}, {t_top, sph::fluid::ritter_front_x(*r.ritter_dam_x, *r.ritter_depth,
                                                                                  *r.gravity, t_top)}},
                    colour_of(2), 1.4, "6,4");
    legend.emplace_back(colour_of(2), "6,4", "Ritter (1892): x_dam + 2 sqrt(g h0) t, h0 = " +
                                                 format_number(*r.ritter_depth) + " m");
  }
  if (r.far_wall_x) {
    canvas.polyline({{0.0, *r.far_wall_x}, {t_end, *r.far_wall_x}}, "#777", 1.0, "2,3");
    legend.emplace_back("#777", "2,3", "the tank's right wall");
  }
  canvas.legend(legend);
  return canvas.str();
}

}  // namespace coupling
