#pragma once
// Small helpers shared by the coupling tests that run the program on files.
#include "test_paths.hpp"
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/output/run_files.hpp"

// A fresh, empty temporary folder, removed when the test ends.
struct TemporaryFolder {
  std::filesystem::path path;
  explicit TemporaryFolder(const std::string& tag) {
    path = std::filesystem::temp_directory_path() / ("sphslope-test-" + tag + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

inline nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in.good()) throw std::runtime_error("cannot read " + file.string());  // fails the test
  return nlohmann::json::parse(in);
}

// Every null (or non-finite number) of the report that its object does not explain: a null is explained when the
// same object holds a non-empty "error" or "<key>_error" (e.g. factor_of_safety: null next to error), or for
// lem.settings.minimum_depth_m (null = automatic, documented).
inline void unexplained_nulls(const nlohmann::json& value, const std::string& path, const nlohmann::json* parent,
                              const std::string& key, std::vector<std::string>& found) {
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it)
      unexplained_nulls(it.value(), path.empty() ? it.key() : path + "." + it.key(), &value, it.key(), found);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      unexplained_nulls(value[i], path + "[" + std::to_string(i) + "]", parent, key, found);
  } else if (value.is_null()) {
    // a reason is a non-empty string
    const auto reason = [&](const std::string& name) {
      return parent->contains(name) && (*parent)[name].is_string() && !(*parent)[name].get<std::string>().empty();
    };
    const bool explained = (parent && (reason("error") || reason(key + "_error"))) ||
                           path.ends_with("settings.minimum_depth_m");
    if (!explained) found.push_back(path);
  } else if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    found.push_back(path);
  }
}

inline std::vector<std::string> unexplained_nulls(const nlohmann::json& report) {
  std::vector<std::string> found;
  unexplained_nulls(report, "", nullptr, "", found);
  return found;
}

// The sphslope program's exit status (-1 when it did not exit normally, e.g. killed by a signal) and its stdout
// and stderr together.
struct ProgramRun {
  int status = -1;
  std::string output;
};

inline ProgramRun run_sphslope(const std::string& arguments) {
  const std::string command = std::string("'") + test_paths::binary() + "' " + arguments + " 2>&1";
  ProgramRun result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot start " + command);  // fails the test
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int raw = ::pclose(pipe);
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return result;
}

// Every fault parse_scene finds in the scene, one per line (empty when it is valid).
inline std::string scene_faults(const nlohmann::json& scene) {
  try {
    coupling::parse_scene(scene.dump());
  } catch (const coupling::SceneError& error) {
    std::string all;
    for (const std::string& m : error.messages()) all += m + "\n";
    return all;
  }
  return "";
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in.good()) throw std::runtime_error("cannot read " + file.string());  // fails the test
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Limit equilibrium only (as `sphslope lem -o dir`), writing report.json, report.html and the figures into dir.
inline coupling::WorkflowResult run_lem_into(const coupling::Scene& scene, const std::filesystem::path& dir) {
  coupling::WorkflowOptions options;
  options.mode = coupling::Mode::lem;
  options.output_dir = dir;
  return coupling::run_scene(scene, options);
}
