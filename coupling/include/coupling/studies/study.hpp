#pragma once
// Error against run time (`sphslope study`): one scene run at several particle spacings, every monitored quantity
// compared with its cited reference, the observed order of convergence, and — for slope sections — the
// limit-equilibrium search against its finest setting. Writes DIR/study.json, DIR/figures/error_vs_runtime.svg
// and one run folder per spacing (DIR/runs/dx_<spacing>_m/, each a complete `sphslope run` folder).
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/output/study_figure.hpp"

namespace coupling {

struct StudyOptions {
  std::vector<double> spacings;      // m, particle spacings (any order; run coarse to fine)
  std::filesystem::path output_dir;  // study.json, figures/, runs/
  bool resume = false;               // reuse finished spacings, continue an interrupted one from its checkpoint
  bool lem_search = true;            // slope sections: also study the limit-equilibrium search
  std::ostream* log = nullptr;       // progress (stderr in the program)
};

struct StudyResult {
  ExitStatus status = ExitStatus::ok;
  std::vector<std::string> errors;  // invalid input: what is wrong; failed: which runs failed and why
  nlohmann::json study;             // the content of study.json (null for invalid input)
};

// Which reference a scene is measured against (chosen from the scene, see docs/accuracy.md):
//   slope section with analyses.sph        -> the limit-equilibrium critical circle (entry, exit, depth, mass)
//   one body, every material elastic       -> the elastic soil column (closed-form oedometric stress)
//   one body of Drucker-Prager soil        -> the granular column collapse (true-2-D experiments' scaling laws)
//   analyses.mps, one granular block       -> the dry collapse of Lajeunesse et al. (2005) (2-D scaling laws)
//   analyses.isph with front_reference     -> the dam break of Martin & Moyce (1952) (their tabulated front)
StudyResult run_study(const std::filesystem::path& scene_file, const StudyOptions& options);

}  // namespace coupling
