#pragma once
// The one reader of a run folder's report.json (coupling/output writes it): what --resume carries over from the run
// before the checkpoint, and what a batch lists of each run. Nothing else reads a report back by key.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "coupling/analyses/isph_bodies.hpp"
#include "coupling/compare/acceptance.hpp"
#include "slope/section.hpp"

namespace coupling {

// What an isph run carries over its whole length (the "isph" block; --resume).
struct IsphCarryOver {
  double max_density_error = 0, mean_density_error = 0, largest_time_step = 0;  // [-], [-], [s]
  std::size_t wall_contacts = 0;
  std::optional<double> fluid_energy_start;  // [J/m]
  std::vector<BodyRecord> bodies;            // name, max speed, work on the fluid, stop time
  std::size_t past_walls_most = 0;
  std::optional<double> past_walls_first_time;  // [s]
};

// What an mps run carries over its whole length (the "mps" block; --resume).
struct MpsCarryOver {
  double max_speed = 0;  // [m/s] over the run
};

// The comparison of a run against one LE method (the "comparison" block; batch summaries).
struct ComparisonRecord {
  std::string method;  // bishop when compared, else the first method of the block
  std::optional<slope::Point> entry_offset, exit_offset;  // SPH - LE [m]
  std::optional<double> mean_normal_distance, intersection_over_union;  // [m], [-]
  std::optional<AcceptanceResult> acceptance;  // analyses.compare.acceptance
};

struct ReportRecord {
  std::string status = "failed";   // "ok", "failed", "not_accepted"
  std::vector<std::string> errors;  // the report's "errors"
  double total_seconds = 0;         // timing_s.total
  std::optional<std::string> sph_stopped_because;
  std::vector<std::pair<std::string, std::optional<double>>> lem_factors;  // method key and its FS, in key order
  std::optional<ComparisonRecord> comparison;
  std::optional<IsphCarryOver> isph;
  std::optional<MpsCarryOver> mps;
};

// The record of `report_json`; none when the file does not exist or is not a report.
std::optional<ReportRecord> read_report_record(const std::filesystem::path& report_json);

}  // namespace coupling
