#pragma once
// The surge front of an isph run against the references of analyses.isph.front_reference: Martin & Moyce's (1952)
// tabulated front in metres and seconds, and the RMS relative error of the run's front (the front_x_m column of
// its monitors) against it, as the isph report and the study give it (docs/isph.md section 5).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "coupling/analyses/monitor_table.hpp"
#include "sph/fluid/reference_fronts.hpp"

namespace coupling {

// The reference points compared: 0.84 <= T <= 3.33 (Martin & Moyce's tabulated points after the first), and the time
// shifts tried, dT in [-0.3, 0] in steps of 0.01 (the experiment's gate opened in a finite time).
inline constexpr double front_error_T_min = 0.84, front_error_T_max = 3.33;
inline constexpr double front_error_min_shift = -0.3, front_error_shift_step = 0.01;

// Martin & Moyce's n^2 = 2 column of width a [m] against a wall at x_wall [m], gravity g [m/s^2].
struct MartinMoyceColumn {
  double a = 0, g = 0, x_wall = 0;
  double time_scale() const;  // T / t = n sqrt(g/a)
};

// The tabulated points as (t [s], x_front [m]).
std::vector<std::pair<double, double>> martin_moyce_points(const MartinMoyceColumn& column);

// The front_x_m column of a monitor table as (T, Z).
sph::fluid::FrontSeries martin_moyce_series(const MonitorTable& monitors, const MartinMoyceColumn& column);

struct FrontErrors {
  double rms = 0;  // RMS relative error of Z without a shift
  double rms_shifted = 0, shift = 0;  // the smallest over the shifts tried, and its dT
  int points = 0;  // reference points compared
  double T_max = 0;  // the last T compared: 3.33, or the run's end when it ends before
};
// The errors of the run's front against the table over 0.84 <= T <= min(3.33, the run's last T); none without a
// front column or a reference point in that range.
std::optional<FrontErrors> martin_moyce_front_errors(const MonitorTable& monitors, const MartinMoyceColumn& column);

// How a computed series s_k agrees with a reference series o_k at the same times (the statistics of the seed paper's
// eqs. 50-53, as intended: its MAE is printed without the absolute value, and its RMSE and NRMSE contradict its
// MAE and NSE, seed A11): Pearson's r, the mean error (s - o), the mean absolute error, the RMS error and the
// Nash-Sutcliffe efficiency 1 - sum (s - o)^2 / sum (o - mean o)^2.
struct AgreementStatistics {
  int points = 0;
  double r = 0, mean_error = 0, mean_absolute_error = 0, rms_error = 0, nse = 0;
};
AgreementStatistics agreement(const std::vector<double>& reference, const std::vector<double>& computed);

// A dam break on a dry bed against Ritter's (1892) solution for a reservoir of depth h0 behind x_dam:
//  * the front X = (x_front - x_dam)/h0 against X = 2T, T = t sqrt(g/h0), over the monitor rows with 0 < t and the
//    front short of the tank's far wall by more than h0 (the statistics above, and the ratio of the computed front's
//    mean speed over the second half of those rows to Ritter's 2 sqrt(g h0));
//  * the depth at the dam site against Ritter's 4 h0/9, from the gauge at x_dam (within dx), over 2 <= T until the
//    negative wave reflected from the back wall returns (t < 3 L/sqrt(g h0), L the reservoir's length).
struct RitterComparison {
  AgreementStatistics front;
  double front_speed_ratio = 0;
  std::optional<double> dam_depth_ratio;  // the mean of h/(4 h0/9) over the rows compared
  int dam_depth_points = 0;
};
struct RitterSetting {
  double dam_x = 0, depth = 0, g = 0;  // [m], [m], [m/s^2]
  double reservoir_length = 0, far_wall_x = 0;  // [m]
  std::optional<std::string> dam_gauge;  // the monitors.csv column of the gauge at the dam
  double gauge_offset = 0;  // [m] added to the gauge's values to give the depth (still water level - bed)
};
std::optional<RitterComparison> ritter_comparison(const MonitorTable& monitors, const RitterSetting& setting);

}  // namespace coupling
