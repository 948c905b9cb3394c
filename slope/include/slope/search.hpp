#pragma once
// Critical circular slip-surface search: automatic entry-exit / grid search over the whole section, then
// Nelder-Mead refinement, per method.
#include <optional>
#include <string>
#include <vector>

#include "slope/methods.hpp"

namespace slope {

struct Range {
  double min = 0.0;
  double max = 0.0;
};

struct CentreGrid {
  Range x;  // m
  Range y;  // m
  int nx = 10;
  int ny = 10;
};

// Optional user limits; anything absent is chosen automatically from the section.
struct SearchLimits {
  std::optional<Range> entry_x;      // m, where the surface may enter the ground behind the crest
  std::optional<Range> exit_x;       // m, where it may leave the ground near the toe
  std::optional<CentreGrid> centre_grid;
  std::optional<Range> radius;       // m
};

struct SearchOptions {
  SearchLimits limits;
  SliceOptions slicing;
  bool refine = true;  // Nelder-Mead refinement of the best trial surfaces
  // Added: smallest admissible slip mass, as its largest vertical thickness (m). Negative: automatic, 2 % of the
  // ground surface relief (keeps cohesionless slopes from converging to vanishing surface ravelling).
  double minimum_depth = -1.0;
  // Points along the whole ground line at which the automatic search lets circles enter and exit (plus every
  // vertex that shapes the ground, at most as many); a user entry/exit range gets 17/41 of them. More points: a
  // finer and slower coarse search.
  int entry_exit_samples = 41;
};

// One trial surface of the coarse search, for the factor-of-safety map.
struct FsMapEntry {
  Circle circle;
  Point entry;
  Point exit;
  double factor_of_safety = 0.0;
};

struct CriticalSurface {
  Method method = Method::bishop;
  std::optional<SlipMass> mass;  // the critical surface; empty if the method failed everywhere
  FsResult result;               // with forces
};

struct SearchResult {
  std::vector<CriticalSurface> methods;  // in the order asked for
  std::vector<FsMapEntry> fs_map;        // coarse-search trials that converged (first method asked for)
  long trial_surfaces = 0;               // all factor-of-safety evaluations, all methods
  double seconds = 0.0;                  // wall time of the whole search
  std::string error;                     // non-empty when the limits admit no valid circle at all
};

SearchResult search_critical(const Section& section, const std::vector<Method>& methods,
                             const SearchOptions& options);

}  // namespace slope
