#pragma once
// The SPH failure surface read out of a final particle state, and its quantitative comparison with the
// critical limit-equilibrium surfaces. SI units inside; the JSON uses units in every key.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/compare/acceptance.hpp"
#include "coupling/compare/failure_surface.hpp"
#include "coupling/scene/json_reader.hpp"
#include "coupling/compare/surface_comparison.hpp"
#include "slope/search.hpp"

namespace coupling {


struct SphFailure {
  FailureSurface band;                      // band centre line, on the initial configuration
  std::optional<CircleFit> fitted_circle;   // least-squares circle through the band centre line
  std::optional<slope::Point> entry, exit;  // ends of the band line carried up to the initial ground surface
  Polyline displaced_mass_base;             // lower boundary of the particles displaced more than delta
  double displacement_threshold = 0.0;      // m, delta actually used
  std::size_t displaced_particles = 0;
  SurfaceDistances band_vs_displacement;    // agreement of the two SPH surfaces
  Polyline final_ground;                    // deformed free surface (top of the particles per bin)
  double farthest_toe_advance = 0.0;        // m, run-out of debris beyond the initial toe (0: none)
  double initial_toe_x = 0.0;               // m
};


// Reads the failure surface out of the particle state. `initial_ground` is the section's ground surface.
SphFailure extract_sph_failure(const ParticleSnapshot& particles, const Polyline& initial_ground,
                               const ComparisonOptions& options);

// The "comparison" block of report.json: the SPH surface, and for every LEM method with a critical surface:
// entry/exit offsets, mean/max normal distance, area between, sliding-mass areas and intersection over union,
// the method's FS on the SPH fitted circle next to its minimum FS; plus "verdict" (plain language).
nlohmann::json comparison_report(const slope::Section& section, const SphFailure& sph,
                                 const slope::SearchResult& lem, const ComparisonOptions& options);

// The slip surface of a critical LEM mass as a polyline from entry to exit.
Polyline lem_surface_polyline(const slope::SlipMass& mass, int segments = 200);

}  // namespace coupling
