#pragma once
// A small SVG canvas in world coordinates (m, y up) with equal scales on both axes, for report figures.
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "slope/section.hpp"

namespace coupling {

struct Rgb {
  int r = 0, g = 0, b = 0;
};
std::string to_hex(Rgb colour);
// Text with &, <, > and " escaped for SVG/XML.
std::string xml_escape(const std::string& text);
// Perceptually ordered colour map (dark blue → green → yellow) for t in [0, 1].
Rgb colour_map(double t);
// Diverging map for factors of safety: dark red (t = 0, critical) through pale yellow to dark blue (t = 1, safe).
Rgb safety_colour_map(double t);
// "Nice" tick step (1, 2, 2.5, 5 x 10^k) giving about `target_ticks` steps over `span`.
double nice_step(double span, int target_ticks);

class SvgCanvas {
 public:
  // World window [x_min, x_max] x [y_min, y_max] drawn `width_px` wide; margins around it for axes and legend.
  // y is drawn `vertical_exaggeration` times the scale of x (1: equal scales; say so in the figure when not 1).
  SvgCanvas(double x_min, double x_max, double y_min, double y_max, double width_px = 900.0,
            double vertical_exaggeration = 1.0);

  double px(double x) const;  // world x → pixel
  double py(double y) const;  // world y → pixel (y up)
  double scale() const { return scale_; }  // pixels per metre in x

  void polyline(const std::vector<slope::Point>& points, const std::string& stroke, double width,
                const std::string& dash = "", const std::string& fill = "none");
  void polygon(const std::vector<slope::Point>& points, const std::string& fill, double opacity = 1.0);
  void dot(double x, double y, double radius_px, const std::string& fill);
  void text(double x_px, double y_px, const std::string& content, double size = 13.0,
            const std::string& anchor = "start", const std::string& colour = "#222");
  void rect_px(double x, double y, double w, double h, const std::string& fill, const std::string& stroke = "none");
  void line_px(double x0, double y0, double x1, double y1, const std::string& stroke, double width = 1.0);
  // Axes with ticks and labels in metres along the bottom and left edges of the world window.
  void axes(const std::string& x_label = "x (m)", const std::string& y_label = "y (m)");
  // Vertical colour bar at the right margin, labelled with its quantity and unit.
  void colour_bar(double value_min, double value_max, const std::string& label);
  // Discrete colour bar at the right margin: band k (colours[k]) spans edges[k]..edges[k + 1], lowest at the
  // bottom; above it one box in `above_colour` for values over the last edge; labelled with quantity and unit.
  void band_bar(const std::vector<double>& edges, const std::vector<std::string>& colours,
                const std::string& above_colour, const std::string& label);
  // Legend entries (colour, dash, label), laid out in columns below the plot.
  void legend(const std::vector<std::tuple<std::string, std::string, std::string>>& entries);
  void title(const std::string& content);

  std::string str() const;

 private:
  double x_min_, x_max_, y_min_, y_max_;
  double scale_, y_scale_;
  double left_ = 70.0, right_ = 140.0, top_ = 40.0, bottom_ = 55.0;
  double plot_w_, plot_h_;
  std::ostringstream body_;
  std::vector<std::tuple<std::string, std::string, std::string>> legend_;
};

// A plot of time [s] from 0 to t_end against a quantity from lo to hi (5 % margin), about 700 x 360 pixels, titled
// and with its axes labelled (the y label names the quantity and its unit).
SvgCanvas time_canvas(double t_end, double lo, double hi, const std::string& title, const std::string& y_label);
// The same for any quantity x from x_lo to x_hi (no margin) along the bottom.
SvgCanvas plot_canvas(double x_lo, double x_hi, double lo, double hi, const std::string& title,
                      const std::string& x_label, const std::string& y_label);

}  // namespace coupling
