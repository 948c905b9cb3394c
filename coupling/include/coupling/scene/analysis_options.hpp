#pragma once
// The typed settings of analyses.compare and analyses.srm, read once by the scene loader (load_scene); the
// stages use these structs and never see the JSON. Keys, units and defaults: docs/scene-format.md.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/scene/json_reader.hpp"

namespace coupling {

// ---- analyses.compare

// How the SPH failure surface is read out of the plastic-strain field (compare/failure_surface.hpp).
struct BandOptions {
  double plastic_strain_threshold = 0.1;  // particles at or above it belong to the band
  double bin_width = 0.0;                 // m; 0 means 2 x spacing
  int min_particles_per_bin = 2;          // bins with fewer band particles are skipped
  bool initial_configuration = true;      // read the band on the initial positions (where LEM surfaces live)
};
// analyses.compare.configuration's names, each with its initial_configuration.
inline constexpr sphslope::NameTable<bool, 2> band_configuration_names{{{"initial", true}, {"current", false}}};

// A length limit in metres, or in particle spacings of the SPH run.
struct LengthLimit {
  double value = 0.0;
  bool in_spacings = false;
  double metres(double particle_spacing) const { return in_spacings ? value * particle_spacing : value; }
};

struct AcceptanceCriteria {
  std::vector<std::string> methods;            // LE method keys the criteria apply to (default: bishop)
  std::optional<LengthLimit> entry_offset;     // distance between the SPH and LE entry points
  std::optional<LengthLimit> exit_offset;      // distance between the SPH and LE exit points
  std::optional<LengthLimit> mean_normal_distance;
  std::optional<LengthLimit> max_normal_distance;
  std::optional<double> min_overlap;           // intersection over union of the sliding masses, in [0, 1]
  std::optional<double> max_fs_difference;     // |FS of LE on the SPH surface - critical LE FS|
};

struct ComparisonOptions {
  BandOptions band;                   // plastic-strain threshold (default 0.1), bins
  double displacement_threshold = 0;  // m, delta of the displacement cross-check; 0 means 2 particle spacings
  std::optional<AcceptanceCriteria> acceptance;  // pass/fail limits for pipelines (analyses.compare.acceptance)
};

// Reads analyses.compare.acceptance (errors at "analyses.compare.acceptance.<key>"); `known_methods` are the method
// keys the scene's LE analysis computes (a criterion on another method is an error).
std::optional<AcceptanceCriteria> read_acceptance(const nlohmann::json& block, const std::vector<std::string>& known_methods,
                                                  Diagnostics& diagnostics);

// Reads analyses.compare (errors at "analyses.compare.<key>"): plastic_strain_threshold, bin_width_m,
// configuration ("initial" | "current"), displacement_threshold_m, acceptance. `lem_methods` are the keys of the
// methods the scene's limit-equilibrium analysis computes (acceptance criteria may name only those).
std::optional<ComparisonOptions> read_comparison_options(const nlohmann::json& block,
                                                         const std::vector<std::string>& lem_methods,
                                                         Diagnostics& diagnostics);

// ---- analyses.srm

// The range of trial factors the bisection may explore (and an analyses.srm.bracket must lie in).
inline constexpr double srm_min_factor = 0.05, srm_max_factor = 20.0;

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

}  // namespace coupling
