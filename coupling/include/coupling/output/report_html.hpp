#pragma once
// report.html: the run on one printable A4 page (scene summary, factors of safety per method, the figures, the
// comparison with its verdict, warnings and errors), built from report.json's content and the scene; the figures
// are inlined so the file stands alone. Its layout is checked by printing it in headless Chromium
// (scripts/check-report-html).
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/scene/scene.hpp"

namespace coupling {

// The page for `report` (a complete report.json document); figures listed in report["figures"] are read from
// `dir` and inlined (an unreadable figure is named in the page instead).
std::string report_html(const Scene& scene, const nlohmann::json& report, const std::filesystem::path& dir);

}  // namespace coupling
