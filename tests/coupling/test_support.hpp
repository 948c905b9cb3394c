#pragma once
// Small helpers shared by the coupling tests that run the program on files.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

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
