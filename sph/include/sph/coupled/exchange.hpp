#pragma once
// What the soil and the water of a coupled run (coupled_step.hpp) give each other (docs/coupled.md):
//  - the soil to the water: its particles as the fluid's boundary. Each soil particle has a twin in the fluid's
//    particle set, a wall particle of material fluid::coupled_wall_material with the fluid's wall mass rho0 dx^2,
//    at the soil particle's position and with its velocity. The fluid's wall treatment then applies to the soil's
//    surface as to any wall: the soil's velocity in the continuity and viscous sums, the pressure extrapolated from
//    the water, the wall clearance (no water passes into the soil);
//  - the water to the soil: a water table. The soil's pore pressure is u = gamma_w (table - y) below it
//    (sph/soil/loads.hpp), with the table at the height of the water's free-surface particles (where the fluid's
//    pressure is 0, decision D6 of docs/isph.md) over each column. The soil's stress is then effective, its momentum
//    balance carries -grad u, and submerged soil at rest carries its buoyant weight; the water's pressure on the
//    soil's surface is the same u there. What the water's pressure does beyond the table's hydrostatic one reaches
//    the soil as a surface force on each particle next to the water (SoilBoundary::take_forces, computed by the
//    fluid's step against the table as its reference pressure).
// Neither physics includes the other; this is the only code that reads both.
#include <optional>
#include <vector>

#include "sph/engine/particle_set.hpp"
#include "sph/fluid/model.hpp"
#include "sph/soil/model.hpp"

namespace sph::coupled {

// The soil's twins in the fluid's particle set.
class SoilBoundary {
 public:
  // The name of the field (in the fluid's set) that holds each twin's soil particle id; checkpointed.
  static constexpr const char* id_field = "coupled_soil_id";

  // Finds the twins in `water` or, when it has none yet, appends one per soil particle (kind material) of `soil`.
  // Throws std::invalid_argument when the two particle spacings differ (the twins must have the fluid's spacing).
  SoilBoundary(fluid::Model& water, const soil::Model& soil);

  // Sets every twin's position, velocity and acceleration (the soil's last rate, for the water's wall pressure) to
  // its soil particle's (by id; either set may have been reordered).
  void update(fluid::Model& water, const soil::Model& soil) const;

  // Sets every soil particle's (force_x, force_y) fields to its twin's entry of (fx, fy) (indexed as the water's
  // particles); zero when fx is empty.
  void take_forces(const fluid::Model& water, const std::vector<double>& fx, const std::vector<double>& fy,
                   soil::Model& soil, FieldId force_x, FieldId force_y) const;

  std::size_t size() const { return count_; }

 private:
  FieldId soil_id_, acceleration_x_ = 0, acceleration_y_ = 0;
  std::size_t count_ = 0;
};

// The water table over the soil: a vertex at the centre of each column of width dx (columns on the fluid's
// lattice, anchored at x = 0) that holds water, at the height of the column's highest fluid particle (dx = the
// fluid's particle spacing) averaged over the four columns to each side with tent weights; level beyond the
// outermost columns. Unit weight rho0 |g|. None when no water is left.
std::optional<soil::PiezometricLine> water_table(const fluid::Model& water);

}  // namespace sph::coupled
