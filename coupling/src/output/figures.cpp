#include "coupling/output/figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

#include "coupling/output/svg.hpp"

namespace coupling {

namespace {

const char* const kMethodColours[] = {"#d62728", "#1f77b4", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

struct Bounds {
  double x_min = std::numeric_limits<double>::infinity(), x_max = -std::numeric_limits<double>::infinity();
  double y_min = std::numeric_limits<double>::infinity(), y_max = -std::numeric_limits<double>::infinity();
  void add(double x, double y) {
    x_min = std::min(x_min, x);
    x_max = std::max(x_max, x);
    y_min = std::min(y_min, y);
    y_max = std::max(y_max, y);
  }
  void add(const Polyline& line) {
    for (const auto& p : line) add(p.x, p.y);
  }
  void pad(double fraction) {
    const double d = fraction * std::max(x_max - x_min, y_max - y_min);
    x_min -= d;
    x_max += d;
    y_min -= d;
    y_max += d;
  }
};

void draw_section(SvgCanvas& canvas, const slope::Section& section) {
  // Soil in light grey below the ground surface, then every profile line.
  Polyline soil = section.profile_lines.front().points;
  soil.push_back({section.x_max(), section.bottom_y});
  soil.push_back({section.x_min(), section.bottom_y});
  canvas.polygon(soil, "#e8e2d4");
  for (std::size_t k = 0; k < section.profile_lines.size(); ++k)
    canvas.polyline(section.profile_lines[k].points, "#333", k == 0 ? 1.8 : 1.0, k == 0 ? "" : "5,3");
  canvas.polyline({{section.x_min(), section.bottom_y}, {section.x_max(), section.bottom_y}}, "#333", 2.5);
  if (section.water) canvas.polyline(section.water->piezometric_line, "#1f77b4", 1.5, "8,4");
}

}  // namespace

std::string section_figure_svg(const SectionFigureData& data) {
  Bounds bounds;
  if (data.section) {
    for (const auto& line : data.section->profile_lines) bounds.add(line.points);
    bounds.add(data.section->x_min(), data.section->bottom_y);
  }
  if (data.particles)
    for (std::size_t i = 0; i < data.particles->x.size(); ++i) bounds.add(data.particles->x[i], data.particles->y[i]);
  for (const auto& s : data.lem_surfaces) bounds.add(s.points);
  bounds.pad(0.03);

  SvgCanvas canvas(bounds.x_min, bounds.x_max, bounds.y_min, bounds.y_max);
  canvas.title(data.title);
  if (data.section) draw_section(canvas, *data.section);

  std::vector<std::tuple<std::string, std::string, std::string>> legend;
  if (data.particles && !data.particles->x.empty()) {
    const auto& strain = data.particles->plastic_strain;
    double top = 0.0;
    for (double e : strain) top = std::max(top, e);
    top = top > 0.0 ? top : 1.0;
    const double radius = std::max(0.8, 0.5 * data.particles->spacing * canvas.scale());
    for (std::size_t i = 0; i < data.particles->x.size(); ++i)
      canvas.dot(data.particles->x[i], data.particles->y[i], radius, to_hex(colour_map(strain[i] / top)));
    canvas.colour_bar(0.0, top, "accumulated plastic strain (-)");
  }
  if (data.section) legend.emplace_back("#333", "", "initial ground surface");
  if (!data.final_ground.empty()) {
    canvas.polyline(data.final_ground, "#000", 2.0, "2,2");
    legend.emplace_back("#000", "2,2", "final ground surface");
  }
  for (std::size_t k = 0; k < data.lem_surfaces.size(); ++k) {
    const std::string colour = kMethodColours[k % std::size(kMethodColours)];
    canvas.polyline(data.lem_surfaces[k].points, colour, 2.0);
    legend.emplace_back(colour, "", data.lem_surfaces[k].label);
  }
  if (data.sph_surface) {
    canvas.polyline(data.sph_surface->points, "#ffffff", 4.0);
    canvas.polyline(data.sph_surface->points, "#000000", 2.0, "7,3");
    legend.emplace_back("#000000", "7,3", data.sph_surface->label);
  }
  if (data.sph_fitted_circle) {
    canvas.polyline(data.sph_fitted_circle->points, "#2ca02c", 1.5, "3,3");
    legend.emplace_back("#2ca02c", "3,3", data.sph_fitted_circle->label);
  }
  if (!legend.empty()) canvas.legend(legend);
  canvas.axes();
  return canvas.str();
}

std::string fs_map_svg(const slope::Section& section, const std::vector<slope::FsMapEntry>& fs_map,
                       const std::optional<slope::Circle>& critical, const std::string& title) {
  Bounds bounds;
  for (const auto& line : section.profile_lines) bounds.add(line.points);
  bounds.add(section.x_min(), section.bottom_y);
  // Centres of nearly flat circles lie far above the section; the map shows the window around the section
  // (a quarter of its width on each side, three quarters above) and says how many centres it leaves out.
  const double span = bounds.x_max - bounds.x_min;
  const double window_x_min = bounds.x_min - 0.25 * span, window_x_max = bounds.x_max + 0.25 * span;
  const double window_y_min = bounds.y_min, window_y_max = bounds.y_max + 0.75 * span;
  std::vector<const slope::FsMapEntry*> shown;
  for (const auto& entry : fs_map)
    if (entry.circle.xc >= window_x_min && entry.circle.xc <= window_x_max && entry.circle.yc >= window_y_min &&
        entry.circle.yc <= window_y_max)
      shown.push_back(&entry);
  double fs_min = std::numeric_limits<double>::infinity(), fs_max = 0.0;
  for (const auto& entry : fs_map) {
    fs_min = std::min(fs_min, entry.factor_of_safety);
    fs_max = std::max(fs_max, entry.factor_of_safety);
  }
  for (const auto* entry : shown) {
    bounds.add(entry->circle.xc, entry->circle.yc);
  }
  if (critical) bounds.add(critical->xc, critical->yc);
  bounds.pad(0.03);
  // Colour up to twice the minimum: the interesting range; higher values saturate.
  const double fs_top = std::isfinite(fs_min) ? std::min(fs_max, 2.0 * fs_min) : 1.0;
  if (!std::isfinite(fs_min)) fs_min = 0.0;

  SvgCanvas canvas(bounds.x_min, bounds.x_max, bounds.y_min, bounds.y_max);
  const std::size_t hidden = fs_map.size() - shown.size();
  canvas.title(title + " - " + std::to_string(fs_map.size()) + " trial circles" +
               (hidden > 0 ? ", " + std::to_string(hidden) + " centres far above the section not shown" : ""));
  draw_section(canvas, section);
  // Highest factors first so the low (critical) ones are drawn on top.
  std::vector<const slope::FsMapEntry*> order = shown;
  std::sort(order.begin(), order.end(),
            [](const auto* a, const auto* b) { return a->factor_of_safety > b->factor_of_safety; });
  for (const auto* entry : order) {
    const double t = fs_top > fs_min ? (entry->factor_of_safety - fs_min) / (fs_top - fs_min) : 0.0;
    canvas.dot(entry->circle.xc, entry->circle.yc, 2.5, to_hex(colour_map(1.0 - t)));
  }
  std::vector<std::tuple<std::string, std::string, std::string>> legend;
  if (critical) {
    Polyline arc;
    const double x_from = critical->xc - critical->radius, x_to = critical->xc + critical->radius;
    for (const auto& p : circle_arc(*critical, x_from, x_to, 400))
      if (p.y <= section.ground_y(p.x)) arc.push_back(p);
    canvas.polyline(arc, "#d62728", 2.0);
    canvas.dot(critical->xc, critical->yc, 4.0, "#d62728");
    char label[64];
    std::snprintf(label, sizeof label, "critical circle (FS = %.3f)", fs_min);
    legend.emplace_back("#d62728", "", label);
  }
  legend.emplace_back("#333", "", "ground surface");
  canvas.legend(legend);
  // The colour bar runs from high FS (dark) to low FS (yellow): reverse its labels.
  canvas.colour_bar(fs_top, fs_min, "factor of safety (-), centres");
  canvas.axes();
  return canvas.str();
}

}  // namespace coupling
