#pragma once
// Newmark's (1965) rigid-block displacement: the slip mass slides, downslope only, while the ground acceleration
// exceeds the yield coefficient k_c (the k_h at which FS = 1, critical_seismic_coefficient in search.hpp), and until
// its velocity relative to the ground is back to zero. Relative acceleration (a(t) - k_c) g while it slides; the
// record is linear between its samples, and each interval is integrated exactly (velocity quadratic, displacement
// cubic in time, the stop found inside the interval), so the result depends on the record alone.
// Closed form for a rectangular pulse of A g over T (A > k_c): d = (A - k_c) A g T^2 / (2 k_c).
#include <string>
#include <vector>

#include "sphslope/units.hpp"

namespace slope {

// An acceleration record: evenly spaced samples, in g, positive toward the slip's downslope direction.
struct AccelerationRecord {
  double time_step = 0.0;             // s, > 0
  std::vector<double> acceleration;   // g, at t = 0, time_step, 2 time_step, ...
};

struct NewmarkResult {
  double displacement = 0.0;   // m, relative to the ground, downslope
  double peak_velocity = 0.0;  // m/s, relative
  double sliding_time = 0.0;   // s, while the block moved relative to the ground
  int sliding_episodes = 0;    // how many times it started to slide
};

// The displacement of a rigid block of yield coefficient k_c (> 0) under the record times `scale` (-1: the record
// the other way round); gravity in m/s^2. A block still sliding at the record's end stops on ground at rest,
// decelerating at k_c g.
// history (optional): the displacement (m) at each sample's time, for figures.
NewmarkResult newmark_displacement(const AccelerationRecord& record, double yield_coefficient, double scale = 1.0,
                                   double gravity = sphslope::standard_gravity,
                                   std::vector<double>* history = nullptr);

// Empty when the record can be used; otherwise what is wrong with it.
std::string record_error(const AccelerationRecord& record);

}  // namespace slope
