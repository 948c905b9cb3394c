// The slice table's loads and its conversions to and from the public SlipMass (slice_table.hpp).
#include <algorithm>
#include <atomic>
#include <cmath>

#include "slice_table.hpp"

namespace slope::detail {

void SliceTable::resize(int n) {
  static std::atomic<std::uint64_t> surfaces{0};
  surface_id = surfaces.fetch_add(1, std::memory_order_relaxed) + 1;
  count = n;
  if (static_cast<std::size_t>(n) <= x_left.size()) return;
  const std::size_t capacity = static_cast<std::size_t>(n) + static_cast<std::size_t>(n) / 2 + 8;
  for (std::vector<double>* v :
       {&x_left, &x_right, &width, &sin_a, &cos_a, &base_length, &base_x, &base_y, &top_y, &weight, &surcharge,
        &ponded, &water_thrust, &seismic, &seismic_up, &cohesion, &tan_phi, &pore_pressure, &cohesion_force, &pore_force,
        &vertical, &horizontal, &drive_moment, &shear_arm, &normal_arm}) {
    v->resize(capacity);
  }
  material.resize(capacity);
  envelope.resize(capacity);
}

// Slice i's loads that a circle and a polyline share: the cohesion and pore forces on the base, the vertical and
// horizontal loads, and the driving moment about the centre (circle.xc, circle.yc) in the mirrored frame (`dir`
// +-1), which it returns and stores; the magnitudes of its parts are added to `scale`.
double SliceTable::shared_loads(int i, double dir, double& scale) {
  cohesion_force[i] = cohesion[i] * base_length[i];
  pore_force[i] = pore_pressure[i] * base_length[i];
  vertical[i] = weight[i] + surcharge[i] + ponded[i] - seismic_up[i];
  horizontal[i] = seismic[i] + water_thrust[i];
  const double x_arm = dir * (base_x[i] - circle.xc);            // vertical loads act on the slice centre line
  const double y_mid = 0.5 * (base_y[i] + top_y[i]) - circle.yc;  // seismic force at mid-height
  const double y_top = top_y[i] - circle.yc;                      // water thrust at the slice top
  const double m = -x_arm * vertical[i] - y_mid * seismic[i] - y_top * water_thrust[i];
  drive_moment[i] = m;
  scale += std::fabs(x_arm * vertical[i]) + std::fabs(y_mid * seismic[i]) + std::fabs(y_top * water_thrust[i]);
  return m;
}

// The loads of every method, from the primitive slice data. Moments are about the circle centre, in a frame
// mirrored so that sliding is toward +x' (x' = direction * (x - xc), y' = y - yc); a moment is positive when it
// drives sliding (anticlockwise in the mirrored frame).
void SliceTable::compute_loads() {
  has_envelopes = envelopes != nullptr && std::any_of(envelope.begin(), envelope.begin() + count, [&](int e) {
                    return e >= 0 && static_cast<std::size_t>(e) < envelopes->size();
                  });
  if (!circular) {
    compute_polyline_arms();
    add_crack_force();
    add_support_forces();
    return;
  }
  const double xc = circle.xc;
  const double yc = circle.yc;
  const double dir = direction >= 0 ? 1.0 : -1.0;
  double total = 0.0, scale = 0.0;
  for (int i = 0; i < count; ++i) {
    total += shared_loads(i, dir, scale);
    const double dx = base_x[i] - xc;
    const double dy = base_y[i] - yc;
    shear_arm[i] = std::sqrt(dx * dx + dy * dy);
  }
  total_drive_moment = total;
  drive_moment_scale = scale;
  add_support_forces();
}

// As the circle's loop above, about the moment point (xc, yc) of a polyline: the base normal N and shear S of slice
// i act at the base midpoint P. With r = P - O in the mirrored frame, t = (cos a, -sin a) the base direction of
// sliding and n = (sin a, cos a) the base normal into the mass, N n has the moment N (r . t) (normal_arm) and the
// resisting shear -S t the moment -S (-(r . n)) (shear_arm = -(r . n), the distance from O to the base line when
// O lies above it). For a circle r = -R n: shear arm R, normal arm 0.
void SliceTable::compute_polyline_arms() {
  const double xc = circle.xc;
  const double yc = circle.yc;
  const double dir = direction >= 0 ? 1.0 : -1.0;
  double total = 0.0, scale = 0.0;
  for (int i = 0; i < count; ++i) {
    total += shared_loads(i, dir, scale);
    const double rx = dir * (base_x[i] - xc);
    const double ry = base_y[i] - yc;
    shear_arm[i] = -(rx * sin_a[i] + ry * cos_a[i]);
    normal_arm[i] = rx * cos_a[i] - ry * sin_a[i];
  }
  total_drive_moment = total;
  drive_moment_scale = scale;
}

// The thrust of a water-filled crack acts on the upslope face of the upslope slice: a horizontal load of that
// slice (force equilibrium) with its own line of action (moment equilibrium).
void SliceTable::add_crack_force() {
  if (crack_force == 0.0 || count < 1) return;
  const int i = direction > 0 ? 0 : count - 1;
  horizontal[i] += crack_force;
  const double m = -(crack_force_y - circle.yc) * crack_force;
  drive_moment[i] += m;
  total_drive_moment += m;
  drive_moment_scale += std::fabs(m);
}

void table_to_mass(const SliceTable& t, SlipMass& mass) {
  mass.circle = t.circle;
  mass.surface = t.surface;
  mass.moment_point = Point{t.circle.xc, t.circle.yc};
  mass.crack_depth = t.crack_depth;
  mass.crack_water_force = t.crack_force;
  mass.crack_water_force_y = t.crack_force_y;
  mass.entry = t.entry;
  mass.exit = t.exit;
  mass.direction = t.direction;
  mass.supports = t.supports;
  mass.line_loads = t.line_loads;
  mass.slices.resize(static_cast<std::size_t>(t.count));
  if (t.has_envelopes) {
    mass.envelopes = *t.envelopes;
  } else {
    mass.envelopes.clear();
  }
  for (int i = 0; i < t.count; ++i) {
    Slice& s = mass.slices[static_cast<std::size_t>(i)];
    s.x_left = t.x_left[i];
    s.x_right = t.x_right[i];
    s.width = t.width[i];
    s.base_angle = std::atan2(t.sin_a[i], t.cos_a[i]);
    s.base_length = t.base_length[i];
    s.base_x = t.base_x[i];
    s.base_y = t.base_y[i];
    s.top_y = t.top_y[i];
    s.weight = t.weight[i];
    s.surcharge_load = t.surcharge[i];
    s.ponded_water_load = t.ponded[i];
    s.cohesion = t.cohesion[i];
    s.tan_friction = t.tan_phi[i];
    s.pore_pressure = t.pore_pressure[i];
    s.base_material = t.material[i];
    s.envelope = t.has_envelopes ? t.envelope[i] : -1;
    s.seismic_force = t.seismic[i];
    s.water_thrust = t.water_thrust[i];
    s.vertical_seismic_force = t.seismic_up[i];
  }
}

void mass_to_table(const SlipMass& mass, SliceTable& t) {
  const int n = static_cast<int>(mass.slices.size());
  t.resize(n);
  t.circle = mass.circle;
  t.circular = mass.surface.empty();
  t.surface = mass.surface;
  t.chord_depth = t.circular ? 0.0 : chord_depth(mass.surface);
  t.crack_depth = mass.crack_depth;
  t.crack_force = mass.crack_water_force;
  t.crack_force_y = mass.crack_water_force_y;
  if (!t.circular) t.circle = Circle{mass.moment_point.x, mass.moment_point.y, 0.0};
  t.entry = mass.entry;
  t.exit = mass.exit;
  t.direction = mass.direction >= 0 ? 1 : -1;
  t.envelopes = &mass.envelopes;
  t.supports = mass.supports;
  t.line_loads = mass.line_loads;
  t.passive_scale = 1.0;
  double max_depth = 0.0;
  for (int i = 0; i < n; ++i) {
    const Slice& s = mass.slices[static_cast<std::size_t>(i)];
    t.x_left[i] = s.x_left;
    t.x_right[i] = s.x_right;
    t.width[i] = s.width;
    t.sin_a[i] = std::sin(s.base_angle);
    t.cos_a[i] = std::cos(s.base_angle);
    t.base_length[i] = s.base_length;
    t.base_x[i] = s.base_x;
    t.base_y[i] = s.base_y;
    t.top_y[i] = s.top_y;
    t.weight[i] = s.weight;
    t.surcharge[i] = s.surcharge_load;
    t.ponded[i] = s.ponded_water_load;
    t.cohesion[i] = s.cohesion;
    t.tan_phi[i] = s.tan_friction;
    t.pore_pressure[i] = s.pore_pressure;
    t.material[i] = s.base_material;
    t.envelope[i] = s.envelope;
    t.seismic[i] = s.seismic_force;
    t.water_thrust[i] = s.water_thrust;
    t.seismic_up[i] = s.vertical_seismic_force;
    max_depth = std::max(max_depth, s.top_y - s.base_y);
  }
  t.max_depth = max_depth;
  t.compute_loads();
}

}  // namespace slope::detail
