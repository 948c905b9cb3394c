// analyses.lem.critical_seismic_coefficient.acceleration_record: a ground acceleration record from a CSV file of
// time (s) and acceleration (g), read when the scene is read so that a bad record is refused before anything runs.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "scene_internal.hpp"

namespace coupling {

namespace {

constexpr std::size_t max_record_samples = 2'000'000;  // 33 min at 1 ms: more than any recorded earthquake
constexpr std::uintmax_t max_record_bytes = 100'000'000;  // 50 bytes a line for the most samples
constexpr double step_tolerance = 1e-3;                // each time step within 0.1 % of the record's mean step

std::string trimmed(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

// The two numbers of a data line "t, a" (comma, semicolon, tab or spaces between them); false otherwise.
bool two_numbers(const std::string& line, double& t, double& a) {
  const char* p = line.c_str();
  char* end = nullptr;
  t = std::strtod(p, &end);
  if (end == p) return false;
  p = end;
  while (*p == ' ' || *p == '\t') ++p;
  if (*p == ',' || *p == ';') ++p;
  const char* second = p;
  a = std::strtod(second, &end);
  if (end == second) return false;
  for (p = end; *p != '\0'; ++p)
    if (*p != ' ' && *p != '\t') return false;
  return std::isfinite(t) && std::isfinite(a);
}

// The samples of the file, or false with the fault reported at `path`.
bool read_samples(std::istream& in, const std::string& name, const std::string& path, Diagnostics& diagnostics,
                  std::vector<double>& times, std::vector<double>& accelerations) {
  std::string line;
  int line_number = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string text = trimmed(line);
    if (text.empty() || text[0] == '#') continue;
    const std::string at = name + " line " + std::to_string(line_number) + ": ";
    double t = 0.0, a = 0.0;
    if (!two_numbers(text, t, a)) {
      if (!header_seen && times.empty()) {  // one header line before the data
        header_seen = true;
        continue;
      }
      diagnostics.error(path, at + "\"" + text.substr(0, 40) + "\" is not a time (s) and an acceleration (g)");
      return false;
    }
    header_seen = true;
    if (!times.empty() && !(t > times.back())) {
      diagnostics.error(path, at + "time " + format_number(t) + " s is not after " + format_number(times.back()) +
                                  " s (the times must increase)");
      return false;
    }
    if (times.size() >= max_record_samples) {
      diagnostics.error(path, name + " has more than " + std::to_string(max_record_samples) +
                                  " samples (resample it more coarsely)");
      return false;
    }
    times.push_back(t);
    accelerations.push_back(a);
  }
  if (times.size() < 2) {
    diagnostics.error(path, name + " has " + std::to_string(times.size()) +
                                " samples (at least two: time in s, acceleration in g)");
    return false;
  }
  return true;
}

// Whether every time step is the first one's, to step_tolerance; the fault reported at `path` otherwise.
bool evenly_spaced(const std::vector<double>& times, const std::string& name, const std::string& path,
                   Diagnostics& diagnostics) {
  const double first = times[1] - times[0];
  for (std::size_t i = 2; i < times.size(); ++i) {
    const double dt = times[i] - times[i - 1];
    if (std::fabs(dt - first) > step_tolerance * first) {
      diagnostics.error(path, name + ": uneven time step " + format_number(dt) + " s from " +
                                  format_number(times[i - 1]) + " s, against the first step's " +
                                  format_number(first) + " s (a record must be evenly spaced, to 0.1 %: resample it)");
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<AccelerationRecordInput> read_acceleration_record(JsonReader& reader,
                                                                 const std::filesystem::path& scene_file) {
  Diagnostics& diagnostics = reader.diagnostics();
  AccelerationRecordInput input;
  const auto file = reader.string("file", Need::required);
  input.scale = reader.number_or("scale", 1.0, Bounds::positive());
  reader.finish();
  if (!file) return std::nullopt;
  input.file = *file;
  const std::string path = reader.path_of("file");
  std::filesystem::path where(*file);
  if (where.is_relative()) where = scene_file.parent_path() / where;
  std::error_code error;
  const bool regular = std::filesystem::is_regular_file(where, error);
  if (regular && std::filesystem::file_size(where, error) > max_record_bytes) {
    diagnostics.error(path, "the acceleration record \"" + where.string() + "\" is larger than " +
                                std::to_string(max_record_bytes / 1000000) + " MB (resample it more coarsely)");
    return std::nullopt;
  }
  std::ifstream in;
  if (regular) in.open(where);
  if (!regular || !in) {
    diagnostics.error(path, "cannot read the acceleration record \"" + where.string() +
                                "\" (a regular CSV file of time in s and acceleration in g; a relative path is taken "
                                "from the scene's folder)");
    return std::nullopt;
  }
  const std::string name = where.filename().string();
  std::vector<double> times;
  if (!read_samples(in, name, path, diagnostics, times, input.record.acceleration) ||
      !evenly_spaced(times, name, path, diagnostics))
    return std::nullopt;
  // the mean step: the rounding of the times written averages out
  input.record.time_step = (times.back() - times.front()) / static_cast<double>(times.size() - 1);
  input.start_time = times.front();
  return input;
}

}  // namespace coupling
