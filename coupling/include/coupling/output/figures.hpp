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
  std::optional<NamedSurface> sph_surface;     // optional: the SPH failure surface
  std::optional<NamedSurface> sph_fitted_circle;
};

std::string section_figure_svg(const SectionFigureData& data);

// Trial-circle centres coloured by factor of safety, with the section and the critical circle.
std::string fs_map_svg(const slope::Section& section, const std::vector<slope::FsMapEntry>& fs_map,
                       const std::optional<slope::Circle>& critical, const std::string& title);

}  // namespace coupling
