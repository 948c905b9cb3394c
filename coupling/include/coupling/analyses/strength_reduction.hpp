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
