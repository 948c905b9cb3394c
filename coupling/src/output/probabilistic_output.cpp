// The outputs of a probabilistic analysis (coupling/output/probabilistic_output.hpp).
#include "coupling/output/probabilistic_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "coupling/output/json_values.hpp"
#include "coupling/output/svg.hpp"
#include "coupling/scene/json_reader.hpp"

namespace coupling {

namespace {

using nlohmann::json;

// The mean and standard deviation of variable v's samples, in SI.
std::pair<double, double> sampled_moments(const ProbabilisticOutcome& o, std::size_t nv, std::size_t v) {
  const std::size_t n = nv == 0 ? 0 : o.values.size() / nv;
  if (n < 2) return {n == 1 ? o.values[v] : 0.0, 0.0};
  double mean = 0.0, m2 = 0.0;
  for (std::size_t s = 0; s < n; ++s) {
    const double x = o.values[s * nv + v], d = x - mean;
    mean += d / static_cast<double>(s + 1);
    m2 += d * (x - mean);
  }
  return {mean, std::sqrt(m2 / static_cast<double>(n - 1))};
}

json variable_report(const ProbabilisticAnalysis& a, const ProbabilisticOutcome& o, std::size_t v) {
  const ProbabilisticVariableInput& in = a.variables[v];
  const slope::RandomVariable& r = a.plan.variables[v];
  const double u = in.scene_unit;
  json out = {{"name", variable_label(in)},
              {"parameter", std::string(sphslope::name_of(random_parameter_names, in.parameter))},
              {"distribution", std::string(sphslope::name_of(distribution_names, r.distribution))},
              {"mean", r.mean / u}};
  if (!in.material.empty()) out["material"] = in.material;
  if (in.surcharge) out["surcharge"] = *in.surcharge;
  if (r.distribution == slope::Distribution::triangular) out["mode"] = r.mean / u;
  if (r.std_dev > 0.0) out["std_dev"] = r.std_dev / u;
  if (r.min) out["min"] = *r.min / u;  // (the truncation, or the range; none: unbounded)
  if (r.max) out["max"] = *r.max / u;
  const auto [mean, sd] = sampled_moments(o, a.plan.variables.size(), v);
  out["sampled_mean"] = mean / u;
  out["sampled_std_dev"] = sd / u;
  return out;
}

json correlation_report(const ProbabilisticAnalysis& a, const ProbabilisticOutcome& o, std::size_t k) {
  const slope::VariableCorrelation& c = a.plan.correlations[k];
  const std::size_t nv = a.plan.variables.size(), n = nv == 0 ? 0 : o.values.size() / nv;
  const auto [m1, s1] = sampled_moments(o, nv, c.first);
  const auto [m2, s2] = sampled_moments(o, nv, c.second);
  double cov = 0.0;
  for (std::size_t s = 0; s < n; ++s) cov += (o.values[s * nv + c.first] - m1) * (o.values[s * nv + c.second] - m2);
  const double sampled = n > 1 && s1 > 0.0 && s2 > 0.0 ? cov / static_cast<double>(n - 1) / (s1 * s2) : 0.0;
  return {{"material", a.correlations[k].material},
          {"cohesion_friction", c.coefficient},
          {"sampled_correlation", sampled}};
}

// lem.probabilistic.taylor_series: Duncan's (2000) Taylor series method about the deterministic FS.
json taylor_report(const ProbabilisticAnalysis& a, const ProbabilisticOutcome& o) {
  json changes = json::array();
  for (const auto& d : o.taylor_change) changes.push_back(optional_number(d));
  json out = {{"evaluations", 2 * a.variables.size()}, {"changes", std::move(changes)}};
  if (!o.taylor_std_dev || !o.deterministic || !(*o.taylor_std_dev > 0.0)) {
    out["std_dev_factor_of_safety"] = nullptr;
    out["std_dev_factor_of_safety_error"] = "the method failed at a variable's mean +- one standard deviation, or "
                                            "FS does not change";
    return out;
  }
  const double f = *o.deterministic, sd = *o.taylor_std_dev, v = sd / f, s2 = std::log1p(v * v);
  out["std_dev_factor_of_safety"] = sd;
  out["reliability_index_normal"] = (f - 1.0) / sd;
  out["reliability_index_lognormal"] = std::log(f / std::sqrt(1.0 + v * v)) / std::sqrt(s2);
  return out;
}

json surface_json(const ProbabilisticAnalysis& a, const ProbabilisticOutcome& o,
                  const std::vector<GivenSurface>& surfaces) {
  if (a.mode == ProbabilisticMode::given_surface) return {{"given_surface", surfaces[*a.surface].name}};
  const slope::Circle& c = o.surface.circle;
  const std::string what = a.mode == ProbabilisticMode::overall ? "the deterministic critical circle (each sample "
                                                                  "is searched for its own)"
                                                                : "the deterministic critical circle";
  return {{"what", what}, {"center_m", {c.xc, c.yc}}, {"radius_m", c.radius}};
}

}  // namespace

json sph_beside_probabilistic(const SrmResult& srm, const ProbabilisticOutcome& o) {
  json out = {{"particle_spacing_m", srm.particle_spacing_m}};
  if (!srm.bisection.bracketed) {
    out["factor_of_safety"] = nullptr;
    out["factor_of_safety_error"] = "the strength reduction found no factor of safety (see srm)";
    return out;
  }
  const double fs = srm.bisection.factor_of_safety;
  long below = 0, with = 0;
  for (const slope::SampleOutcome& s : o.samples)
    if (s.factor_of_safety) {
      ++with;
      below += *s.factor_of_safety < fs ? 1 : 0;
    }
  out["factor_of_safety"] = fs;
  out["bracket"] = {srm.bisection.lo, srm.bisection.hi};
  out["share_of_samples_below"] = with > 0 ? static_cast<double>(below) / static_cast<double>(with) : 0.0;
  out["note"] = "FS_SPH at the scene's values (the means), beside the distribution of the LE factor of safety";
  return out;
}

json probabilistic_report(const ProbabilisticAnalysis& a, const ProbabilisticOutcome& o,
                          const std::vector<GivenSurface>& surfaces, const SrmResult* srm) {
  json out = {{"method", std::string(slope::method_key(a.method))},
              {"mode", std::string(sphslope::name_of(probabilistic_mode_names, a.mode))},
              {"sampling", std::string(sphslope::name_of(sampling_names, a.plan.sampling))},
              {"samples", a.plan.samples},
              {"seed", a.plan.seed}};
  if (!o.error.empty()) {
    out["error"] = o.error;
    return out;
  }
  out["surface"] = surface_json(a, o, surfaces);
  if (o.part)
    out["part"] = {{"index", o.part->index},
                   {"parts", o.part->parts},
                   {"first_sample", o.first_sample},
                   {"samples", static_cast<long>(o.samples.size())}};
  if (!o.merged_from.empty()) out["merged_from"] = o.merged_from;
  json variables = json::array(), correlations = json::array();
  for (std::size_t v = 0; v < a.variables.size(); ++v) variables.push_back(variable_report(a, o, v));
  for (std::size_t k = 0; k < a.correlations.size(); ++k) correlations.push_back(correlation_report(a, o, k));
  out["variables"] = std::move(variables);
  out["correlations"] = std::move(correlations);
  const slope::ProbabilisticStatistics& s = o.statistics;
  out["deterministic_factor_of_safety"] = optional_number(o.deterministic);
  out["samples_with_factor"] = s.samples;
  out["failed_samples"] = s.failed_samples;
  out["mean_factor_of_safety"] = s.samples > 0 ? json(s.mean) : json(nullptr);
  out["std_dev_factor_of_safety"] = s.samples > 1 ? json(s.std_dev) : json(nullptr);
  out["min_factor_of_safety"] = s.samples > 0 ? json(s.min) : json(nullptr);
  out["max_factor_of_safety"] = s.samples > 0 ? json(s.max) : json(nullptr);
  out["samples_below_one"] = s.below_one;
  out["probability_of_failure"] = s.samples > 0 ? json(s.probability_of_failure) : json(nullptr);
  out["reliability_index_normal"] = optional_number(s.beta_normal);
  out["reliability_index_lognormal"] = optional_number(s.beta_lognormal);
  if (s.samples == 0) out["error"] = "no sample has a factor of safety (" + std::string(slope::method_key(a.method)) +
                                     " failed on every one)";
  else if (!s.beta_normal) out["reliability_index_normal_error"] = "the factors of safety do not vary";
  if (s.samples > 0 && !s.beta_lognormal)
    out["reliability_index_lognormal_error"] = s.beta_normal ? "the mean factor of safety is not > 0"
                                                             : "the factors of safety do not vary";
  json convergence = json::array();
  for (const slope::ConvergencePoint& p : s.convergence)
    convergence.push_back({{"samples", p.samples},
                           {"mean_factor_of_safety", p.mean},
                           {"std_dev_factor_of_safety", p.std_dev},
                           {"probability_of_failure", p.probability_of_failure}});
  out["convergence"] = std::move(convergence);
  out["taylor_series"] = taylor_report(a, o);
  if (srm != nullptr) out["sph_strength_reduction"] = sph_beside_probabilistic(*srm, o);
  out["samples_file"] = probabilistic_samples_file;
  out["seconds"] = o.seconds;
  return out;
}

std::string probabilistic_samples_csv(const ProbabilisticAnalysis& a, const ProbabilisticOutcome& o) {
  std::string out = "# " + std::string(slope::method_key(a.method)) + ", " +
                    std::string(sphslope::name_of(sampling_names, a.plan.sampling)) + ", seed " +
                    std::to_string(a.plan.seed) + "; the values in the scene's units\nsample";
  for (const ProbabilisticVariableInput& v : a.variables) {
    out += ',';  // (appended piece by piece: g++ 12 warns falsely, -Wrestrict, on "," + std::string inlined here)
    out += variable_label(v);
  }
  const bool overall = a.mode == ProbabilisticMode::overall;
  out += overall ? ",factor_of_safety,center_x_m,center_y_m,radius_m\n" : ",factor_of_safety\n";
  const std::size_t nv = a.variables.size();
  char number[40];
  for (std::size_t s = 0; s < o.samples.size(); ++s) {
    out += std::to_string(o.first_sample + static_cast<long>(s));
    for (std::size_t v = 0; v < nv; ++v) {
      std::snprintf(number, sizeof number, ",%.10g", o.values[s * nv + v] / a.variables[v].scene_unit);
      out += number;
    }
    const slope::SampleOutcome& r = o.samples[s];
    out += ",";
    if (r.factor_of_safety) {
      std::snprintf(number, sizeof number, "%.17g", *r.factor_of_safety);  // (exact: parts are merged from it)
      out += number;
    }
    if (overall) {
      if (r.circle) std::snprintf(number, sizeof number, ",%.6f,%.6f,%.6f", r.circle->xc, r.circle->yc, r.circle->radius);
      out += r.circle ? number : ",,,";
    }
    out += "\n";
  }
  return out;
}

std::string probabilistic_line(const ProbabilisticAnalysis& a, const ProbabilisticOutcome& o) {
  std::string head = "probabilistic (" + std::string(slope::method_key(a.method)) + ", " +
                     std::string(sphslope::name_of(probabilistic_mode_names, a.mode)) + ", " +
                     std::to_string(a.plan.samples) + " " +
                     (a.plan.sampling == slope::Sampling::monte_carlo ? "Monte Carlo" : "Latin hypercube") +
                     " samples): ";
  if (!o.error.empty()) return head + "not run: " + o.error;
  if (o.part) {
    head += "part " + std::to_string(o.part->index) + " of " + std::to_string(o.part->parts) + " (samples ";
    head += std::to_string(o.first_sample) + " to " + std::to_string(o.first_sample + static_cast<long>(o.samples.size()) - 1) + "): ";
  }
  if (!o.merged_from.empty()) head += "merged from " + std::to_string(o.merged_from.size()) + " parts: ";
  const slope::ProbabilisticStatistics& s = o.statistics;
  char text[256];
  std::snprintf(text, sizeof text, "mean FS %.3f, sd %.3f, P(FS < 1) %.3g %%", s.mean, s.std_dev,
                100.0 * s.probability_of_failure);
  head += text;
  if (s.beta_normal) {
    std::snprintf(text, sizeof text, ", beta %.3f (lognormal %.3f)", *s.beta_normal, s.beta_lognormal.value_or(NAN));
    head += text;
  }
  if (s.failed_samples > 0) {
    head += "; ";
    head += std::to_string(s.failed_samples) + " samples without a factor of safety";
  }
  return head;
}

namespace {

std::vector<double> sorted_factors(const ProbabilisticOutcome& o) {
  std::vector<double> f;
  for (const slope::SampleOutcome& s : o.samples)
    if (s.factor_of_safety) f.push_back(*s.factor_of_safety);
  std::sort(f.begin(), f.end());
  return f;
}

// FS = 1, the deterministic FS and the mean as vertical lines from lo to hi, with their legend entries.
void mark_factors(SvgCanvas& canvas, const ProbabilisticOutcome& o, double lo, double hi, double x_lo, double x_hi) {
  std::vector<std::tuple<std::string, std::string, std::string>> legend;
  const auto mark = [&](double x, const char* colour, const char* dash, const std::string& label) {
    if (!(x >= x_lo && x <= x_hi)) return;
    canvas.polyline({{x, lo}, {x, hi}}, colour, 1.6, dash);
    legend.emplace_back(colour, dash, label);
  };
  mark(1.0, "#d62728", "6,4", "FS = 1");
  if (o.deterministic) mark(*o.deterministic, "#2ca02c", "2,2", "deterministic FS " + format_number(*o.deterministic));
  mark(o.statistics.mean, "#111111", "", "mean FS " + format_number(o.statistics.mean));
  canvas.legend(legend);
}

}  // namespace

std::string probabilistic_histogram_svg(const ProbabilisticOutcome& o, const std::string& title) {
  const std::vector<double> f = sorted_factors(o);
  const double lo = f.empty() ? 0.5 : std::min(f.front(), 1.0);
  const double hi = std::max(f.empty() ? 1.5 : std::max(f.back(), 1.0), lo + 0.01);  // (every sample at FS = 1)
  const double step = nice_step(hi - lo, 30);
  const double start = std::floor(lo / step) * step;
  const std::size_t bins = static_cast<std::size_t>(std::ceil((hi - start) / step + 1e-9)) + 1;
  std::vector<double> share(bins, 0.0);
  for (double x : f) share[std::min(bins - 1, static_cast<std::size_t>((x - start) / step))] += 1.0;
  double top = 0.0;
  for (double& s : share) top = std::max(top, s = 100.0 * s / static_cast<double>(std::max<std::size_t>(1, f.size())));
  const double x_hi = start + step * static_cast<double>(bins);
  SvgCanvas canvas = plot_canvas(start, x_hi, 0.0, top, title + ": FS of " + std::to_string(f.size()) + " samples",
                                 "factor of safety", "share of the samples (%)");
  for (std::size_t b = 0; b < bins; ++b) {
    if (share[b] <= 0.0) continue;
    const double x0 = start + step * static_cast<double>(b), x1 = x0 + step;
    canvas.polygon({{x0, 0.0}, {x1, 0.0}, {x1, share[b]}, {x0, share[b]}}, x1 <= 1.0 + 1e-12 ? "#e8a0a0" : "#9ecae1");
  }
  mark_factors(canvas, o, 0.0, top, start, x_hi);
  return canvas.str();
}

std::string probabilistic_cdf_svg(const ProbabilisticOutcome& o, const std::string& title) {
  const std::vector<double> f = sorted_factors(o);
  const double lo = f.empty() ? 0.5 : std::min(f.front(), 1.0), hi = f.empty() ? 1.5 : std::max(f.back(), 1.0);
  SvgCanvas canvas = plot_canvas(lo, hi, 0.0, 100.0, title + ": the samples below each FS", "factor of safety",
                                 "samples with a lower FS (%)");
  std::vector<slope::Point> line;
  const std::size_t n = f.size(), stride = std::max<std::size_t>(1, n / 2000);
  for (std::size_t i = 0; i < n; i += stride)
    line.push_back({f[i], 100.0 * static_cast<double>(i + 1) / static_cast<double>(n)});
  if (n > 0) line.push_back({f.back(), 100.0});
  canvas.polyline(line, "#1f77b4", 1.8);
  mark_factors(canvas, o, 0.0, 100.0, lo, hi);
  return canvas.str();
}

json sensitivity_report(const SensitivityAnalysis& a, const SensitivityOutcome& o,
                        const std::vector<GivenSurface>& surfaces) {
  json out = {{"method", std::string(slope::method_key(a.method))},
              {"mode", std::string(sphslope::name_of(probabilistic_mode_names, a.mode))},
              {"points", a.points}};
  if (!o.error.empty()) {
    out["error"] = o.error;
    return out;
  }
  ProbabilisticAnalysis like;  // (for the surface's description)
  like.mode = a.mode;
  like.surface = a.surface;
  ProbabilisticOutcome where;
  where.surface = o.surface;
  out["surface"] = surface_json(like, where, surfaces);
  out["deterministic_factor_of_safety"] = optional_number(o.deterministic);
  json variables = json::array();
  for (std::size_t k = 0; k < a.variables.size(); ++k) {
    const ProbabilisticVariableInput& in = a.inputs[k];
    const double u = in.scene_unit;
    json v = {{"name", variable_label(in)},
              {"parameter", std::string(sphslope::name_of(random_parameter_names, in.parameter))},
              {"value", a.variables[k].mean / u},
              {"min", *a.variables[k].min / u},
              {"max", *a.variables[k].max / u}};
    if (!in.material.empty()) v["material"] = in.material;
    if (in.surcharge) v["surcharge"] = *in.surcharge;
    json values = json::array(), factors = json::array();
    bool failed = false;
    for (std::size_t j = 0; j < o.values[k].size(); ++j) {
      values.push_back(o.values[k][j] / u);
      factors.push_back(optional_number(o.factors[k][j]));
      failed = failed || !o.factors[k][j];
    }
    v["values"] = std::move(values);
    v["factors_of_safety"] = std::move(factors);
    if (failed) v["factors_of_safety_error"] = "null where " + std::string(slope::method_key(a.method)) + " failed";
    variables.push_back(std::move(v));
  }
  out["variables"] = std::move(variables);
  out["seconds"] = o.seconds;
  return out;
}

namespace {

// The least and largest factor of safety of a variable's sweep (nullopt when the method failed everywhere).
std::optional<std::pair<double, double>> factor_range(const std::vector<std::optional<double>>& factors) {
  std::optional<std::pair<double, double>> out;
  for (const auto& f : factors)
    if (f) out = out ? std::make_pair(std::min(out->first, *f), std::max(out->second, *f)) : std::make_pair(*f, *f);
  return out;
}

}  // namespace

std::string sensitivity_table(const SensitivityAnalysis& a, const SensitivityOutcome& o) {
  std::string text = "sensitivity (" + std::string(slope::method_key(a.method)) + ", " +
                     std::string(sphslope::name_of(probabilistic_mode_names, a.mode)) + "): ";
  if (!o.error.empty()) return text + "not run: " + o.error + "\n";
  text += "FS over each range, the others at the scene's values\n";
  char line[256];
  for (std::size_t k = 0; k < a.variables.size(); ++k) {
    const double u = a.inputs[k].scene_unit;
    const auto range = factor_range(o.factors[k]);
    std::snprintf(line, sizeof line, "  %-40s %10.4g to %-10.4g FS %s\n", variable_label(a.inputs[k]).c_str(),
                  *a.variables[k].min / u, *a.variables[k].max / u,
                  range ? (format_number(o.factors[k].front().value_or(NAN)) + " to " +
                           format_number(o.factors[k].back().value_or(NAN)) + " (" + format_number(range->first) +
                           " to " + format_number(range->second) + ")").c_str()
                        : "-");
    text += line;
  }
  return text;
}

std::string sensitivity_svg(const SensitivityAnalysis& a, const SensitivityOutcome& o, const std::string& title) {
  double lo = 1.0, hi = 1.0;
  for (const auto& factors : o.factors)
    if (const auto r = factor_range(factors)) {
      lo = std::min(lo, r->first);
      hi = std::max(hi, r->second);
    }
  SvgCanvas canvas = plot_canvas(0.0, 100.0, lo, hi, title + ": FS with one variable at a time",
                                 "place in the variable's range, min to max (%)", "factor of safety");
  static const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b",
                                  "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#d62728"};
  std::vector<std::tuple<std::string, std::string, std::string>> legend;
  canvas.polyline({{0.0, 1.0}, {100.0, 1.0}}, "#d62728", 1.2, "6,4");
  legend.emplace_back("#d62728", "6,4", "FS = 1");
  for (std::size_t k = 0; k < a.variables.size(); ++k) {
    const std::string colour = colours[k % std::size(colours)];
    const double span = *a.variables[k].max - *a.variables[k].min;
    std::vector<slope::Point> line;
    for (std::size_t j = 0; j < o.values[k].size(); ++j)
      if (o.factors[k][j]) line.push_back({100.0 * (o.values[k][j] - *a.variables[k].min) / span, *o.factors[k][j]});
    canvas.polyline(line, colour, 1.6);
    if (o.deterministic)
      canvas.dot(100.0 * (a.variables[k].mean - *a.variables[k].min) / span, *o.deterministic, 3.5, colour);
    const double u = a.inputs[k].scene_unit;
    legend.emplace_back(colour, "", variable_label(a.inputs[k]) + " " + format_number(*a.variables[k].min / u) +
                                        " to " + format_number(*a.variables[k].max / u));
  }
  canvas.legend(legend);
  return canvas.str();
}

std::vector<Polyline> sample_surface_lines(const slope::Section& section, const ProbabilisticOutcome& o,
                                           const slope::SliceOptions& slicing, std::size_t count) {
  std::vector<Polyline> lines;
  for (const slope::SampleOutcome& s : o.samples) {
    if (lines.size() >= count) break;
    if (!s.circle) continue;
    if (const auto mass = slope::slice_circle(section, *s.circle, slicing)) lines.push_back(lem_surface_polyline(*mass));
  }
  return lines;
}

}  // namespace coupling
