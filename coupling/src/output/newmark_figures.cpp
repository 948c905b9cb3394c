// The figures of Newmark's displacement (coupling/output/newmark_figures.hpp).
#include "coupling/output/newmark_figures.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "coupling/output/svg.hpp"
#include "coupling/scene/json_reader.hpp"

namespace coupling {

namespace {

constexpr std::size_t drawn_stretches = 1500;

// The series (value at each sample, every `step` s) as a polyline of at most about 2 x drawn_stretches points:
// each stretch's least and largest values in their order.
std::vector<slope::Point> thinned(const std::vector<double>& values, double step, double factor) {
  std::vector<slope::Point> line;
  const std::size_t n = values.size();
  const std::size_t per = std::max<std::size_t>(1, (n + drawn_stretches - 1) / drawn_stretches);
  const auto point = [&](std::size_t i) { return slope::Point{static_cast<double>(i) * step, values[i] * factor}; };
  for (std::size_t start = 0; start < n; start += per) {
    std::size_t lo = start, hi = start;
    for (std::size_t i = start; i < std::min(n, start + per); ++i) {
      if (values[i] * factor < values[lo] * factor) lo = i;
      if (values[i] * factor > values[hi] * factor) hi = i;
    }
    line.push_back(point(std::min(lo, hi)));
    if (hi != lo) line.push_back(point(std::max(lo, hi)));
  }
  return line;
}

}  // namespace

std::string newmark_record_svg(const AccelerationRecordInput& record, double yield_coefficient,
                               const std::string& title) {
  const std::vector<double>& a = record.record.acceleration;
  const double dt = record.record.time_step;
  const double t_end = dt * static_cast<double>(a.size() - 1);
  double lo = -yield_coefficient, hi = yield_coefficient;
  for (double v : a) {
    lo = std::min(lo, v * record.scale);
    hi = std::max(hi, v * record.scale);
  }
  SvgCanvas canvas = time_canvas(t_end, lo, hi, title + ": the acceleration record and k_c",
                                 "ground acceleration (g), positive downslope");
  canvas.polyline(thinned(a, dt, record.scale), "#1f77b4", 1.0);
  canvas.polyline({{0.0, yield_coefficient}, {t_end, yield_coefficient}}, "#d62728", 1.6, "6,4");
  canvas.polyline({{0.0, -yield_coefficient}, {t_end, -yield_coefficient}}, "#9467bd", 1.6, "6,4");
  canvas.legend({{"#1f77b4", "", record.file + (record.scale != 1.0 ? " x " + format_number(record.scale) : "")},
                 {"#d62728", "6,4", "k_c = " + format_number(yield_coefficient) + ": slides downslope above"},
                 {"#9467bd", "6,4", "-k_c: the reversed record slides below"}});
  return canvas.str();
}

std::string newmark_displacement_svg(const AccelerationRecordInput& record, const NewmarkOutcome& newmark,
                                     const std::string& title) {
  const double dt = record.record.time_step;
  const double t_end = dt * static_cast<double>(record.record.acceleration.size() - 1);
  const double hi = std::max({newmark.as_given.displacement, newmark.reversed.displacement, 1e-3});
  SvgCanvas canvas = time_canvas(t_end, 0.0, hi, title + ": Newmark's rigid-block displacement at k_c",
                                 "displacement downslope (m)");
  canvas.polyline(thinned(newmark.as_given_history, dt, 1.0), "#1f77b4", 1.6);
  canvas.polyline(thinned(newmark.reversed_history, dt, 1.0), "#ff7f0e", 1.6, "6,4");
  // a mass still sliding at the record's end stops after it: its total is in the legend
  const auto total = [](const slope::NewmarkResult& r, const std::vector<double>& history) {
    const bool after = !history.empty() && r.displacement > history.back() + 1e-9;
    return format_number(r.displacement) + " m" + (after ? " (with the stop after the record's end)" : "");
  };
  canvas.legend({{"#1f77b4", "", "as given: " + total(newmark.as_given, newmark.as_given_history)},
                 {"#ff7f0e", "6,4", "reversed: " + total(newmark.reversed, newmark.reversed_history)}});
  return canvas.str();
}

}  // namespace coupling
