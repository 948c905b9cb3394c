#include "coupling/app/batch.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "coupling/analyses/report_record.hpp"
#include "coupling/output/batch_summary.hpp"
#include "coupling/output/comparison_report.hpp"
#include "sph/engine/atomic_file.hpp"
#include "coupling/scene/json_text.hpp"

extern char** environ;

namespace coupling {

namespace fs = std::filesystem;

namespace {

volatile std::sig_atomic_t batch_interrupted = 0;
void on_batch_interrupt(int) { batch_interrupted = 1; }

// What a scene's run folder says about it.
enum class RunState { fresh, interrupted, finished };

std::optional<ReportRecord> read_report(const fs::path& folder) { return read_report_record(folder / "report.json"); }

RunState run_state(const fs::path& folder) {
  if (const auto report = read_report(folder)) {
    const bool interrupted = report->sph_stopped_because == "interrupted";
    return interrupted && fs::exists(folder / "checkpoint.bin") ? RunState::interrupted : RunState::finished;
  }
  return fs::exists(folder / "checkpoint.bin") ? RunState::interrupted : RunState::fresh;
}

struct Job {
  fs::path scene;
  fs::path folder;
  std::optional<int> exit_status;  // of this session's run; empty when skipped
  double seconds = 0.0;
  bool resumed = false;
};

// Starts `program run SCENE -o FOLDER [--resume]` with stdout and stderr in FOLDER.log.
pid_t launch(const fs::path& program, Job& job, int threads) {
  std::vector<std::string> args = {program.string(), "run", job.scene.string(), "-o", job.folder.string()};
  if (job.resumed) args.push_back("--resume");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_strings;
  for (char** e = environ; *e != nullptr; ++e)
    if (std::string(*e).rfind("OMP_NUM_THREADS=", 0) != 0) env_strings.emplace_back(*e);
  env_strings.push_back("OMP_NUM_THREADS=" + std::to_string(threads));
  std::vector<char*> envp;
  for (auto& e : env_strings) envp.push_back(e.data());
  envp.push_back(nullptr);
  const std::string log = job.folder.string() + ".log";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error("cannot start " + program.string() + " for " + job.scene.string());
  return pid;
}

std::string status_of(const std::optional<ReportRecord>& report, const std::optional<int>& exit_status) {
  if (report) return report->status;
  if (exit_status && *exit_status == 2) return "invalid_input";
  return exit_status ? "failed" : "not_run";
}

int exit_of(const std::string& status) {
  if (status == "ok") return 0;
  if (status == "not_accepted") return 3;
  if (status == "invalid_input") return 2;
  return 1;
}

// The last lines of a run's log (the reason of an invalid or failed run).
std::string log_tail(const fs::path& log, std::size_t lines = 3) {
  std::ifstream in(log);
  std::vector<std::string> all;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) all.push_back(line);
  std::string text;
  for (std::size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i)
    text += (text.empty() ? "" : "\n") + all[i];
  return text;
}

// One summary row per scene: status, FS per method, the comparison against the acceptance method (or Bishop).
// The exit status of a scene's last run (this session's, or the one recorded in <folder>.exit by an earlier batch).
std::optional<int> last_exit_status(const Job& job) {
  if (job.exit_status) return job.exit_status;
  std::ifstream in(job.folder.string() + ".exit");
  int status = 0;
  if (in >> status) return status;
  return std::nullopt;
}

nlohmann::json optional_json(const std::optional<double>& value) { return value ? nlohmann::json(*value) : nlohmann::json(); }
nlohmann::json optional_json(const std::optional<slope::Point>& p) {
  return p ? nlohmann::json::array({p->x, p->y}) : nlohmann::json();
}

nlohmann::json summary_row(const Job& job, const fs::path& output_dir) {
  const auto report = read_report(job.folder);
  nlohmann::json row;
  row["scene"] = job.scene.string();
  row["folder"] = fs::relative(job.folder, output_dir).string();
  row["status"] = status_of(report, last_exit_status(job));
  row["exit_status"] = exit_of(row["status"]);
  row["seconds"] = report ? report->total_seconds : job.seconds;
  nlohmann::json fs_by_method = nlohmann::json::object();
  if (report)
    for (const auto& [key, fs] : report->lem_factors) fs_by_method[key] = optional_json(fs);
  row["factor_of_safety"] = fs_by_method;
  if (report && report->comparison) {
    const ComparisonRecord& c = *report->comparison;
    row["comparison"] = {{"method", c.method},
                         {"entry_offset_m", optional_json(c.entry_offset)},
                         {"exit_offset_m", optional_json(c.exit_offset)},
                         {"mean_normal_distance_m", optional_json(c.mean_normal_distance)},
                         {"intersection_over_union", optional_json(c.intersection_over_union)}};
    if (c.acceptance) {
      row["accepted"] = c.acceptance->accepted;
      row["criteria"] = acceptance_json(*c.acceptance)["criteria"];
    }
  }
  if (row["exit_status"] == 1 || row["exit_status"] == 2) {
    std::string reason = report && !report->errors.empty() ? report->errors.front()
                                                           : log_tail(fs::path(job.folder.string() + ".log"));
    row["reason"] = reason.empty() ? "the scene was not run" : reason;
  }
  return row;
}

int batch_exit_status(const nlohmann::json& rows, bool interrupted) {
  int status = 0;
  for (const auto& row : rows) {
    const int s = row["exit_status"];
    if (s == 1 || s == 2) status = 1;
    else if (s == 3 && status == 0) status = 3;
  }
  return interrupted ? 1 : status;
}

// "[3/12] ": how many scenes are done out of all.
std::string progress(std::size_t done, std::size_t total) {
  std::ostringstream text;
  text << "[" << done << "/" << total << "] ";
  return text.str();
}

// Runs the scenes that are not finished, at most `jobs` at once; skips finished ones.
bool run_jobs(std::vector<Job>& jobs, const BatchOptions& options) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const int parallel = std::max(1, options.jobs);
  const int threads = std::max(1, static_cast<int>(cores) / parallel);
  std::map<pid_t, std::pair<std::size_t, std::chrono::steady_clock::time_point>> running;
  std::size_t next = 0, done = 0;
  auto say = [&](const std::string& text) { if (options.log) *options.log << text << std::flush; };
  while (done < jobs.size()) {
    while (!batch_interrupted && next < jobs.size() && static_cast<int>(running.size()) < parallel) {
      Job& job = jobs[next++];
      const RunState state = run_state(job.folder);
      if (state == RunState::finished) {
        ++done;
        say(progress(done, jobs.size()) + job.scene.string() + ": finished in an earlier batch, skipped\n");
        continue;
      }
      job.resumed = state == RunState::interrupted;
      fs::create_directories(job.folder.parent_path());
      running[launch(options.program, job, threads)] = {next - 1, std::chrono::steady_clock::now()};
      say("started " + job.scene.string() + (job.resumed ? " (resuming)" : "") + "\n");
    }
    if (running.empty()) break;  // interrupted before anything else started
    int wstatus = 0;
    const pid_t pid = ::waitpid(-1, &wstatus, 0);
    if (pid < 0) {
      if (errno == EINTR) {
        for (const auto& [child, unused] : running) ::kill(child, SIGINT);  // the children checkpoint and stop
        continue;
      }
      throw std::runtime_error("waiting for the scene runs failed");
    }
    const auto found = running.find(pid);
    if (found == running.end()) continue;
    Job& job = jobs[found->second.first];
    job.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - found->second.second).count();
    job.exit_status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 1;
    sph::write_file_atomically(job.folder.string() + ".exit", std::to_string(*job.exit_status) + "\n");
    running.erase(found);
    ++done;
    const char* outcome[] = {"ok", "failed", "invalid input", "not accepted"};
    const int code = *job.exit_status;
    std::ostringstream line;
    const char* what = batch_interrupted && code == 1 ? "interrupted (checkpoint kept)"
                       : code >= 0 && code <= 3      ? outcome[code]
                                                     : "failed";
    line << progress(done, jobs.size()) << job.scene.string() << ": " << what
         << " (" << static_cast<int>(job.seconds) << " s; " << job.folder.string() << ".log)\n";
    say(line.str());
  }
  return batch_interrupted != 0;
}

}  // namespace

std::vector<fs::path> batch_scenes(const fs::path& input) {
  std::vector<fs::path> scenes;
  if (fs::is_directory(input)) {
    for (const auto& entry : fs::directory_iterator(input))
      if (entry.is_regular_file() && entry.path().extension() == ".json") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
  } else {
    std::ifstream in(input);
    if (!in) throw std::runtime_error("cannot read \"" + input.string() + "\" (a folder of scenes or a manifest)");
    for (std::string line; std::getline(in, line);) {
      line.erase(0, line.find_first_not_of(" \t\r"));
      line.erase(line.find_last_not_of(" \t\r") + 1);
      if (line.empty() || line[0] == '#') continue;
      const fs::path scene = fs::path(line).is_absolute() ? fs::path(line) : input.parent_path() / line;
      if (!fs::is_regular_file(scene))
        throw std::runtime_error(input.string() + ": scene \"" + line + "\" does not exist");
      scenes.push_back(scene);
    }
  }
  if (scenes.empty()) throw std::runtime_error("\"" + input.string() + "\" lists no scene (*.json)");
  std::map<std::string, fs::path> stems;
  for (const auto& scene : scenes) {
    const auto [it, inserted] = stems.emplace(scene.stem().string(), scene);
    if (!inserted)
      throw std::runtime_error("scenes \"" + it->second.string() + "\" and \"" + scene.string() +
                               "\" would share the run folder \"" + scene.stem().string() + "\" (rename one)");
  }
  return scenes;
}

int run_batch(const BatchOptions& options) {
  std::vector<fs::path> scenes;
  try {
    scenes = batch_scenes(options.input);
  } catch (const std::exception& error) {
    if (options.log) *options.log << "batch: " << error.what() << "\n";
    return 2;
  }
  if (options.index && *options.index >= scenes.size()) {
    if (options.log)
      *options.log << "batch: --index " << *options.index << " is beyond the " << scenes.size()
                   << " scenes of the list (0 to " << scenes.size() - 1 << ")\n";
    return 2;
  }
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < scenes.size(); ++i)
    if (!options.index || *options.index == i) jobs.push_back({scenes[i], options.output_dir / scenes[i].stem(), {}, 0.0, false});
  fs::create_directories(options.output_dir);
  batch_interrupted = 0;
  struct sigaction action = {};
  action.sa_handler = on_batch_interrupt;  // no SA_RESTART: waitpid returns so the children can be told
  struct sigaction old_int = {}, old_term = {};
  ::sigaction(SIGINT, &action, &old_int);
  ::sigaction(SIGTERM, &action, &old_term);
  const bool interrupted = options.summary_only ? false : run_jobs(jobs, options);
  ::sigaction(SIGINT, &old_int, nullptr);
  ::sigaction(SIGTERM, &old_term, nullptr);

  if (options.index) {  // an array job runs one scene; the summary is gathered afterwards (--summary-only)
    const nlohmann::json row = summary_row(jobs.front(), options.output_dir);
    return row["exit_status"].get<int>();
  }
  nlohmann::json rows = nlohmann::json::array();
  for (const Job& job : jobs) rows.push_back(summary_row(job, options.output_dir));
  const int status = batch_exit_status(rows, interrupted);
  const nlohmann::json summary = {{"format", "sphslope-batch/1"},
                                  {"input", options.input.string()},
                                  {"exit_status", status},
                                  {"interrupted", interrupted},
                                  {"scenes", rows}};
  sph::write_file_atomically(options.output_dir / "summary.json", json_text(summary));
  sph::write_file_atomically(options.output_dir / "summary.csv", summary_csv(rows));
  sph::write_file_atomically(options.output_dir / "junit.xml", junit_xml(rows));
  if (options.log) {
    *options.log << "batch: " << (options.output_dir / "summary.csv").string() << ", summary.json, junit.xml\n";
    if (interrupted)
      *options.log << "batch: interrupted; run the same command again to continue (finished scenes are skipped, "
                      "interrupted ones resume from their checkpoints)\n";
  }
  return status;
}

}  // namespace coupling
