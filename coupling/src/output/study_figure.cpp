// The error-against-run-time figure of `sphslope study`: a log-log plot, one line per monitored quantity.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "coupling/studies/study.hpp"
#include "coupling/output/svg.hpp"

namespace coupling {
namespace {

constexpr double error_floor = 1e-6;  // errors below it (e.g. exactly 0) are drawn on it, hollow

std::string fixed(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v);
  return buffer;
}

std::string decade_label(int exponent) {
  if (exponent >= -2 && exponent <= 3) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", std::pow(10.0, exponent));
    return buffer;
  }
  return "1e" + std::to_string(exponent);
}

// Distinct colours for up to eight lines (then repeated with a dash pattern).
const char* palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};

}  // namespace

std::string error_vs_runtime_svg(const std::string& title, const std::vector<StudySeries>& series) {
  double t_lo = 1e300, t_hi = -1e300, e_lo = 1e300, e_hi = -1e300;
  for (const auto& s : series)
    for (std::size_t k = 0; k < s.seconds.size() && k < s.errors.size(); ++k) {
      if (!(s.seconds[k] > 0.0) || !std::isfinite(s.errors[k])) continue;
      t_lo = std::min(t_lo, s.seconds[k]);
      t_hi = std::max(t_hi, s.seconds[k]);
      const double e = std::max(s.errors[k], error_floor);
      e_lo = std::min(e_lo, e);
      e_hi = std::max(e_hi, e);
    }
  const bool empty = !(t_hi >= t_lo);
  const int tx0 = empty ? -1 : static_cast<int>(std::floor(std::log10(t_lo)));
  const int tx1 = empty ? 3 : std::max(tx0 + 1, static_cast<int>(std::ceil(std::log10(t_hi))));
  const int ey0 = empty ? -4 : static_cast<int>(std::floor(std::log10(e_lo)));
  const int ey1 = empty ? 0 : std::max(ey0 + 1, static_cast<int>(std::ceil(std::log10(e_hi))));

  const double left = 80, top = 50, plot_w = 640, plot_h = 420, right_pad = 40;
  const double rows = static_cast<double>(series.size());
  const double width = left + plot_w + right_pad, height = top + plot_h + 60 + 20 * rows + 10;
  auto px = [&](double t) { return left + plot_w * (std::log10(t) - tx0) / (tx1 - tx0); };
  auto py = [&](double e) { return top + plot_h * (ey1 - std::log10(std::max(e, error_floor))) / (ey1 - ey0); };

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"sans-serif\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << left << "\" y=\"28\" font-size=\"16\">" << xml_escape(title) << "</text>\n";
  // grid and decade ticks
  for (int d = tx0; d <= tx1; ++d) {
    const double x = px(std::pow(10.0, d));
    svg << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << top + plot_h
        << "\" stroke=\"#ddd\"/>\n";
    svg << "<text x=\"" << x << "\" y=\"" << top + plot_h + 18 << "\" font-size=\"12\" text-anchor=\"middle\">"
        << decade_label(d) << "</text>\n";
  }
  for (int d = ey0; d <= ey1; ++d) {
    const double y = py(std::pow(10.0, d));
    svg << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << left + plot_w << "\" y2=\"" << y
        << "\" stroke=\"#ddd\"/>\n";
    svg << "<text x=\"" << left - 6 << "\" y=\"" << y + 4 << "\" font-size=\"12\" text-anchor=\"end\">"
        << decade_label(d) << "</text>\n";
  }
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << plot_w << "\" height=\"" << plot_h
      << "\" fill=\"none\" stroke=\"#333\"/>\n";
  svg << "<text x=\"" << left + 0.5 * plot_w << "\" y=\"" << top + plot_h + 38
      << "\" font-size=\"13\" text-anchor=\"middle\">wall time (s)</text>\n";
  svg << "<text x=\"20\" y=\"" << top + 0.5 * plot_h << "\" font-size=\"13\" text-anchor=\"middle\" "
      << "transform=\"rotate(-90 20 " << top + 0.5 * plot_h << ")\">relative error (-)</text>\n";
  if (empty)
    svg << "<text x=\"" << left + 0.5 * plot_w << "\" y=\"" << top + 0.5 * plot_h
        << "\" font-size=\"14\" text-anchor=\"middle\">no finished run with a measurable error</text>\n";

  for (std::size_t k = 0; k < series.size(); ++k) {
    const StudySeries& s = series[k];
    const std::string colour = palette[k % std::size(palette)];
    const std::string dash = k < std::size(palette) ? "" : " stroke-dasharray=\"6 4\"";
    std::ostringstream points;
    for (std::size_t i = 0; i < s.seconds.size() && i < s.errors.size(); ++i)
      if (s.seconds[i] > 0.0 && std::isfinite(s.errors[i]))
        points << fixed(px(s.seconds[i])) << "," << fixed(py(s.errors[i])) << " ";
    svg << "<polyline points=\"" << points.str() << "\" fill=\"none\" stroke=\"" << colour
        << "\" stroke-width=\"1.8\"" << dash << "/>\n";
    for (std::size_t i = 0; i < s.seconds.size() && i < s.errors.size(); ++i) {
      if (!(s.seconds[i] > 0.0) || !std::isfinite(s.errors[i])) continue;
      const bool floored = s.errors[i] < error_floor;
      svg << "<circle cx=\"" << fixed(px(s.seconds[i])) << "\" cy=\"" << fixed(py(s.errors[i])) << "\" r=\"4\" fill=\""
          << (floored ? "white" : colour) << "\" stroke=\"" << colour << "\"><title>"
          << xml_escape(s.label + ", " + (i < s.point_labels.size() ? s.point_labels[i] : "")) << "</title></circle>\n";
      if (i < s.point_labels.size())
        svg << "<text x=\"" << fixed(px(s.seconds[i]) + 6) << "\" y=\"" << fixed(py(s.errors[i]) - 6)
            << "\" font-size=\"10\" fill=\"" << colour << "\">" << xml_escape(s.point_labels[i]) << "</text>\n";
    }
    const double ly = top + plot_h + 62 + 20 * static_cast<double>(k);
    svg << "<line x1=\"" << left << "\" y1=\"" << ly - 4 << "\" x2=\"" << left + 28 << "\" y2=\"" << ly - 4
        << "\" stroke=\"" << colour << "\" stroke-width=\"2\"" << dash << "/>\n";
    svg << "<text x=\"" << left + 36 << "\" y=\"" << ly << "\" font-size=\"12\">" << xml_escape(s.label)
        << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace coupling
