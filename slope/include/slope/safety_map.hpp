#pragma once
// Safety map of a search (Baker & Leshchinsky 2001, "Spatial distribution of safety factors", J. Geotech.
// Geoenviron. Eng. 127(2):135-145): at each point of the slope, the lowest factor of safety of all trial slip
// surfaces that pass through it. Its lowest value is the critical surface's; its low-FS zone is where a slip can
// run, which is what a picture of the search should show (and what the SPH plastic zone is set against).
#include <vector>

#include "slope/search.hpp"

namespace slope {

struct SafetyMap {
  double x0 = 0.0;    // m, left edge of column 0
  double y0 = 0.0;    // m, bottom edge of row 0
  double cell = 1.0;  // m, side of a square cell
  int nx = 0;
  int ny = 0;
  std::vector<double> fs;  // nx * ny, row iy from the bottom: fs[iy * nx + ix]; NaN where no trial surface passes

  double at(int ix, int iy) const { return fs[static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(ix)]; }
  double lowest() const;  // lowest factor in the map (NaN for an empty map)
};

// The map of `trials` (circles with their entry and exit on the ground) over the section, `columns` cells across
// its width (square cells; rows from bottom_y up to the highest ground point). Each circle marks every cell its
// arc between entry and exit passes through (sampled at a quarter cell).
SafetyMap safety_map(const Section& section, const std::vector<FsMapEntry>& trials, int columns = 160);

}  // namespace slope
