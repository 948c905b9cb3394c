#pragma once
// sphslope batch: runs a set of scenes (a folder of *.json or a manifest listing scene files), one run folder per
// scene, a bounded number of parallel jobs, resumable (finished scenes are skipped, interrupted ones resumed),
// and writes summary.csv, summary.json and junit.xml. With an index it runs one scene of the list (a scheduler's
// array job); with summary_only it gathers the summary of the runs already made. docs/pipelines.md.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace coupling {

struct BatchOptions {
  std::filesystem::path input;        // a folder (its *.json files) or a manifest (one scene file per line)
  std::filesystem::path output_dir;   // one folder per scene: output_dir/<scene file stem>/
  int jobs = 1;                       // scenes run at once; each gets max(1, cores / jobs) OpenMP threads
  std::optional<std::size_t> index;   // run only this scene of the list (0-based)
  bool summary_only = false;          // run nothing; gather the summary of the runs in output_dir
  std::filesystem::path program;      // the sphslope executable that runs each scene
  std::ostream* log = nullptr;        // progress and messages
};

// The scene files of a folder (sorted) or a manifest (in order; blank lines and lines starting with # are
// skipped; relative paths are relative to the manifest's folder). Throws std::runtime_error naming the problem.
std::vector<std::filesystem::path> batch_scenes(const std::filesystem::path& input);

// Runs the batch; returns the exit status: 0 every scene ran and was accepted, 3 some comparison was not
// accepted, 1 some scene failed, was invalid or the batch was interrupted, 2 invalid batch input.
int run_batch(const BatchOptions& options);

}  // namespace coupling
