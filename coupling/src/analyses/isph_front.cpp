// The front of an isph run against Martin & Moyce's table (coupling/analyses/isph_front.hpp).
#include "coupling/analyses/isph_front.hpp"

#include <algorithm>
#include <cmath>

namespace coupling {

double MartinMoyceColumn::time_scale() const { return sph::fluid::martin_moyce_1952_n2_2_n * std::sqrt(g / a); }

std::vector<std::pair<double, double>> martin_moyce_points(const MartinMoyceColumn& column) {
  std::vector<std::pair<double, double>> out;
  for (const sph::fluid::FrontPoint& p : sph::fluid::martin_moyce_1952_n2_2())
    out.emplace_back(p.T / column.time_scale(), column.x_wall + p.Z * column.a);
  return out;
}

sph::fluid::FrontSeries martin_moyce_series(const MonitorTable& monitors, const MartinMoyceColumn& column) {
  sph::fluid::FrontSeries series;
  for (const auto& [t, x] : monitor_column(monitors, "front_x_m")) {
    series.T.push_back(t * column.time_scale());
    series.Z.push_back((x - column.x_wall) / column.a);
  }
  return series;
}

std::optional<FrontErrors> martin_moyce_front_errors(const MonitorTable& monitors, const MartinMoyceColumn& column) {
  const sph::fluid::FrontSeries run = martin_moyce_series(monitors, column);
  if (run.T.empty()) return std::nullopt;
  FrontErrors e;
  e.T_max = std::min(front_error_T_max, run.T.back());
  for (const sph::fluid::FrontPoint& p : sph::fluid::martin_moyce_1952_n2_2())
    if (p.T >= front_error_T_min && p.T <= e.T_max) ++e.points;
  if (e.points == 0) return std::nullopt;
  const auto table = sph::fluid::martin_moyce_1952_n2_2();
  e.rms = sph::fluid::front_rms_error(run, table, front_error_T_min, e.T_max);
  const sph::fluid::ShiftedFrontError shifted = sph::fluid::best_shifted_front_error(
      run, table, front_error_T_min, e.T_max, front_error_min_shift, front_error_shift_step);
  e.rms_shifted = shifted.error;
  e.shift = shifted.shift;
  return e;
}

}  // namespace coupling
