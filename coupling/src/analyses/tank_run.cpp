// --resume and the outcome of the runs of the flows in a tank (coupling/analyses/tank_run.hpp).
#include "coupling/analyses/tank_run.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <stdexcept>

#include "coupling/scene/json_reader.hpp"

namespace coupling {

nlohmann::json resume_tank_run(const WorkflowOptions& options, const std::string& analysis,
                               const std::function<void(const std::string& path)>& read_checkpoint,
                               const sph::RunState& state, TankMonitorObserver& monitors) {
  if (!options.output_dir) throw std::runtime_error("--resume needs the run folder (-o DIR) that holds checkpoint.bin");
  const std::filesystem::path checkpoint = *options.output_dir / "checkpoint.bin";
  if (!std::filesystem::exists(checkpoint))
    throw std::runtime_error("--resume: no checkpoint at " + checkpoint.string() + " (start the run without --resume)");
  read_checkpoint(checkpoint.string());
  std::ifstream csv(*options.output_dir / "monitors.csv");
  monitors.restore(std::string(std::istreambuf_iterator<char>(csv), {}), state.time);
  std::ifstream report(*options.output_dir / "report.json");
  const nlohmann::json earlier = nlohmann::json::parse(report, nullptr, false);
  if (options.log)
    *options.log << analysis << ": resuming at t = " << state.time << " s (step " << state.step << ")\n";
  if (earlier.is_discarded() || !earlier.contains(analysis) || !earlier[analysis].is_object())
    return nlohmann::json::object();
  return earlier[analysis];
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
