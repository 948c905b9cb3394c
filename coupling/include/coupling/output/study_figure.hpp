#pragma once
// The study's figure, figures/error_vs_runtime.svg (coupling/studies/study.hpp runs the study and draws it).
#include <string>
#include <vector>

namespace coupling {

// One line of the error-against-run-time figure.
struct StudySeries {
  std::string label;
  std::vector<double> seconds;            // wall time of each point (s)
  std::vector<double> errors;             // relative error of each point (-)
  std::vector<std::string> point_labels;  // e.g. "dx 0.2 m"
};
// Log-log plot of error against wall time; errors below 1e-6 (e.g. exactly 0) are drawn at 1e-6 as hollow marks.
std::string error_vs_runtime_svg(const std::string& title, const std::vector<StudySeries>& series);

}  // namespace coupling
