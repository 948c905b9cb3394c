#pragma once
// Report figures as SVG text: the slope section with the slip surfaces (and, when there is one, the SPH
// particle state coloured by accumulated plastic strain), and the factor-of-safety map of the LEM search.
#include <optional>
#include <string>
#include <vector>

#include "coupling/compare/failure_surface.hpp"
#include "coupling/compare/surface_comparison.hpp"
#include "slope/search.hpp"

namespace coupling {

struct NamedSurface {
  std::string label;  // e.g. "Bishop FS = 1.38"
  Polyline points;
};

struct SectionFigureData {
  std::string title;
  const slope::Section* section = nullptr;     // profile lines of the initial section
  const ParticleSnapshot* particles = nullptr; // optional: current positions coloured by plastic strain
  Polyline final_ground;                       // optional: deformed ground profile
  std::vector<NamedSurface> lem_surfaces;      // critical LEM surfaces (one per method)
  // optional: the critical circles of some samples of a probabilistic analysis (thin, grey, under the others)
  std::vector<Polyline> sample_surfaces;
  std::string sample_surfaces_label;
  std::optional<NamedSurface> sph_surface;     // optional: the SPH failure surface
  std::optional<NamedSurface> sph_fitted_circle;
};

std::string section_figure_svg(const SectionFigureData& data);

// The safety map of the search (slope/safety_map.hpp) for one method: each cell of the section coloured by the
// lowest factor of safety of the trial circles through it, in bands of a colour scale clipped to
// [lowest, scale_max] (cells above it in one pale colour), with that method's critical circular and non-circular
// surfaces drawn on it.
struct FsMapFigureData {
  std::string title;
  const slope::Section* section = nullptr;
  const std::vector<slope::FsMapEntry>* trials = nullptr;
  std::optional<double> scale_max;                   // top of the colour scale (absent: 1.5 x the lowest factor)
  std::optional<NamedSurface> critical_circle;       // the method's critical circle
  std::optional<NamedSurface> critical_noncircular;  // and its non-circular critical surface
};

std::string fs_map_svg(const FsMapFigureData& data);

// Band edges of the safety map's colour scale: "nice" steps (0.05, 0.1, 0.2, ...) from at or below `lowest` to at or
// above `top`, about ten bands; a value of 1.0 inside the range always falls on an edge.
std::vector<double> fs_band_edges(double lowest, double top);

}  // namespace coupling
