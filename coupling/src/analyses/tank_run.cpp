// --resume and the outcome of the runs of the flows in a tank (coupling/analyses/tank_run.hpp).
#include "coupling/analyses/tank_run.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <stdexcept>

#include "coupling/scene/json_reader.hpp"

namespace coupling {

std::optional<ReportRecord> resume_tank_run(const WorkflowOptions& options, const std::string& analysis,
                               const std::function<void(const std::string& path)>& read_checkpoint,
                               const sph::RunState& state, TankMonitorObserver& monitors) {
  if (!options.output_dir) throw std::runtime_error("--resume needs the run folder (-o DIR) that holds checkpoint.bin");
  const std::filesystem::path checkpoint = *options.output_dir / "checkpoint.bin";
  if (!std::filesystem::exists(checkpoint))
    throw std::runtime_error("--resume: no checkpoint at " + checkpoint.string() + " (start the run without --resume)");
  read_checkpoint(checkpoint.string());
  std::ifstream csv(*options.output_dir / "monitors.csv");
  monitors.restore(std::string(std::istreambuf_iterator<char>(csv), {}), state.time);
  if (options.log)
    *options.log << analysis << ": resuming at t = " << state.time << " s (step " << state.step << ")\n";
  return read_report_record(*options.output_dir / "report.json");
}

void tank_run_outcome(const sph::RunSummary& summary, const std::string& analysis, StageOutcome& outcome) {
  if (summary.stopped_because == "interrupted") {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back(analysis + ": the run was interrupted at t = " + format_number(summary.simulated_time) +
                             " s; continue it with --resume");
  } else if (summary.stopped_because != "end_time") {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back(analysis + ": stopped (" + summary.stopped_because + ") " + summary.diagnostic);
  }
}

}  // namespace coupling
