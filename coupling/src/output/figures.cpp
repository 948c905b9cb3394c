#include "coupling/output/figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

#include "coupling/output/svg.hpp"
#include "slope/safety_map.hpp"

namespace coupling {

namespace {

const char* const kReinforcementColour = "#006400";
const char* const kMethodColours[] = {"#d62728", "#1f77b4", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

struct PlotBounds {
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
  for (const slope::Reinforcement& e : section.reinforcement) {
    canvas.polyline({e.head, e.tail}, kReinforcementColour, 2.5);
    canvas.dot(e.head.x, e.head.y, 2.5, kReinforcementColour);
  }
}

}  // namespace

std::string section_figure_svg(const SectionFigureData& data) {
  PlotBounds bounds;
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
  if (data.section && !data.section->reinforcement.empty())
    legend.emplace_back(kReinforcementColour, "", "reinforcement (dot: head)");
  if (!data.final_ground.empty()) {
    canvas.polyline(data.final_ground, "#000", 2.0, "2,2");
    legend.emplace_back("#000", "2,2", "final ground surface");
  }
  for (const Polyline& line : data.sample_surfaces) canvas.polyline(line, "#9a9a9a", 0.7);
  if (!data.sample_surfaces.empty()) legend.emplace_back("#9a9a9a", "", data.sample_surfaces_label);
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

std::vector<double> fs_band_edges(double lowest, double top) {
  if (!(top > lowest)) top = lowest + 0.1;
  const double step = nice_step(top - lowest, 10);
  std::vector<double> edges;
  for (double v = std::floor(lowest / step + 1e-9) * step; edges.empty() || edges.back() < top - 1e-9 * step;
       v += step)
    edges.push_back(std::round(v / step) * step);
  return edges;
}

namespace {

// Cells of the safety map as rectangles, one per run of equal band along a row; `band` maps a factor to its
// band (-1: above the scale).
void draw_safety_map(SvgCanvas& canvas, const slope::SafetyMap& map, const std::vector<double>& edges,
                     const std::vector<std::string>& colours, const std::string& above) {
  auto band = [&](double fs) {
    for (std::size_t k = 0; k + 1 < edges.size(); ++k)
      if (fs < edges[k + 1]) return static_cast<int>(k);
    return -1;
  };
  const double h = map.cell * canvas.scale();
  for (int iy = 0; iy < map.ny; ++iy) {
    int ix = 0;
    while (ix < map.nx) {
      if (!std::isfinite(map.at(ix, iy))) {
        ++ix;
        continue;
      }
      const int b = band(map.at(ix, iy));
      int end = ix + 1;
      while (end < map.nx && std::isfinite(map.at(end, iy)) && band(map.at(end, iy)) == b) ++end;
      const double x = canvas.px(map.x0 + ix * map.cell), y = canvas.py(map.y0 + (iy + 1) * map.cell);
      canvas.rect_px(x, y, (end - ix) * h + 0.4, h + 0.4, b < 0 ? above : colours[static_cast<std::size_t>(b)]);
      ix = end;
    }
  }
}

}  // namespace

std::string fs_map_svg(const FsMapFigureData& data) {
  const slope::Section& section = *data.section;
  const slope::SafetyMap map = slope::safety_map(section, *data.trials, 160);
  PlotBounds bounds;
  for (const auto& line : section.profile_lines) bounds.add(line.points);
  bounds.add(section.x_min(), section.bottom_y);
  bounds.pad(0.02);
  const double lowest = std::isfinite(map.lowest()) ? map.lowest() : 1.0;
  const std::vector<double> edges = fs_band_edges(lowest, data.scale_max ? *data.scale_max : 1.5 * lowest);
  std::vector<std::string> colours;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    colours.push_back(to_hex(safety_colour_map((k + 0.5) / static_cast<double>(edges.size() - 1))));
  const std::string above = "#d9d9d9";

  SvgCanvas canvas(bounds.x_min, bounds.x_max, bounds.y_min, bounds.y_max);
  canvas.title(data.title);
  draw_section(canvas, section);
  draw_safety_map(canvas, map, edges, colours, above);
  for (std::size_t k = 0; k < section.profile_lines.size(); ++k)
    canvas.polyline(section.profile_lines[k].points, "#333", k == 0 ? 1.8 : 1.0, k == 0 ? "" : "5,3");
  std::vector<std::tuple<std::string, std::string, std::string>> legend;
  if (data.critical_circle) {
    canvas.polyline(data.critical_circle->points, "#ffffff", 4.5);
    canvas.polyline(data.critical_circle->points, "#000000", 2.2);
    legend.emplace_back("#000000", "", data.critical_circle->label);
  }
  if (data.critical_noncircular) {
    canvas.polyline(data.critical_noncircular->points, "#ffffff", 4.5);
    canvas.polyline(data.critical_noncircular->points, "#7b3294", 2.2, "8,4");
    legend.emplace_back("#7b3294", "8,4", data.critical_noncircular->label);
  }
  legend.emplace_back("#333", "", "ground surface; dashed: layer boundaries");
  legend.emplace_back("#e8e2d4", "", "soil that no trial circle crosses");
  canvas.legend(legend);
  canvas.band_bar(edges, colours, above, "FS (-)");
  canvas.axes();
  return canvas.str();
}

}  // namespace coupling
