// analyses.lem.probabilistic, run after the limit-equilibrium search: the surface the samples are analysed on, the
// samples, and their statistics (slope/probabilistic.hpp).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "coupling/analyses/stage.hpp"

namespace coupling {

namespace {

const slope::CriticalSurface* critical_of(const slope::SearchResult& search, slope::Method method) {
  for (const slope::CriticalSurface& c : search.methods)
    if (c.method == method && c.mass && c.result.factor_of_safety) return &c;
  return nullptr;
}

// The surface and the deterministic factor of safety; error set when the method has none.
template <class Analysis, class Outcome>
void choose_surface(const Analysis& a, const LemStageResult& lem, Outcome& out) {
  const std::string method(slope::method_key(a.method));
  if (a.mode == ProbabilisticMode::given_surface) {
    const GivenSurfaceResult& given = lem.surfaces[*a.surface];
    out.surface.kind = slope::ProbabilisticSurface::Kind::fixed_polyline;
    out.surface.polyline = lem.analysis.surfaces[*a.surface].polyline;
    for (const slope::CriticalSurface& c : given.methods)
      if (c.method == a.method) out.deterministic = c.result.factor_of_safety;
    if (!out.deterministic)
      out.error = method + " found no factor of safety on the given surface \"" + given.name + "\"";
    return;
  }
  const slope::CriticalSurface* critical = critical_of(lem.search, a.method);
  if (critical == nullptr) {
    out.error = "the search found no critical circle for " + method;
    return;
  }
  out.deterministic = critical->result.factor_of_safety;
  out.surface.circle = critical->mass->circle;
  out.surface.kind = a.mode == ProbabilisticMode::overall ? slope::ProbabilisticSurface::Kind::overall
                                                          : slope::ProbabilisticSurface::Kind::fixed_circle;
}

// The text between commas of one line of a samples file.
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields(1);
  for (char c : line) {
    if (c == ',') fields.emplace_back();
    else if (c != '\r') fields.back() += c;
  }
  return fields;
}

std::optional<double> number_in(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// One line of a part's samples file into out.samples; throws std::invalid_argument naming the file and the line.
void read_sample_line(const std::string& line, const std::string& where, const ProbabilisticAnalysis& a,
                      ProbabilisticOutcome& out, std::vector<char>& seen) {
  const std::size_t nv = a.variables.size();
  const bool overall = a.mode == ProbabilisticMode::overall;
  const std::vector<std::string> f = fields_of(line);
  if (f.size() != nv + (overall ? 5 : 2)) throw std::invalid_argument(where + ": not a line of this analysis's samples");
  const auto index = number_in(f[0]);
  const bool in_range = index && *index >= 0.0 && *index < static_cast<double>(a.plan.samples);
  const long s = in_range ? static_cast<long>(*index) : -1;
  if (!in_range || *index != static_cast<double>(s))
    throw std::invalid_argument(where + ": sample index \"" + f[0] + "\" is not one of 0 to " +
                                std::to_string(a.plan.samples - 1));
  if (seen[static_cast<std::size_t>(s)]) throw std::invalid_argument(where + ": sample " + f[0] + " is there twice");
  seen[static_cast<std::size_t>(s)] = 1;
  for (std::size_t v = 0; v < nv; ++v) {
    const double drawn = out.values[static_cast<std::size_t>(s) * nv + v] / a.variables[v].scene_unit;
    const auto given = number_in(f[1 + v]);
    if (!given || std::fabs(*given - drawn) > 1e-8 * std::max(1.0, std::fabs(drawn)))
      throw std::invalid_argument(where + ": sample " + f[0] + " was not drawn by this scene (" +
                                  variable_label(a.variables[v]) + " " + f[1 + v] + ", here " + std::to_string(drawn) +
                                  "): the parts must come from the same scene, seed and number of samples");
  }
  slope::SampleOutcome& r = out.samples[static_cast<std::size_t>(s)];
  r.factor_of_safety = number_in(f[1 + nv]);
  if (overall) {
    const auto x = number_in(f[nv + 2]), y = number_in(f[nv + 3]), radius = number_in(f[nv + 4]);
    if (x && y && radius) r.circle = slope::Circle{*x, *y, *radius};
  }
}

// Every sample's result from the parts' files; throws std::invalid_argument when one is missing or wrong.
void merge_parts(const ProbabilisticAnalysis& a, const std::vector<std::filesystem::path>& merge,
                 ProbabilisticOutcome& out) {
  out.samples.assign(static_cast<std::size_t>(a.plan.samples), {});
  std::vector<char> seen(static_cast<std::size_t>(a.plan.samples), 0);
  for (std::filesystem::path file : merge) {
    if (std::filesystem::is_directory(file)) file /= "probabilistic_samples.csv";
    std::ifstream in(file);
    if (!in) throw std::invalid_argument("--merge-samples: cannot read " + file.string() + " (a part's probabilistic_samples.csv)");
    std::string line;
    long number = 0;
    bool header = false;
    while (std::getline(in, line)) {
      ++number;
      if (line.empty() || line[0] == '#') continue;
      if (!header) {  // the column names
        header = true;
        continue;
      }
      read_sample_line(line, "--merge-samples: " + file.string() + " line " + std::to_string(number), a, out, seen);
    }
    out.merged_from.push_back(file.string());
  }
  const auto missing = std::find(seen.begin(), seen.end(), 0);
  if (missing != seen.end())
    throw std::invalid_argument("--merge-samples: the parts do not hold sample " + std::to_string(missing - seen.begin()) + " (of " +
                                std::to_string(a.plan.samples) + "): merge every part");
}

// A variable's standard deviation (uniform and triangular: of their distribution).
double standard_deviation(const slope::RandomVariable& v) {
  if (v.distribution == slope::Distribution::uniform) return (*v.max - *v.min) / std::sqrt(12.0);
  if (v.distribution == slope::Distribution::triangular) {
    const double a = *v.min, b = *v.max, c = v.mean;
    return std::sqrt((a * a + b * b + c * c - a * b - a * c - b * c) / 18.0);
  }
  return v.std_dev;
}

// The Taylor series method: 2 V factors of safety, each variable at its mean +- one standard deviation.
void taylor_series(const slope::Section& section, const LemStageResult& lem, const ProbabilisticAnalysis& a,
                   ProbabilisticOutcome& out) {
  const std::vector<slope::RandomVariable>& vars = a.plan.variables;
  const std::size_t nv = vars.size();
  std::vector<double> rows;
  for (std::size_t k = 0; k < nv; ++k)
    for (double sign : {1.0, -1.0}) {
      const double x = vars[k].mean + sign * standard_deviation(vars[k]);
      for (std::size_t i = 0; i < nv; ++i)
        rows.push_back(i != k ? vars[i].mean
                              : std::clamp(x, vars[k].min.value_or(-INFINITY), vars[k].max.value_or(INFINITY)));
    }
  const std::vector<slope::SampleOutcome> f =
      slope::evaluate_samples(section, a.plan, out.surface, a.method, lem.analysis.search, rows);
  double variance = 0.0;
  bool complete = true;
  for (std::size_t k = 0; k < nv; ++k) {
    const auto& up = f[2 * k].factor_of_safety;
    const auto& down = f[2 * k + 1].factor_of_safety;
    out.taylor_change.push_back(up && down ? std::optional<double>(*up - *down) : std::nullopt);
    if (out.taylor_change.back()) variance += 0.25 * *out.taylor_change.back() * *out.taylor_change.back();
    else complete = false;
  }
  for (const slope::VariableCorrelation& c : a.plan.correlations)
    if (out.taylor_change[c.first] && out.taylor_change[c.second])
      variance += 2.0 * c.coefficient * 0.25 * *out.taylor_change[c.first] * *out.taylor_change[c.second];
  if (complete && variance >= 0.0) out.taylor_std_dev = std::sqrt(variance);
}

}  // namespace

SensitivityOutcome run_sensitivity(const slope::Section& section, const LemStageResult& lem,
                                   const SensitivityAnalysis& a) {
  SensitivityOutcome out;
  const StageClock::time_point start = StageClock::now();
  choose_surface(a, lem, out);
  if (!out.error.empty()) return out;
  // every point of every variable one row, the other variables at the scene's values
  const std::size_t nv = a.variables.size(), points = static_cast<std::size_t>(a.points);
  std::vector<double> rows;
  out.values.assign(nv, {});
  for (std::size_t k = 0; k < nv; ++k)
    for (std::size_t j = 0; j < points; ++j) {
      const slope::RandomVariable& v = a.variables[k];
      const double x = *v.min + (*v.max - *v.min) * static_cast<double>(j) / static_cast<double>(points - 1);
      out.values[k].push_back(x);
      for (std::size_t i = 0; i < nv; ++i) rows.push_back(i == k ? x : a.variables[i].mean);
    }
  slope::SamplingPlan plan;
  plan.variables = a.variables;
  const std::vector<slope::SampleOutcome> outcomes =
      slope::evaluate_samples(section, plan, out.surface, a.method, lem.analysis.search, rows);
  out.factors.assign(nv, {});
  for (std::size_t k = 0; k < nv; ++k)
    for (std::size_t j = 0; j < points; ++j) out.factors[k].push_back(outcomes[k * points + j].factor_of_safety);
  out.seconds = seconds_since(start);
  return out;
}

ProbabilisticOutcome run_probabilistic(const slope::Section& section, const LemStageResult& lem,
                                       const ProbabilisticAnalysis& a, std::ostream* log,
                                       const std::optional<SamplePart>& part,
                                       const std::vector<std::filesystem::path>& merge) {
  ProbabilisticOutcome out;
  const StageClock::time_point start = StageClock::now();
  choose_surface(a, lem, out);
  if (!out.error.empty()) return out;
  long first = 0, count = a.plan.samples;
  if (part) {
    if (part->parts > a.plan.samples)
      throw std::invalid_argument("--sample-part: " + std::to_string(part->parts) + " parts of " +
                                  std::to_string(a.plan.samples) + " samples (at most one part a sample)");
    first = part->index * a.plan.samples / part->parts;
    count = (part->index + 1) * a.plan.samples / part->parts - first;
    out.part = part;
  }
  out.first_sample = first;
  out.values = slope::draw_samples(a.plan, first, count);
  if (!merge.empty()) {
    merge_parts(a, merge, out);
  } else {
    StageClock::time_point last = start;
    const auto progress = [&](long done) {
      if (log == nullptr || seconds_since(last) < 2.0) return;
      last = StageClock::now();
      *log << "lem probabilistic: " << done << " / " << count << " samples ("
           << static_cast<long>(seconds_since(start)) << " s)" << std::endl;
    };
    out.samples = slope::evaluate_samples(section, a.plan, out.surface, a.method, lem.analysis.search, out.values,
                                          progress);
  }
  out.statistics = slope::probabilistic_statistics(out.samples);
  taylor_series(section, lem, a, out);
  out.seconds = seconds_since(start);
  return out;
}

}  // namespace coupling
