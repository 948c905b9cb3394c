#pragma once
// report.html: the run on one printable A4 page (scene summary, factors of safety per method, the figures, the
// comparison with its verdict, warnings and errors), built from the run's typed results and the scene; the figures
// are inlined so the file stands alone. Its layout is checked by printing it in headless Chromium
// (scripts/check-report-html).
#include <filesystem>
#include <string>
#include <vector>

#include "coupling/analyses/run_results.hpp"
#include "coupling/scene/scene.hpp"

namespace coupling {

// What the page states of the run besides the stages' results: its status ("ok", "failed", "not_accepted"), its
// errors (report.json's "errors") and the figures written (relative to the run folder).
struct RunPage {
  std::string status = "ok";
  std::vector<std::string> errors;
  std::vector<std::string> figures;
};

// The page; the figures are read from `dir` and inlined (an unreadable figure is named in the page instead).
std::string report_html(const Scene& scene, const RunResults& results, const RunPage& page,
                        const std::filesystem::path& dir);

}  // namespace coupling
