#pragma once
// SPH factor of safety by strength reduction (analyses.srm, docs/scene-format.md): every material's strength is
// divided by a trial factor F (c/F, tan(phi)/F, tan(psi)/F), the slope is run from geostatic stress with velocity
// damping to a quasi-static state, and a displacement criterion decides whether it failed; F is bisected between a
// stable and a failing value.
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/json_reader.hpp"
#include "coupling/scene/scene.hpp"

namespace coupling {

// analyses.srm; a missing value is computed per scene (see resolve_srm_options).
struct SrmOptions {
  double tolerance = 0.02;                      // stop when hi - lo <= tolerance
  std::optional<std::pair<double, double>> bracket;  // default: around the LEM Bishop FS, else [0.5, 3]
  std::optional<double> failure_displacement_m;      // default: 5 % of the slope height
  std::optional<double> max_time_s;                  // per trial; default: 40 fundamental periods, at least 2 s
  std::optional<double> damping_per_s;               // default: the first shear-mode angular frequency
  std::optional<double> rest_speed_m_s;              // quasi-static threshold; default 1e-3 * sqrt(g H)
  int max_trials = 30;                               // including bracket expansions
};

// Reads analyses.srm (errors at "analyses.srm.<key>").
std::optional<SrmOptions> read_srm_options(const nlohmann::json& block, Diagnostics& diagnostics);
// Validation for the scene loader: the block itself, plus "srm needs a section and analyses.sph".
void check_srm_scene(const Scene& scene, Diagnostics& diagnostics);

// One run of the oracle.
struct SrmTrial {
  double factor = 0.0;
  bool failed = false;
  double max_displacement_m = 0.0;
  double simulated_time_s = 0.0;
  double wall_seconds = 0.0;
  std::string stopped_because;  // quasi_static | end_time | blow_up | ...
  std::string reason;           // why it counted as failed or stable
};

struct BisectionResult {
  bool bracketed = false;  // a stable lower and a failing upper bound were found
  double lo = 0.0, hi = 0.0;  // last stable / first failing factor
  double factor_of_safety = 0.0;  // (lo + hi) / 2 when bracketed
  std::vector<SrmTrial> trials;   // in the order run
  std::string error;
};

// Bisection on the factor with an arbitrary failure oracle (independent of SPH, for tests): checks lo is stable
// and hi fails, expanding the bracket (lo / 1.5 down to 0.05, hi * 1.5 up to 20) when not, then halves it until
// hi - lo <= tolerance or max_trials oracle calls have been made.
BisectionResult bisect_factor(const std::function<SrmTrial(double)>& oracle, double lo, double hi, double tolerance,
                              int max_trials);

struct SrmResult {
  BisectionResult bisection;
  nlohmann::json report;  // the "srm" block of report.json
  bool ok = false;
};

// Runs the strength-reduction analysis of a validated slope scene (needs section + analyses.sph + analyses.srm).
// `lem_bishop_fs`: the LEM Bishop factor (for the default bracket and the report), when available.
// `lem_fs_by_method`: method key -> LEM FS, copied into the report.
SrmResult run_strength_reduction(const Scene& scene, const SrmOptions& options, std::optional<double> lem_bishop_fs,
                                 const nlohmann::json& lem_fs_by_method, std::ostream* log);

}  // namespace coupling
