#pragma once
// Critical slip-surface searches, per method: circular (automatic entry-exit / grid search over the whole section,
// then Nelder-Mead refinement) and non-circular (vertex optimisation of polylines starting from the critical
// circles).
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
  // The method whose coarse-search factors go to SearchResult::fs_map (must be one of those asked for; empty: the
  // first one asked for).
  std::optional<Method> fs_map_method;
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
  std::vector<FsMapEntry> fs_map;        // coarse-search trials that converged (SearchOptions::fs_map_method)
  long trial_surfaces = 0;               // all factor-of-safety evaluations, all methods
  double seconds = 0.0;                  // wall time of the whole search
  std::string error;                     // non-empty when the limits admit no valid circle at all
};

SearchResult search_critical(const Section& section, const std::vector<Method>& methods,
                             const SearchOptions& options);

// The critical (yield) seismic coefficient k_c of the slope (critical_coefficient.cpp): the horizontal k_h at which
// the least factor of safety of the circular search by `method` is 1, the section's k_v held as it is. Found by the
// Illinois false-position method on FS_min(k_h) - 1 to 1e-4 in k_h, each evaluation a whole search.
struct CriticalCoefficient {
  std::optional<double> coefficient;  // k_c; empty when there is none (`why`)
  std::string why;                    // FS_min <= 1 without k_h, or > 1 up to k_h = 0.99, or the search failed
  double factor_of_safety_without = 0.0;  // FS_min at k_h = 0
  std::optional<CriticalSurface> surface;  // the critical surface at k_c
  int searches = 0;
  double seconds = 0.0;
};
CriticalCoefficient critical_seismic_coefficient(const Section& section, Method method, const SearchOptions& options);

// Non-circular search (search_noncircular.cpp): a pattern search over the vertices of a polyline, started from
// each method's critical circle inscribed as `initial_segments` chords; the number of segments doubles after each
// converged stage up to `segments`. Bishop takes moments about its critical circle's centre; the Ordinary method
// (defined for circles) is not searched and keeps its critical circle. The surfaces obey SearchOptions' entry/exit limits and minimum depth and
// slice_polyline's admissibility (concave upward, no convex kink; above the rigid base).
struct NonCircularOptions {
  int initial_segments = 8;
  int segments = 32;  // segments of the final polyline (a power-of-two multiple of initial_segments)
  // Vertex moves stop below this fraction of the critical circle's entry-exit chord (m / m).
  double tolerance = 2e-4;
};

struct NonCircularSurface {
  Method method = Method::bishop;
  // The critical surface: the optimised polyline, or, when no polyline beats the method's critical circle, that
  // circle itself (from_circle): by construction never a higher factor of safety than the circular search.
  std::optional<SlipMass> mass;
  FsResult result;  // with forces
  bool from_circle = false;
  bool searched = false;  // false for the Ordinary method and for a method without a critical circle
  std::optional<double> circle_factor_of_safety;    // the method's critical circle
  std::optional<double> polyline_factor_of_safety;  // the best polyline found, whether or not it beat the circle
  long trial_surfaces = 0;                          // polylines evaluated for this method
};

struct NonCircularResult {
  std::vector<NonCircularSurface> methods;  // in the order of the circular search's methods
  long trial_surfaces = 0;                  // all polylines evaluated, all methods
  double seconds = 0.0;                     // wall time of the non-circular search alone
};

NonCircularResult search_noncircular(const Section& section, const SearchResult& circular,
                                     const SearchOptions& options, const NonCircularOptions& noncircular = {});

}  // namespace slope
