#include "coupling/output/svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace coupling {

std::string to_hex(Rgb c) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", std::clamp(c.r, 0, 255), std::clamp(c.g, 0, 255),
                std::clamp(c.b, 0, 255));
  return buffer;
}

namespace {

// Linear interpolation between evenly spaced colour stops, t in [0, 1] (clamped; NaN counts as 0).
template <std::size_t N>
Rgb interpolate(const std::array<std::array<int, 3>, N>& stops, double t) {
  if (!std::isfinite(t)) t = 0.0;
  t = std::clamp(t, 0.0, 1.0) * (N - 1);
  const auto k = std::min<std::size_t>(static_cast<std::size_t>(t), N - 2);
  const double f = t - static_cast<double>(k);
  auto mix = [&](int c) { return static_cast<int>(std::lround(stops[k][c] + f * (stops[k + 1][c] - stops[k][c]))); };
  return {mix(0), mix(1), mix(2)};
}

}  // namespace

Rgb colour_map(double t) {
  // Control points sampled from a viridis-like ramp.
  static constexpr std::array<std::array<int, 3>, 6> stops{
      {{68, 1, 84}, {65, 68, 135}, {42, 120, 142}, {34, 168, 132}, {122, 209, 81}, {253, 231, 37}}};
  return interpolate(stops, t);
}

Rgb safety_colour_map(double t) {
  static constexpr std::array<std::array<int, 3>, 6> stops{
      {{165, 0, 38}, {244, 109, 67}, {253, 224, 144}, {224, 243, 248}, {116, 173, 209}, {49, 54, 149}}};
  return interpolate(stops, t);
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

double nice_step(double span, int target_ticks) {
  const double raw = span / std::max(1, target_ticks);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * magnitude >= raw) return m * magnitude;
  return 10.0 * magnitude;
}

namespace {

std::string svg_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buffer;
}
}  // namespace

SvgCanvas::SvgCanvas(double x_min, double x_max, double y_min, double y_max, double width_px,
                     double vertical_exaggeration)
    : x_min_(x_min), x_max_(x_max), y_min_(y_min), y_max_(y_max) {
  if (!(x_max_ > x_min_)) x_max_ = x_min_ + 1.0;
  if (!(y_max_ > y_min_)) y_max_ = y_min_ + 1.0;
  plot_w_ = width_px;
  scale_ = plot_w_ / (x_max_ - x_min_);
  y_scale_ = vertical_exaggeration > 0 ? scale_ * vertical_exaggeration : scale_;
  plot_h_ = y_scale_ * (y_max_ - y_min_);
}

double SvgCanvas::px(double x) const { return left_ + (x - x_min_) * scale_; }
double SvgCanvas::py(double y) const { return top_ + (y_max_ - y) * y_scale_; }

void SvgCanvas::polyline(const std::vector<slope::Point>& points, const std::string& stroke, double width,
                         const std::string& dash, const std::string& fill) {
  if (points.empty()) return;
  body_ << "<polyline fill=\"" << fill << "\" stroke=\"" << stroke << "\" stroke-width=\"" << width << "\"";
  if (!dash.empty()) body_ << " stroke-dasharray=\"" << dash << "\"";
  body_ << " stroke-linejoin=\"round\" points=\"";
  for (const auto& p : points) body_ << svg_number(px(p.x)) << ',' << svg_number(py(p.y)) << ' ';
  body_ << "\"/>\n";
}

void SvgCanvas::polygon(const std::vector<slope::Point>& points, const std::string& fill, double opacity) {
  if (points.size() < 3) return;
  body_ << "<polygon fill=\"" << fill << "\" fill-opacity=\"" << opacity << "\" stroke=\"none\" points=\"";
  for (const auto& p : points) body_ << svg_number(px(p.x)) << ',' << svg_number(py(p.y)) << ' ';
  body_ << "\"/>\n";
}

void SvgCanvas::dot(double x, double y, double radius_px, const std::string& fill) {
  body_ << "<circle cx=\"" << svg_number(px(x)) << "\" cy=\"" << svg_number(py(y)) << "\" r=\"" << svg_number(radius_px)
        << "\" fill=\"" << fill << "\"/>\n";
}

void SvgCanvas::text(double x_px, double y_px, const std::string& content, double size, const std::string& anchor,
                     const std::string& colour) {
  body_ << "<text x=\"" << svg_number(x_px) << "\" y=\"" << svg_number(y_px) << "\" font-size=\"" << size
        << "\" text-anchor=\"" << anchor << "\" fill=\"" << colour << "\">" << xml_escape(content) << "</text>\n";
}

void SvgCanvas::rect_px(double x, double y, double w, double h, const std::string& fill, const std::string& stroke) {
  body_ << "<rect x=\"" << svg_number(x) << "\" y=\"" << svg_number(y) << "\" width=\"" << svg_number(w) << "\" height=\""
        << svg_number(h) << "\" fill=\"" << fill << "\" stroke=\"" << stroke << "\"/>\n";
}

void SvgCanvas::line_px(double x0, double y0, double x1, double y1, const std::string& stroke, double width) {
  body_ << "<line x1=\"" << svg_number(x0) << "\" y1=\"" << svg_number(y0) << "\" x2=\"" << svg_number(x1) << "\" y2=\""
        << svg_number(y1) << "\" stroke=\"" << stroke << "\" stroke-width=\"" << width << "\"/>\n";
}

void SvgCanvas::axes(const std::string& x_label, const std::string& y_label) {
  const double x0 = px(x_min_), x1 = px(x_max_), y0 = py(y_min_), y1 = py(y_max_);
  rect_px(x0, y1, x1 - x0, y0 - y1, "none", "#555");
  const double step_x = nice_step(x_max_ - x_min_, 8);
  for (double v = std::ceil(x_min_ / step_x) * step_x; v <= x_max_ + 1e-9; v += step_x) {
    line_px(px(v), y0, px(v), y0 + 5, "#555");
    text(px(v), y0 + 18, svg_number(v), 11, "middle");
  }
  const double step_y = nice_step(y_max_ - y_min_, std::max(3, static_cast<int>(8 * plot_h_ / plot_w_) + 2));
  for (double v = std::ceil(y_min_ / step_y) * step_y; v <= y_max_ + 1e-9; v += step_y) {
    line_px(x0 - 5, py(v), x0, py(v), "#555");
    text(x0 - 8, py(v) + 4, svg_number(v), 11, "end");
  }
  text(0.5 * (x0 + x1), y0 + 38, x_label, 13, "middle");
  body_ << "<text x=\"18\" y=\"" << svg_number(0.5 * (y0 + y1)) << "\" font-size=\"13\" text-anchor=\"middle\" "
        << "transform=\"rotate(-90 18 " << svg_number(0.5 * (y0 + y1)) << ")\">" << xml_escape(y_label) << "</text>\n";
}

void SvgCanvas::colour_bar(double value_min, double value_max, const std::string& label) {
  const double x = px(x_max_) + 30, y_top = py(y_max_), height = std::max(120.0, py(y_min_) - y_top);
  const int bands = 64;
  for (int k = 0; k < bands; ++k) {
    const double t = 1.0 - (k + 0.5) / bands;
    rect_px(x, y_top + height * k / bands, 18, height / bands + 0.5, to_hex(colour_map(t)));
  }
  rect_px(x, y_top, 18, height, "none", "#555");
  for (int k = 0; k <= 4; ++k) {
    const double v = value_min + (value_max - value_min) * k / 4.0;
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", v);
    text(x + 24, y_top + height * (1.0 - k / 4.0) + 4, buffer, 11);
  }
  body_ << "<text x=\"" << svg_number(x + 9) << "\" y=\"" << svg_number(y_top - 10)
        << "\" font-size=\"12\" text-anchor=\"middle\">" << xml_escape(label) << "</text>\n";
}

void SvgCanvas::band_bar(const std::vector<double>& edges, const std::vector<std::string>& colours,
                         const std::string& above_colour, const std::string& label) {
  if (colours.empty() || edges.size() != colours.size() + 1) return;
  const double x = px(x_max_) + 30, y_top = py(y_max_) + 14, height = std::max(150.0, py(y_min_) - y_top);
  const double box = height / static_cast<double>(colours.size() + 1);
  rect_px(x, y_top, 18, box - 3, above_colour, "#555");
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "> %.3g", edges.back());
  text(x + 24, y_top + 0.5 * box + 2, buffer, 11);
  for (std::size_t k = 0; k < colours.size(); ++k) {
    const double y = y_top + box * static_cast<double>(colours.size() - k);
    rect_px(x, y, 18, box + 0.5, colours[k]);
  }
  rect_px(x, y_top + box, 18, height - box, "none", "#555");
  for (std::size_t k = 0; k < edges.size(); ++k) {
    std::snprintf(buffer, sizeof buffer, "%.3g", edges[k]);
    text(x + 24, y_top + box * static_cast<double>(edges.size() - k) + 4, buffer, 11);
  }
  text(x + 9, y_top - 4, label, 12, "middle");
}

void SvgCanvas::legend(const std::vector<std::tuple<std::string, std::string, std::string>>& entries) {
  legend_ = entries;
}

void SvgCanvas::title(const std::string& content) { text(left_, 24, content, 15); }

std::string SvgCanvas::str() const {
  std::ostringstream out;
  const double width = left_ + plot_w_ + right_;
  constexpr double row_height = 20.0;
  // Columns as wide as the longest label needs (about 6.8 px a character at 12 px), at least 200 px.
  std::size_t longest = 0;
  for (const auto& entry : legend_) longest = std::max(longest, std::get<2>(entry).size());
  const double column_width = std::max(200.0, 58.0 + 6.8 * static_cast<double>(longest));
  const auto columns = static_cast<std::size_t>(std::max(1.0, std::floor(plot_w_ / column_width)));
  const std::size_t rows = (legend_.size() + columns - 1) / columns;
  const double legend_top = top_ + plot_h_ + bottom_;
  const double height = legend_top + static_cast<double>(rows) * row_height + (rows > 0 ? 10.0 : 0.0);
  std::ostringstream legend;
  for (std::size_t k = 0; k < legend_.size(); ++k) {
    const auto& [colour, dash, label] = legend_[k];
    const double x = left_ + static_cast<double>(k % columns) * column_width;
    const double y = legend_top + static_cast<double>(k / columns) * row_height + 8.0;
    legend << "<line x1=\"" << svg_number(x) << "\" y1=\"" << svg_number(y) << "\" x2=\"" << svg_number(x + 30) << "\" y2=\""
           << svg_number(y) << "\" stroke=\"" << colour << "\" stroke-width=\"3\"";
    if (!dash.empty()) legend << " stroke-dasharray=\"" << dash << "\"";
    legend << "/>\n<text x=\"" << svg_number(x + 38) << "\" y=\"" << svg_number(y + 4) << "\" font-size=\"12\" fill=\"#222\">"
           << xml_escape(label) << "</text>\n";
  }
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << svg_number(width) << "\" height=\"" << svg_number(height)
      << "\" viewBox=\"0 0 " << svg_number(width) << ' ' << svg_number(height)
      << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << body_.str() << legend.str() << "</svg>\n";
  return out.str();
}

SvgCanvas time_canvas(double t_end, double lo, double hi, const std::string& title, const std::string& y_label) {
  if (!(t_end > 0)) t_end = 1.0;
  return plot_canvas(0.0, t_end, lo, hi, title, "time t (s)", y_label);
}

SvgCanvas plot_canvas(double x_lo, double x_hi, double lo, double hi, const std::string& title,
                      const std::string& x_label, const std::string& y_label) {
  constexpr double width = 700.0, height = 360.0;  // [px]
  if (!(x_hi > x_lo)) x_hi = x_lo + 1.0;
  if (!(hi > lo)) hi = lo + 1.0;
  const double pad = 0.05 * (hi - lo);
  lo -= pad;
  hi += pad;
  const double exaggeration = height / (width / (x_hi - x_lo) * (hi - lo));
  SvgCanvas canvas(x_lo, x_hi, lo, hi, width, exaggeration);
  canvas.title(title);
  canvas.axes(x_label, y_label);
  return canvas;
}

}  // namespace coupling
