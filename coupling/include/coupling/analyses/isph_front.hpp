#pragma once
// The surge front of an isph run against the references of analyses.isph.front_reference: Martin & Moyce's (1952)
// tabulated front in metres and seconds, and the RMS relative error of the run's front (the front_x_m column of
// its monitors) against it, as the isph report and the study give it (docs/isph.md section 5).
#include <optional>
#include <utility>
#include <vector>

#include "coupling/output/monitor_table.hpp"
#include "sph/fluid/reference_fronts.hpp"

namespace coupling {

// The reference points compared: 0.84 <= T <= 3.33 (shared/references/fluids-granular.md section 7), and the time
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

}  // namespace coupling
