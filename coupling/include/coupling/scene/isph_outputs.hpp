#pragma once
// analyses.isph's outputs beyond monitors.csv (docs/scene-format.md): the times of the particle snapshots
// (snapshots_s) and the reference drawn with the front in figures/isph_front.svg (front_reference). Read before the
// rest of analyses.isph (read_isph_outputs marks its keys as known), checked against it afterwards
// (check_isph_outputs: the end time, the front monitor, the tank).
#include <optional>
#include <string>
#include <vector>

#include "coupling/scene/json_reader.hpp"

namespace coupling {

struct IsphAnalysis;

// front_reference: Martin & Moyce's tabulated front (data "martin_moyce_1952_n2_2", with the column's width a and
// x measured from the tank's left wall), Ritter's dry-bed front from the dam, or both.
struct FrontReference {
  std::string data;  // "martin_moyce_1952_n2_2" or empty
  double column_width = 0;  // a [m], with data
  std::optional<double> ritter_dam_x, ritter_depth;  // [m], together
};

struct IsphOutputs {
  std::vector<double> snapshot_times;  // [s], increasing: figures/isph_snapshot_<t>s.svg
  std::optional<FrontReference> front_reference;
};

inline constexpr const char* martin_moyce_n2_2_key = "martin_moyce_1952_n2_2";

// Reads isph.snapshots_s and isph.front_reference (faults to the reader's diagnostics with their JSON paths).
IsphOutputs read_isph_outputs(JsonReader& isph);

// Once the rest of analyses.isph is read: every snapshot time at most end_time_s, a front reference only with the
// front monitor, Ritter's dam inside the tank. Faults name their paths under isph_path.
void check_isph_outputs(const IsphOutputs& outputs, const IsphAnalysis& analysis, const std::string& isph_path,
                        Diagnostics& diagnostics);

}  // namespace coupling
