#pragma once
// The SPH failure surface read out of a final particle state, and its quantitative comparison with the
// critical limit-equilibrium surfaces. SI units inside; the JSON uses units in every key.
#include <optional>
#include <string>
#include <vector>

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

// Where an LE surface lies against the SPH failure surface (set when both surfaces exist).
struct SurfaceGeometry {
  std::optional<slope::Point> entry_offset_m, exit_offset_m;  // SPH - LEM (when the SPH band has ends)
  double common_from_x_m = 0, common_to_x_m = 0;
  double mean_normal_distance_m = 0, max_normal_distance_m = 0, area_between_m2 = 0;
  double sph_sliding_mass_area_m2 = 0, lem_sliding_mass_area_m2 = 0, intersection_area_m2 = 0;
  double intersection_over_union = 0;
};

// The method's non-circular critical surface (analyses.lem.noncircular_search) against the SPH surface.
struct NonCircularComparison : SurfaceGeometry {
  double factor_of_safety = 0;
  bool from_circle = false;  // no polyline beat the circle: the geometry is the circle's
};

// One LE method's critical surface against the SPH failure surface: the circle's geometry (the SurfaceGeometry
// fields), and that of the non-circular critical surface when it was searched for.
struct MethodComparison : SurfaceGeometry {
  std::string method;                                     // method key
  std::optional<double> lem_factor_of_safety;             // its minimum FS (none: the method failed)
  std::optional<double> factor_of_safety_on_sph_circle;   // its FS on the SPH fitted circle
  std::optional<std::string> on_sph_circle_error;         // why that FS is missing
  std::optional<double> factor_of_safety_on_sph_surface;  // its FS on the SPH band line itself (sph_surface_lem.hpp)
  std::optional<std::string> on_sph_surface_error;        // why that FS is missing
  bool has_geometry = false;                              // the SurfaceGeometry fields are set
  std::optional<NonCircularComparison> noncircular;       // with the non-circular search and an SPH band
};

// The SPH failure surface against every LEM method's critical surface; coupling/output/comparison_report writes
// it as the "comparison" block of report.json.
struct ComparisonResult {
  SphFailure sph;
  bool initial_configuration = true;  // the band is drawn on the initial particle positions
  double circle_raised_for_lem_m = 0;  // the SPH circle was raised this much to clear the base
  // the SPH band line as an LE slip surface: what was analysed (polyline, crack), or why it could not be
  std::optional<slope::SlipPolyline> sph_surface_for_lem;
  std::optional<slope::SlipMass> sph_surface_mass;
  std::string sph_surface_for_lem_error;
  double sph_scarp_angle = 0;  // rad
  double sph_largest_convex_kink = 0;  // rad
  int sph_surface_dropped_vertices = 0;  // band vertices dropped at reversals (sph_surface_lem.hpp)
  std::vector<MethodComparison> methods;  // in the order of the LE result
  std::string verdict;                    // plain language
  std::optional<AcceptanceResult> acceptance;

  const MethodComparison* find(const std::string& method) const;
};

// Entry/exit offsets, mean/max normal distance, area between, sliding-mass areas and intersection over union for
// every LEM method with a critical surface, the method's FS on the SPH fitted circle next to its minimum FS, and a
// verdict against Bishop's circle (else the first method's).
// With `noncircular` (the non-circular search's result), each method is also set against its non-circular critical
// surface, and the verdict gains a sentence on it.
ComparisonResult compare_with_lem(const slope::Section& section, const SphFailure& sph, const slope::SearchResult& lem,
                                  const ComparisonOptions& options,
                                  const slope::NonCircularResult* noncircular = nullptr);

// The slip surface of a critical LEM mass as a polyline from entry to exit.
Polyline lem_surface_polyline(const slope::SlipMass& mass, int segments = 200);

}  // namespace coupling
