#pragma once
// The SPH failure surface itself as a limit-equilibrium slip surface, so that the LE methods can be put on the
// surface the SPH model found (like for like), not only on a circle fitted to it.
#include <optional>
#include <string>

#include "coupling/compare/comparison.hpp"
#include "slope/slices.hpp"

namespace coupling {

struct SphSurfaceForLem {
  std::optional<slope::SlipPolyline> polyline;  // the surface given to slope::slice_polyline
  std::optional<slope::SlipMass> mass;          // its slices (with the tension crack cut off)
  std::string reason;                           // why there is no mass
  double scarp_angle = 0.0;                     // rad: segments steeper than this at the upper end form the crack
  // rad: the most a segment of the analysed surface steepens over the one before it, in the direction of sliding
  // (0: concave upward throughout). Large values warn that the rigid-slice methods may disagree on this surface.
  double largest_convex_kink = 0.0;
  // band vertices dropped where the band turned back on itself by more than the slicer accepts (its scatter)
  int dropped_vertices = 0;
};

// The band centre line from its entry to its exit on the initial ground: vertices clipped to just below the ground
// and to the rigid base (and the ground's own vertices added where a segment would cut above them), simplified
// (Douglas-Peucker, half a bin: the band's scatter), and its steep upper part - the scarp of the graben, steeper
// than the Rankine active plane 45 deg + phi'/2 of the soil there - replaced by a dry tension crack as deep as the
// surface where it flattens. A vertex where the band turns back on itself beyond the slicer's tolerance (a spike of
// its scatter) is dropped.
SphSurfaceForLem sph_surface_for_lem(const slope::Section& section, const SphFailure& sph);

}  // namespace coupling
