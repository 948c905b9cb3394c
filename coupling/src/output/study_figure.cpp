// The error-against-run-time figure of `sphslope study`: a log-log plot, one line per monitored quantity.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "coupling/output/study_figure.hpp"
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

// The plot area and its decades: wall time on x, relative error on y, both logarithmic.
struct LogPlot {
  int tx0 = -1, tx1 = 3, ey0 = -4, ey1 = 0;  // decades shown
  bool empty = true;                         // no point to draw
  double left = 80, top = 50, plot_w = 640, plot_h = 420, right_pad = 40;
  double px(double t) const { return left + plot_w * (std::log10(t) - tx0) / (tx1 - tx0); }
  double py(double e) const { return top + plot_h * (ey1 - std::log10(std::max(e, error_floor))) / (ey1 - ey0); }
};

LogPlot log_plot(const std::vector<StudySeries>& series) {
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
  LogPlot plot;
  plot.empty = !(t_hi >= t_lo);
  if (plot.empty) return plot;
  plot.tx0 = static_cast<int>(std::floor(std::log10(t_lo)));
  plot.tx1 = std::max(plot.tx0 + 1, static_cast<int>(std::ceil(std::log10(t_hi))));
  plot.ey0 = static_cast<int>(std::floor(std::log10(e_lo)));
  plot.ey1 = std::max(plot.ey0 + 1, static_cast<int>(std::ceil(std::log10(e_hi))));
  return plot;
}

// Grid lines and decade labels of both axes, the frame and the axis titles.
void draw_axes(const LogPlot& p, std::ostringstream& svg) {
  for (int d = p.tx0; d <= p.tx1; ++d) {
    const double x = p.px(std::pow(10.0, d));
    svg << "<line x1=\"" << x << "\" y1=\"" << p.top << "\" x2=\"" << x << "\" y2=\"" << p.top + p.plot_h
        << "\" stroke=\"#ddd\"/>\n";
    svg << "<text x=\"" << x << "\" y=\"" << p.top + p.plot_h + 18 << "\" font-size=\"12\" text-anchor=\"middle\">"
        << decade_label(d) << "</text>\n";
  }
  for (int d = p.ey0; d <= p.ey1; ++d) {
    const double y = p.py(std::pow(10.0, d));
    svg << "<line x1=\"" << p.left << "\" y1=\"" << y << "\" x2=\"" << p.left + p.plot_w << "\" y2=\"" << y
        << "\" stroke=\"#ddd\"/>\n";
    svg << "<text x=\"" << p.left - 6 << "\" y=\"" << y + 4 << "\" font-size=\"12\" text-anchor=\"end\">"
        << decade_label(d) << "</text>\n";
  }
  svg << "<rect x=\"" << p.left << "\" y=\"" << p.top << "\" width=\"" << p.plot_w << "\" height=\"" << p.plot_h
      << "\" fill=\"none\" stroke=\"#333\"/>\n";
  svg << "<text x=\"" << p.left + 0.5 * p.plot_w << "\" y=\"" << p.top + p.plot_h + 38
      << "\" font-size=\"13\" text-anchor=\"middle\">wall time (s)</text>\n";
  svg << "<text x=\"20\" y=\"" << p.top + 0.5 * p.plot_h << "\" font-size=\"13\" text-anchor=\"middle\" "
      << "transform=\"rotate(-90 20 " << p.top + 0.5 * p.plot_h << ")\">relative error (-)</text>\n";
  if (p.empty)
    svg << "<text x=\"" << p.left + 0.5 * p.plot_w << "\" y=\"" << p.top + 0.5 * p.plot_h
        << "\" font-size=\"14\" text-anchor=\"middle\">no finished run with a measurable error</text>\n";
}

// Series k: its line, its points (hollow when below the error floor) with labels, and its legend row.
void draw_series(const LogPlot& p, const StudySeries& s, std::size_t k, std::ostringstream& svg) {
  const std::string colour = palette[k % std::size(palette)];
  const std::string dash = k < std::size(palette) ? "" : " stroke-dasharray=\"6 4\"";
  std::ostringstream points;
  for (std::size_t i = 0; i < s.seconds.size() && i < s.errors.size(); ++i)
    if (s.seconds[i] > 0.0 && std::isfinite(s.errors[i]))
      points << fixed(p.px(s.seconds[i])) << "," << fixed(p.py(s.errors[i])) << " ";
  svg << "<polyline points=\"" << points.str() << "\" fill=\"none\" stroke=\"" << colour
      << "\" stroke-width=\"1.8\"" << dash << "/>\n";
  for (std::size_t i = 0; i < s.seconds.size() && i < s.errors.size(); ++i) {
    if (!(s.seconds[i] > 0.0) || !std::isfinite(s.errors[i])) continue;
    const bool floored = s.errors[i] < error_floor;
    svg << "<circle cx=\"" << fixed(p.px(s.seconds[i])) << "\" cy=\"" << fixed(p.py(s.errors[i])) << "\" r=\"4\" fill=\""
        << (floored ? "white" : colour) << "\" stroke=\"" << colour << "\"><title>"
        << xml_escape(s.label + ", " + (i < s.point_labels.size() ? s.point_labels[i] : "")) << "</title></circle>\n";
    if (i < s.point_labels.size())
      svg << "<text x=\"" << fixed(p.px(s.seconds[i]) + 6) << "\" y=\"" << fixed(p.py(s.errors[i]) - 6)
          << "\" font-size=\"10\" fill=\"" << colour << "\">" << xml_escape(s.point_labels[i]) << "</text>\n";
  }
  const double ly = p.top + p.plot_h + 62 + 20 * static_cast<double>(k);
  svg << "<line x1=\"" << p.left << "\" y1=\"" << ly - 4 << "\" x2=\"" << p.left + 28 << "\" y2=\"" << ly - 4
      << "\" stroke=\"" << colour << "\" stroke-width=\"2\"" << dash << "/>\n";
  svg << "<text x=\"" << p.left + 36 << "\" y=\"" << ly << "\" font-size=\"12\">" << xml_escape(s.label)
      << "</text>\n";
}

}  // namespace

std::string error_vs_runtime_svg(const std::string& title, const std::vector<StudySeries>& series) {
  const LogPlot plot = log_plot(series);
  const double rows = static_cast<double>(series.size());
  const double width = plot.left + plot.plot_w + plot.right_pad, height = plot.top + plot.plot_h + 60 + 20 * rows + 10;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"sans-serif\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << plot.left << "\" y=\"28\" font-size=\"16\">" << xml_escape(title) << "</text>\n";
  draw_axes(plot, svg);
  for (std::size_t k = 0; k < series.size(); ++k) draw_series(plot, series[k], k, svg);
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace coupling
