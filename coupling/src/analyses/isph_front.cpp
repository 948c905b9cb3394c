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

AgreementStatistics agreement(const std::vector<double>& o, const std::vector<double>& s) {
  AgreementStatistics a;
  const std::size_t n = std::min(o.size(), s.size());
  if (n == 0) return a;
  double mo = 0, ms = 0;
  for (std::size_t k = 0; k < n; ++k) {
    mo += o[k];
    ms += s[k];
  }
  mo /= static_cast<double>(n);
  ms /= static_cast<double>(n);
  double soo = 0, sss = 0, sos = 0, se = 0, sae = 0, see = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double e = s[k] - o[k];
    soo += (o[k] - mo) * (o[k] - mo);
    sss += (s[k] - ms) * (s[k] - ms);
    sos += (o[k] - mo) * (s[k] - ms);
    se += e;
    sae += std::abs(e);
    see += e * e;
  }
  const double nn = static_cast<double>(n);
  a.points = static_cast<int>(n);
  a.r = soo > 0 && sss > 0 ? sos / std::sqrt(soo * sss) : 0.0;
  a.mean_error = se / nn;
  a.mean_absolute_error = sae / nn;
  a.rms_error = std::sqrt(see / nn);
  a.nse = soo > 0 ? 1.0 - see / soo : 0.0;
  return a;
}

std::optional<RitterComparison> ritter_comparison(const MonitorTable& monitors, const RitterSetting& c) {
  if (!(c.depth > 0) || !(c.g > 0)) return std::nullopt;
  const double celerity = std::sqrt(c.g * c.depth), time_scale = std::sqrt(c.g / c.depth);
  std::vector<double> reference, computed, times;
  for (const auto& [t, x] : monitor_column(monitors, "front_x_m")) {
    if (!(t > 0) || x > c.far_wall_x - c.depth) continue;
    times.push_back(t);
    reference.push_back(2.0 * t * time_scale);
    computed.push_back((x - c.dam_x) / c.depth);
  }
  if (times.size() < 4) return std::nullopt;
  RitterComparison out;
  out.front = agreement(reference, computed);
  const std::size_t half = times.size() / 2;  // the mean speed over the second half of the rows
  const double speed = (computed.back() - computed[half]) * c.depth / (times.back() - times[half]);
  out.front_speed_ratio = speed / (2.0 * celerity);
  if (c.dam_gauge) {
    const double t_min = 2.0 / time_scale, t_max = 3.0 * c.reservoir_length / celerity;
    double sum = 0;
    for (const auto& [t, h] : monitor_column(monitors, *c.dam_gauge))
      if (t >= t_min && t < t_max) {
        sum += (h + c.gauge_offset) / (4.0 * c.depth / 9.0);
        ++out.dam_depth_points;
      }
    if (out.dam_depth_points > 0) out.dam_depth_ratio = sum / out.dam_depth_points;
  }
  return out;
}

}  // namespace coupling
