#pragma once
// SPH factor of safety by strength reduction (analyses.srm, docs/scene-format.md): every material's strength is
// divided by a trial factor F (c/F, tan(phi)/F, tan(psi)/F), the slope is run from geostatic stress with velocity
// damping to a quasi-static state, and a displacement criterion decides whether it failed; F is bisected between a
// stable and a failing value.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

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

// How the trials are run (from the slope's height and slowest shear wave, or analyses.srm).
struct SrmPlan {
  double height = 0.0;                // m
  double period = 0.0;                // s, first shear mode of a layer of the slope height
  double damping = 0.0;               // 1/s
  double max_time = 0.0;              // s per trial
  double failure_displacement = 0.0;  // m
  double rest_speed = 0.0;            // m/s
  double min_time = 0.0;              // s, rest is not checked before
};

struct SrmBracket {
  double lo = 0.5, hi = 3.0;
  std::string source = "default [0.5, 3]";
};

// What the strength reduction found; coupling/output/srm_report writes it as the "srm" block of report.json.
struct SrmResult {
  BisectionResult bisection;
  bool ok = false;
  double tolerance = 0.0;
  SrmBracket initial_bracket;
  SrmPlan plan;
  double particle_spacing_m = 0.0;
  std::size_t soil_particles = 0;
  std::map<std::string, double> lem_fs_by_method;  // method key -> LEM FS
  std::optional<double> lem_bishop;
  std::vector<std::string> warnings;  // loads SPH leaves out
  double seconds = 0.0;
};

// Where a strength reduction keeps what `--resume` needs (srm_trials.json, srm_trial_checkpoint.bin), and whether
// this run continues from them. No folder: nothing is written and nothing can be resumed.
struct SrmFiles {
  std::optional<std::filesystem::path> dir;
  bool resume = false;
};

// Runs the strength-reduction analysis of a validated slope scene (needs section + analyses.sph + analyses.srm).
// `lem_bishop_fs`: the LEM Bishop factor (for the default bracket and the report), when available.
// `lem_fs_by_method`: method key -> LEM FS, copied into the result. With files.dir, every finished trial is
// journalled and the trial in progress checkpointed (analyses.sph.checkpoint_interval_s, and when interrupted);
// with files.resume, the run continues from them and reaches the result of an uninterrupted run.
SrmResult run_strength_reduction(const Scene& scene, const SrmOptions& options, std::optional<double> lem_bishop_fs,
                                 const std::map<std::string, double>& lem_fs_by_method, std::ostream* log,
                                 const SrmFiles& files = {});

}  // namespace coupling
