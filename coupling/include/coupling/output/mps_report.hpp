#pragma once
// The "mps" block of report.json, from the typed result of the mps stage (coupling/analyses/mps_stage.hpp;
// docs/scene-format.md, report "mps").
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/analyses/mps_stage.hpp"

namespace coupling {

nlohmann::json mps_report(const MpsStageResult& result);

// profiles.csv: time_s, x_m, surface_m, bed_m, one row per bin and time.
std::string profiles_csv(const std::vector<Profile>& profiles);
// profiles.svg: the surface (solid) and the bed (dashed) at each time over the tank, y exaggerated.
std::string profiles_svg(const std::vector<Profile>& profiles, const Tank& tank, const std::string& title,
                         std::optional<double> dam_x);
nlohmann::json mps_error_report(const std::string& error);

}  // namespace coupling
