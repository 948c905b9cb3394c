#pragma once
// One analysis stage per analysis key of the scene ("lem", "sph", "compare", "srm"), behind one interface. The
// pipeline (run_scene) runs the stages the scene asks for in the order of the table pipeline_stages(). Adding an
// analysis is one stage file (its run function) and one row of that table.
//
// A stage reads its typed settings from the Scene and writes its typed result (and its wall time) into
// context.results, where later stages find what they need; coupling/output turns the results into files.
#include <chrono>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "coupling/analyses/pipeline.hpp"
#include "coupling/compare/comparison.hpp"
#include "coupling/compare/failure_surface.hpp"
#include "coupling/scene/scene.hpp"
#include "sphslope/wall_clock.hpp"

namespace coupling {

// What one analysis stage hands back to the pipeline.
struct StageOutcome {
  ExitStatus status = ExitStatus::ok;
  std::vector<std::string> errors;  // invalid input: JSON-path messages; failed: reasons; not accepted: criteria

  // A stage that stopped without a result: failed, for `reason` ("<stage>: why"), which its record keeps as well.
  void fail(std::string reason, std::string& record_error) {
    status = ExitStatus::failed;
    errors.push_back(std::move(reason));
    record_error = errors.back();
  }
};

// What the stages of one run share.
struct StageContext {
  const WorkflowOptions& options;
  RunResults& results;            // each stage's typed result; the LE result and the SPH state for later stages
  std::optional<LemAnalysis> lem;  // analyses.lem, or its defaults for "sphslope lem"
};

struct Stage {
  std::string_view key;                                       // the analysis name in the scene and the report
  bool (*requested)(const Scene& scene, const StageContext& context);  // does this run ask for it?
  StageOutcome (*run)(const Scene& scene, StageContext& context);
};

// The stages in the order they run: limit equilibrium first (fast, and it can still reject the input before
// anything is written), then SPH, the comparison of the two, and strength reduction.
std::span<const Stage> pipeline_stages();

// The run functions of the stages (one file each: lem_stage.cpp, sph_stage.cpp, compare_stage.cpp, srm_stage.cpp).
StageOutcome run_lem_stage(const Scene& scene, StageContext& context);
StageOutcome run_sph_analysis_stage(const Scene& scene, StageContext& context);
StageOutcome run_compare_stage(const Scene& scene, StageContext& context);
StageOutcome run_srm_stage(const Scene& scene, StageContext& context);
StageOutcome run_isph_stage(const Scene& scene, StageContext& context);  // isph_stage.cpp
StageOutcome run_mps_stage(const Scene& scene, StageContext& context);  // mps_stage.cpp
StageOutcome run_coupled_stage(const Scene& scene, StageContext& context);  // coupled_stage.cpp

// Wall-clock seconds for the report's timing_s block.
using StageClock = sphslope::WallClock;
using sphslope::seconds_since;

}  // namespace coupling
