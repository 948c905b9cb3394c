// Safety map of a circular search (slope/safety_map.hpp).
#include "slope/safety_map.hpp"
#include "sphslope/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slope {

namespace {


// Angle of p about the circle's centre in (-3 pi / 2, pi / 2]: the lowest point of the circle (-pi / 2) lies
// strictly inside that range, so the slip arc between entry and exit is the angle interval between them.
double arc_angle(const Circle& c, const Point& p) {
  double a = std::atan2(p.y - c.yc, p.x - c.xc);
  if (a > 0.5 * sphslope::pi) a -= 2.0 * sphslope::pi;
  return a;
}

}  // namespace

double SafetyMap::lowest() const {
  double low = std::numeric_limits<double>::quiet_NaN();
  for (double f : fs)
    if (std::isfinite(f) && !(f >= low)) low = f;
  return low;
}

SafetyMap safety_map(const Section& section, const std::vector<FsMapEntry>& trials, int columns) {
  SafetyMap map;
  columns = std::max(columns, 1);
  double top = section.bottom_y;
  for (const Point& p : section.profile_lines.front().points) top = std::max(top, p.y);
  map.x0 = section.x_min();
  map.y0 = section.bottom_y;
  map.cell = (section.x_max() - section.x_min()) / columns;
  map.nx = columns;
  map.ny = std::max(1, static_cast<int>(std::ceil((top - map.y0) / map.cell)));
  map.fs.assign(static_cast<std::size_t>(map.nx) * static_cast<std::size_t>(map.ny),
                std::numeric_limits<double>::quiet_NaN());
  for (const FsMapEntry& trial : trials) {
    const Circle& c = trial.circle;
    if (!(c.radius > 0.0) || !std::isfinite(trial.factor_of_safety)) continue;
    const double a = arc_angle(c, trial.entry), b = arc_angle(c, trial.exit);
    const double from = std::min(a, b), to = std::max(a, b);
    const int samples = std::max(2, static_cast<int>(std::ceil((to - from) * c.radius / (0.25 * map.cell))) + 1);
    for (int k = 0; k < samples; ++k) {
      const double t = from + (to - from) * k / (samples - 1);
      const int ix = static_cast<int>(std::floor((c.xc + c.radius * std::cos(t) - map.x0) / map.cell));
      const int iy = static_cast<int>(std::floor((c.yc + c.radius * std::sin(t) - map.y0) / map.cell));
      if (ix < 0 || ix >= map.nx || iy < 0 || iy >= map.ny) continue;
      double& cell = map.fs[static_cast<std::size_t>(iy) * static_cast<std::size_t>(map.nx) + static_cast<std::size_t>(ix)];
      if (!(cell <= trial.factor_of_safety)) cell = trial.factor_of_safety;
    }
  }
  return map;
}

}  // namespace slope
