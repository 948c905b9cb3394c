#pragma once
// What the stages of the flows in a tank (isph, mps) share around their run: --resume from the run folder's
// checkpoint with the monitors' earlier rows kept, and the stage's outcome of the run's stop.
#include <functional>
#include <string>

#include <optional>

#include "coupling/analyses/report_record.hpp"
#include "coupling/analyses/stage.hpp"
#include "coupling/analyses/tank_monitors.hpp"
#include "sph/engine/run_loop.hpp"

namespace coupling {

// --resume: `read_checkpoint` reads options.output_dir/checkpoint.bin into the model (whose RunState is `state`),
// the monitors keep the rows of the folder's monitors.csv up to the checkpoint's time, and "<analysis>: resuming at
// t = ... s (step ...)" goes to the log. Returns the record of the folder's earlier report.json (none when there is
// none), for the figures a run carries over its whole length. Throws std::runtime_error without a run folder or a
// checkpoint in it.
std::optional<ReportRecord> resume_tank_run(const WorkflowOptions& options, const std::string& analysis,
                               const std::function<void(const std::string& path)>& read_checkpoint,
                               const sph::RunState& state, TankMonitorObserver& monitors);

// The outcome of a run's stop: at its end time nothing; interrupted (Ctrl-C) a failure that says to continue it
// with --resume; any other stop a failure with the diagnostic.
void tank_run_outcome(const sph::RunSummary& summary, const std::string& analysis, StageOutcome& outcome);

}  // namespace coupling
