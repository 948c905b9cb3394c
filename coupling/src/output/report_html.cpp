// report.html (coupling/output/report_html.hpp): one printable page per run.
#include "coupling/output/report_html.hpp"
#include "coupling/output/probabilistic_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "coupling/output/report.hpp"
#include "coupling/output/svg.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

const char* const kStyle = R"(<style>
@page { size: A4 portrait; margin: 9mm; }
* { box-sizing: border-box; }
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 8.2pt; color: #222; margin: 0 auto; max-width: 192mm; }
h1 { font-size: 12.5pt; margin: 0 0 1mm 0; }
h2 { font-size: 9.5pt; margin: 2.2mm 0 1mm 0; border-bottom: 0.3mm solid #999; }
p { margin: 0.6mm 0; }
.meta { color: #555; }
.source { font-size: 7.2pt; display: -webkit-box; -webkit-line-clamp: 3; -webkit-box-orient: vertical; overflow: hidden; }
.status { font-weight: bold; padding: 0.3mm 2mm; border-radius: 1mm; color: #fff; }
.ok { background: #2e7d32; } .not_accepted { background: #ef6c00; } .failed { background: #c62828; }
table { border-collapse: collapse; margin: 0.5mm 0; }
th, td { border: 0.2mm solid #bbb; padding: 0.4mm 1.6mm; text-align: right; }
th { background: #eee; } td.l, th.l { text-align: left; }
.low { font-weight: bold; background: #fde0dd; }
.cols { display: flex; gap: 4mm; align-items: flex-start; } .cols > div { flex: 1 1 auto; }
figure { margin: 1mm 0; text-align: center; } figure svg { width: 100%; height: auto; max-height: 70mm; }
figcaption { font-size: 7.5pt; color: #555; }
ul { margin: 0.5mm 0; padding-left: 5mm; } .warn li { color: #8a4b00; }
</style>
)";

std::string esc(const std::string& s) { return xml_escape(s); }

// A number with `digits` decimals, or a dash when there is none (or it is not finite).
std::string fixed(std::optional<double> v, int digits = 3) {
  if (!v || !std::isfinite(*v)) return "&ndash;";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, *v);
  return buffer;
}

std::optional<double> seconds_of(const RunResults& r, const char* key) {
  const auto it = r.seconds.find(key);
  return it == r.seconds.end() ? std::nullopt : std::optional<double>(it->second);
}

// The factor of safety a report gives for a critical surface: its value when the method solved it.
std::optional<double> solved_factor(const slope::CriticalSurface& critical) {
  const auto& fs = critical.result.factor_of_safety;
  if (critical.mass && fs && std::isfinite(*fs)) return *fs;
  return std::nullopt;
}

template <class Record>
auto result_of(const std::optional<Record>& record) -> decltype(&*record->result) {
  return record && record->result ? &*record->result : nullptr;
}

std::string header(const Scene& scene, const RunResults& results, const RunPage& page) {
  std::ostringstream out;
  out << "<h1>" << esc(scene.name) << "</h1>\n<p class=\"meta\">Scene " << esc(scene.file.string())
      << " &middot; sphslope " << esc(std::string(program_version())) << " &middot; analyses: ";
  for (std::size_t k = 0; k < results.analyses.size(); ++k) out << (k ? ", " : "") << esc(results.analyses[k]);
  out << " &middot; run time " << fixed(seconds_of(results, "total"), 1) << " s &middot; <span class=\"status "
      << esc(page.status) << "\">" << esc(page.status) << "</span></p>\n";
  if (!scene.source.empty()) out << "<p class=\"meta source\">Source: " << esc(scene.source) << "</p>\n";
  out << "<p class=\"meta\">Every number of the run is in report.json beside this page (units in every key); "
         "forces per metre of slope width.</p>\n";
  return out.str();
}

// c' in kPa, with its increase with depth z (m) where it has one: "9.6 + 2.36 z below y = 9.14 m, at most 50".
std::string cohesion_cell(const slope::Material& m) {
  char text[160];
  if (!(m.cohesion_rate > 0.0)) {
    std::snprintf(text, sizeof text, "%.1f", m.cohesion / 1e3);
    return text;
  }
  char below[48] = "its top";
  if (m.cohesion_datum_y) std::snprintf(below, sizeof below, "y = %.2f m", *m.cohesion_datum_y);
  std::snprintf(text, sizeof text, "%.1f + %.3g z below %s", m.cohesion / 1e3, m.cohesion_rate / 1e3, below);
  std::string out = text;
  if (std::isfinite(m.cohesion_max)) {
    std::snprintf(text, sizeof text, ", at most %.1f", m.cohesion_max / 1e3);
    out += text;
  }
  return out;
}

std::string materials_table(const slope::Section& s) {
  std::ostringstream out;
  out << "<table><tr><th class=\"l\">material</th><th>&gamma; (kN/m&sup3;)</th><th>c&prime; (kPa)</th>"
         "<th>&phi;&prime; (&deg;)</th></tr>\n";
  char row[256];
  for (const slope::Material& m : s.materials) {
    char gamma[64];
    std::snprintf(gamma, sizeof gamma, "%.2f", m.unit_weight / 1e3);
    if (m.saturated_unit_weight && s.water)
      std::snprintf(gamma, sizeof gamma, "%.2f; %.2f below water", m.unit_weight / 1e3, *m.saturated_unit_weight / 1e3);
    if (m.envelope) {  // the envelope in place of c' and phi'
      std::snprintf(row, sizeof row, "<td>%s</td>", gamma);
      out << "<tr><td class=\"l\">" << esc(m.name) << "</td>" << row << "<td colspan=\"2\" class=\"l\">"
          << esc(slope::describe_envelope(*m.envelope)) << "</td></tr>\n";
      continue;
    }
    std::snprintf(row, sizeof row, "<td>%s</td><td>%s</td><td>%.1f</td></tr>\n", gamma, cohesion_cell(m).c_str(),
                  sphslope::degrees(m.friction_angle));
    out << "<tr><td class=\"l\">" << esc(m.name) << "</td>" << row;
  }
  out << "</table>\n";
  return out.str();
}

// The reinforcement elements: where they are, their capacity and how their force acts. The force each puts on a
// method's critical surface is in report.json (lem.methods.<method>.reinforcement).
std::string reinforcement_table(const slope::Section& s) {
  if (s.reinforcement.empty()) return {};
  std::ostringstream out;
  out << "<table><tr><th class=\"l\">reinforcement</th><th>head (x, y) m</th><th>tail (x, y) m</th>"
         "<th>capacity (kN)</th><th>spacing (m)</th><th class=\"l\">force</th></tr>\n";
  char cells[320];
  for (std::size_t k = 0; k < s.reinforcement.size(); ++k) {
    const slope::Reinforcement& e = s.reinforcement[k];
    const bool pile = e.type == slope::SupportType::pile;
    std::snprintf(cells, sizeof cells, "<td>(%.2f, %.2f)</td><td>(%.2f, %.2f)</td><td>%.1f%s</td><td>%.2f</td>",
                  e.head.x, e.head.y, e.tail.x, e.tail.y, (pile ? e.shear_capacity : e.tensile_capacity) / 1e3,
                  pile ? " shear" : "", e.spacing);
    out << "<tr><td class=\"l\">" << k << ": " << sphslope::name_of(slope::support_type_names, e.type) << "</td>"
        << cells << "<td class=\"l\">" << sphslope::name_of(slope::support_direction_names, e.direction) << ", "
        << sphslope::name_of(slope::support_application_names, e.application)
        << (e.application == slope::SupportApplication::passive ? " (divided by F)" : " (not divided by F)")
        << "</td></tr>\n";
  }
  out << "</table>\n";
  return out.str();
}

std::string geometry_lines(const slope::Section& s) {
  double top = s.bottom_y, low = 1e300;
  for (const slope::Point& p : s.profile_lines.front().points) {
    top = std::max(top, p.y);
    low = std::min(low, p.y);
  }
  char line[512];
  std::snprintf(line, sizeof line,
                "<p>Section x = %.2f to %.2f m; ground from %.2f to %.2f m (relief %.2f m); rigid base at y = %.2f m; "
                "%zu profile line(s).</p>\n",
                s.x_min(), s.x_max(), low, top, top - low, s.bottom_y, s.profile_lines.size());
  std::string out = line;
  std::string loads;
  if (s.water) loads += "piezometric line (" + std::to_string(s.water->piezometric_line.size()) + " points); ";
  for (const slope::Material& m : s.materials) {
    if (!(m.pore_pressure_ratio > 0.0)) continue;
    std::snprintf(line, sizeof line, "r<sub>u</sub> = %.3g in ", m.pore_pressure_ratio);
    loads += line + esc(m.name) + "; ";
  }
  for (const slope::Surcharge& q : s.surcharges) {
    if (q.pressure_end)
      std::snprintf(line, sizeof line, "surcharge %.1f to %.1f kPa on x = %.2f to %.2f m; ", q.pressure / 1e3,
                    *q.pressure_end / 1e3, q.from_x, q.to_x);
    else
      std::snprintf(line, sizeof line, "surcharge %.1f kPa on x = %.2f to %.2f m; ", q.pressure / 1e3, q.from_x,
                    q.to_x);
    loads += line;
  }
  for (const slope::LineLoad& q : s.line_loads) {
    std::snprintf(line, sizeof line, "line load (%.1f, %.1f) kN/m (x, y) at x = %.2f m; ", q.force_x / 1e3,
                  q.force_y / 1e3, q.x);
    loads += line;
  }
  if (s.seismic_coefficient != 0.0) {
    std::snprintf(line, sizeof line, "pseudo-static k<sub>h</sub> = %.3f; ", s.seismic_coefficient);
    loads += line;
  }
  if (s.vertical_seismic_coefficient != 0.0) {
    std::snprintf(line, sizeof line, "pseudo-static k<sub>v</sub> = %.3f %s; ", std::fabs(s.vertical_seismic_coefficient),
                  s.vertical_seismic_coefficient > 0.0 ? "upward" : "downward");
    loads += line;
  }
  out += "<p>Water and loads: " + (loads.empty() ? std::string("none (dry, unloaded)") : loads) + "</p>\n";
  return out;
}

std::string sph_lines(const RunResults& results) {
  std::ostringstream out;
  if (const SphStageResult* sph = result_of(results.sph)) {
    out << "<p>SPH: spacing " << fixed(sph->model.particle_spacing_m, 3) << " m, " << sph->model.soil_particles
        << " soil particles, " << fixed(sph->summary.simulated_time, 2) << " s simulated in "
        << sph->summary.total_steps << " steps (" << fixed(sph->summary.wall_seconds, 1)
        << " s wall); largest displacement " << fixed(sph->max_displacement_m, 3) << " m, energy ratio "
        << fixed(sph->energy_balance ? std::optional<double>(sph->energy_balance->ratio) : std::nullopt, 3)
        << ".</p>\n";
  }
  if (const IsphStageResult* isph = result_of(results.isph)) {
    out << "<p>ISPH (" << esc(isph->pressure_mode) << " pressure): spacing " << fixed(isph->particle_spacing, 4)
        << " m, " << isph->fluid_particles << " fluid particles, " << fixed(isph->summary.simulated_time, 3)
        << " s simulated in " << isph->summary.total_steps << " steps; front at x = " << fixed(isph->front_x, 3)
        << " m; fluid mass " << fixed(isph->fluid_mass_start, 3) << " &rarr; " << fixed(isph->fluid_mass_end, 3)
        << " kg/m; largest density error " << fixed(isph->max_density_error, 4) << ". Monitors: monitors.csv.</p>\n";
  }
  if (const MpsStageResult* mps = result_of(results.mps)) {
    out << "<p>WC-MPS: spacing " << fixed(mps->particle_spacing, 4) << " m, " << mps->moving_particles
        << " particles, " << fixed(mps->summary.simulated_time, 3) << " s simulated in " << mps->summary.total_steps
        << " steps; deposit front x = " << fixed(mps->front_end, 3) << " m, height at the left wall "
        << fixed(mps->wall_height_end, 3) << " m, largest speed at the end " << fixed(mps->max_speed_end, 4)
        << " m/s. Monitors: monitors.csv.</p>\n";
  }
  if (const CoupledStageResult* c = result_of(results.coupled)) {
    out << "<p>Soil and water in one run: spacing " << fixed(c->particle_spacing, 4) << " m, " << c->soil_particles
        << " soil and " << c->water_particles << " water particles, " << fixed(c->summary.simulated_time, 3)
        << " s simulated in " << c->summary.total_steps << " water steps (" << fixed(c->mean_substeps, 1)
        << " soil sub-steps each on average, " << fixed(c->mean_solver_iterations, 1)
        << " pressure-solver iterations); water volume " << fixed(c->water_volume_start, 4) << " &rarr; "
        << fixed(c->water_volume_end, 4) << " m&sup2;/m, " << c->water_inside_soil
        << " water particles inside the soil at the end; the soil's largest displacement "
        << fixed(c->soil_max_displacement, 4) << " m. Monitors: monitors.csv.</p>\n";
  }
  if (const SrmResult* srm = result_of(results.srm)) {
    const BisectionResult& b = srm->bisection;
    out << "<p>SPH strength reduction: FS = <b>"
        << fixed(b.bracketed ? std::optional<double>(b.factor_of_safety) : std::nullopt) << "</b> (spacing "
        << fixed(srm->particle_spacing_m, 2) << " m; LE Bishop " << fixed(srm->lem_bishop) << ").</p>\n";
  }
  return out.str();
}

std::string scene_summary(const Scene& scene, const RunResults& results) {
  std::ostringstream out;
  out << "<h2>Scene</h2>\n";
  if (scene.section) {
    out << geometry_lines(scene.section->section) << materials_table(scene.section->section)
        << reinforcement_table(scene.section->section) << sph_lines(results);
  } else {
    out << sph_lines(results);
  }
  return out.str();
}

// One column of the factor-of-safety table: a heading and the factor per method key (none: not computed).
struct FsColumn {
  std::string heading;
  std::function<std::optional<double>(const std::string&)> factor;
};

// The last entry of `list` whose method key is `key` (as the report's objects keep the last one).
template <class List, class KeyOf>
auto last_of(const List& list, const std::string& key, KeyOf key_of) -> decltype(&*list.begin()) {
  decltype(&*list.begin()) found = nullptr;
  for (const auto& item : list)
    if (key_of(item) == key) found = &item;
  return found;
}

std::string method_key_of(const slope::CriticalSurface& c) { return std::string(slope::method_key(c.method)); }

std::vector<FsColumn> fs_columns(const LemStageResult& lem, const ComparisonResult* comparison) {
  std::vector<FsColumn> columns;
  columns.push_back({"critical circle", [&lem](const std::string& k) -> std::optional<double> {
                       const slope::CriticalSurface* c = last_of(lem.search.methods, k, method_key_of);
                       return c ? solved_factor(*c) : std::nullopt;
                     }});
  if (lem.noncircular)
    columns.push_back({"non-circular search", [&lem](const std::string& k) -> std::optional<double> {
                         // a method the search leaves alone (Ordinary, defined for circles) has no entry here
                         const slope::NonCircularSurface* s =
                             last_of(lem.noncircular->methods, k, [](const slope::NonCircularSurface& n) {
                               return std::string(slope::method_key(n.method));
                             });
                         if (!s || !s->searched) return std::nullopt;
                         return solved_factor(slope::CriticalSurface{s->method, s->mass, s->result});
                       }});
  if (comparison)
    columns.push_back({"on the SPH surface", [comparison](const std::string& k) -> std::optional<double> {
                         const MethodComparison* m =
                             last_of(comparison->methods, k, [](const MethodComparison& c) { return c.method; });
                         return m ? m->factor_of_safety_on_sph_surface : std::nullopt;
                       }});
  for (std::size_t i = 0; i < lem.surfaces.size() && i < 3; ++i)
    columns.push_back({"surface &ldquo;" + esc(lem.surfaces[i].name) + "&rdquo;",
                       [&lem, i](const std::string& k) -> std::optional<double> {
                         const slope::CriticalSurface* c = last_of(lem.surfaces[i].methods, k, method_key_of);
                         return c ? solved_factor(*c) : std::nullopt;
                       }});
  return columns;
}

// The probabilistic analysis's result in a sentence (none when it was not asked for).
std::string probabilistic_paragraph(const LemStageResult& lem, const SrmResult* srm) {
  if (!lem.probabilistic || !lem.analysis.probabilistic) return "";
  const ProbabilisticAnalysis& a = *lem.analysis.probabilistic;
  const ProbabilisticOutcome& o = *lem.probabilistic;
  std::ostringstream out;
  const std::string method(slope::method_key(a.method));
  const std::string where = a.mode == ProbabilisticMode::overall        ? "each sample's own critical circle"
                            : a.mode == ProbabilisticMode::given_surface ? "the given surface \"" +
                                                                               lem.surfaces[*a.surface].name + "\""
                                                                         : "the critical circle";
  out << "<p>Probabilistic analysis (" << esc(method) << ", " << a.plan.samples << " "
      << (a.plan.sampling == slope::Sampling::monte_carlo ? "Monte Carlo" : "Latin hypercube") << " samples of "
      << a.variables.size() << " variable" << (a.variables.size() == 1 ? "" : "s") << " on " << esc(where) << "): ";
  if (!o.error.empty()) return out.str() + "not run &ndash; " + esc(o.error) + ".</p>\n";
  const slope::ProbabilisticStatistics& s = o.statistics;
  out << "mean FS <b>" << fixed(s.mean) << "</b> (deterministic " << fixed(o.deterministic) << "), standard deviation "
      << fixed(s.std_dev) << ", probability of failure <b>" << fixed(100.0 * s.probability_of_failure, 2)
      << " %</b> (" << s.below_one << " of " << s.samples << " below 1), reliability index " << fixed(s.beta_normal, 2)
      << " (lognormal " << fixed(s.beta_lognormal, 2) << ")";
  if (s.failed_samples > 0) out << "; " << s.failed_samples << " samples without a factor of safety";
  out << " (" << probabilistic_samples_file << "; figures probabilistic_histogram.svg, probabilistic_cdf.svg).";
  if (srm != nullptr && srm->bisection.bracketed) {
    const nlohmann::json beside = sph_beside_probabilistic(*srm, o);
    out << " Beside it, the SPH strength reduction at the means: <b>FS<sub>SPH</sub> = "
        << fixed(srm->bisection.factor_of_safety) << "</b>, above "
        << fixed(100.0 * beside["share_of_samples_below"].get<double>(), 1) << " % of the LE samples.";
  }
  out << "</p>\n";
  return out.str();
}

// Rapid drawdown in a sentence per given surface.
std::string drawdown_paragraph(const LemStageResult& lem) {
  if (!lem.analysis.rapid_drawdown) return "";
  std::ostringstream out;
  for (const DrawdownSurfaceResult& s : lem.rapid_drawdown) {
    const slope::DrawdownResult& r = s.result;
    out << "<p>Rapid drawdown (" << esc(std::string(slope::method_key(lem.analysis.rapid_drawdown->method)))
        << ", Duncan, Wright &amp; Wong's three stages) on &ldquo;" << esc(s.name) << "&rdquo;: ";
    if (!r.factor_of_safety) {
      out << "no factor of safety &ndash; " << esc(r.error) << ".</p>\n";
      continue;
    }
    out << "<b>FS = " << fixed(r.factor_of_safety) << "</b> after drawdown (" << fixed(r.stage1)
        << " before it; undrained " << fixed(r.stage2);
    if (r.stage3) out << ", with the drained strength where it is lower " << fixed(r.stage3);
    out << ").</p>\n";
  }
  return out.str();
}

// The sensitivity analysis in a sentence: the variables by how far FS moves over their ranges, largest first.
std::string sensitivity_paragraph(const LemStageResult& lem) {
  if (!lem.sensitivity || !lem.analysis.sensitivity) return "";
  const SensitivityAnalysis& a = *lem.analysis.sensitivity;
  const SensitivityOutcome& o = *lem.sensitivity;
  std::ostringstream out;
  out << "<p>Sensitivity (" << esc(std::string(slope::method_key(a.method))) << ", one variable at a time, the others "
      << "at the scene's values): ";
  if (!o.error.empty()) return out.str() + "not run &ndash; " + esc(o.error) + ".</p>\n";
  std::vector<std::pair<double, std::size_t>> spread;
  for (std::size_t k = 0; k < a.variables.size(); ++k) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& f : o.factors[k])
      if (f) lo = std::min(lo, *f), hi = std::max(hi, *f);
    spread.emplace_back(hi >= lo ? hi - lo : 0.0, k);
  }
  std::stable_sort(spread.begin(), spread.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  for (std::size_t i = 0; i < spread.size(); ++i) {
    const std::size_t k = spread[i].second;
    const double u = a.inputs[k].scene_unit;
    out << (i == 0 ? "" : "; ") << esc(variable_label(a.inputs[k])) << " " << format_number(*a.variables[k].min / u)
        << "&ndash;" << format_number(*a.variables[k].max / u) << ": FS " << fixed(o.factors[k].front()) << "&ndash;"
        << fixed(o.factors[k].back());
  }
  out << " (figure sensitivity.svg).</p>\n";
  return out.str();
}

std::string fs_table(const RunResults& results) {
  const LemStageResult* lem = results.lem_result();
  if (!lem || lem->analysis.methods.empty()) return "";
  std::vector<std::string> keys;
  for (slope::Method m : lem->analysis.methods) keys.emplace_back(slope::method_key(m));
  const std::vector<FsColumn> columns = fs_columns(*lem, results.comparison_result());
  std::vector<double> lowest(columns.size(), INFINITY);
  for (const std::string& key : keys)
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (const std::optional<double> f = columns[c].factor(key)) lowest[c] = std::min(lowest[c], *f);
  std::ostringstream out;
  out << "<h2>Limit equilibrium: factor of safety</h2>\n<table><tr><th class=\"l\">method</th>";
  for (const FsColumn& c : columns) out << "<th>" << c.heading << "</th>";
  out << "</tr>\n";
  for (const std::string& k : keys) {
    out << "<tr><td class=\"l\">" << esc(k) << "</td>";
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::optional<double> f = columns[c].factor(k);
      const bool low = f && *f == lowest[c];
      out << "<td" << (low ? " class=\"low\"" : "") << ">" << fixed(f) << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</table>\n<p class=\"meta\">Lowest factor in each column in bold; &ndash;: not computed (see the "
         "warnings; Ordinary is defined for circles and is not searched off them). Search: "
      << fixed(static_cast<double>(lem->search.trial_surfaces), 0) << " trial circles in "
      << fixed(lem->search.seconds, 2) << " s.</p>\n";
  if (const auto& k = lem->critical_coefficient) {
    const std::string method(slope::method_key(*lem->analysis.critical_coefficient_method));
    if (k->coefficient)
      out << "<p>Critical seismic coefficient (" << esc(method) << "): <b>k<sub>c</sub> = " << fixed(k->coefficient, 4)
          << "</b>, the horizontal k<sub>h</sub> at which the least factor of safety is 1 (FS "
          << fixed(k->factor_of_safety_without) << " without it; " << k->searches << " searches).</p>\n";
    else
      out << "<p>Critical seismic coefficient (" << esc(method) << "): none &ndash; " << esc(k->why) << ".</p>\n";
  }
  if (const auto& n = lem->newmark) {
    const AccelerationRecordInput& record = *lem->analysis.acceleration_record;
    const bool given = n->as_given.displacement >= n->reversed.displacement;
    out << "<p>Newmark's rigid-block displacement at k<sub>c</sub> under " << esc(record.file) << " (peak "
        << fixed(n->peak_acceleration, 3) << " g): <b>" << fixed(std::max(n->as_given.displacement,
                                                                            n->reversed.displacement), 3)
        << " m</b> with the record " << (given ? "as given" : "reversed") << " ("
        << fixed(std::min(n->as_given.displacement, n->reversed.displacement), 3) << " m the other way; figures "
        << "newmark_record.svg, newmark_displacement.svg).</p>\n";
  }
  const SrmResult* srm = results.srm && results.srm->result ? &*results.srm->result : nullptr;
  out << drawdown_paragraph(*lem) << probabilistic_paragraph(*lem, srm) << sensitivity_paragraph(*lem);
  return out.str();
}

std::string read_svg(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return "";
  std::stringstream text;
  text << in.rdbuf();
  std::string svg = text.str();
  if (const auto start = svg.find("<svg"); start != std::string::npos) svg.erase(0, start);
  return svg;
}

std::string figures(const std::vector<std::string>& list, const std::filesystem::path& dir) {
  if (list.empty()) return "";
  std::ostringstream out;
  out << "<h2>Figures</h2>\n";
  // Newmark's two figures side by side, smaller, and the probabilistic analysis's two with the sensitivity's spider
  // plot, so that the page still prints on one sheet
  bool pair_open = false, styled = false;
  std::string open_group;
  // the probabilistic pair and the sensitivity's plot in one row, lower still
  const bool three_variation_figures =
      std::find(list.begin(), list.end(), "figures/sensitivity.svg") != list.end() &&
      std::find(list.begin(), list.end(), "figures/probabilistic_cdf.svg") != list.end();
  for (const std::string& file : list) {
    if (file.size() < 4 || file.substr(file.size() - 4) != ".svg") continue;
    const std::string group = file.starts_with("figures/newmark_")         ? "newmark"
                              : file.starts_with("figures/probabilistic_") || file == "figures/sensitivity.svg"
                                  ? "probabilistic"
                                                                            : "";
    const bool paired = !group.empty();
    if (pair_open && group != open_group) out << "</div>\n";
    if (paired && group != open_group) {  // (its style here: the pages without a pair stay as they were)
      if (!styled)
        out << "<style>.pair > div { flex: 1 1 0; } .pair figure svg { max-height: 42mm; } .pair.short figure svg { "
               "max-height: " << (three_variation_figures ? 22 : 30) << "mm; }</style>\n";
      styled = true;
      out << (group == "probabilistic" ? "<div class=\"cols pair short\">" : "<div class=\"cols pair\">");
    }
    pair_open = paired;
    open_group = group;
    const std::string svg = read_svg(dir / file);
    out << (paired ? "<div>" : "") << "<figure>"
        << (svg.empty() ? "<p>(" + esc(file) + " could not be read)</p>" : svg) << "<figcaption>" << esc(file)
        << "</figcaption></figure>" << (paired ? "</div>" : "") << "\n";
  }
  if (pair_open) out << "</div>\n";
  return out.str();
}

std::string comparison(const RunResults& results) {
  const ComparisonResult* c = results.comparison_result();
  if (!c) return "";
  return "<h2>SPH against limit equilibrium</h2>\n<p>" + esc(c->verdict) + "</p>\n";
}

// Every warning and error of the run, each once: the run's errors, the SPH and strength reduction's warnings, the
// LE search's and the comparison's errors, and each LE method's error (by method key, in key order).
std::vector<std::string> warnings(const RunResults& results, const RunPage& page) {
  std::vector<std::string> all = page.errors;
  if (const SphStageResult* sph = result_of(results.sph)) all.insert(all.end(), sph->warnings.begin(), sph->warnings.end());
  const SrmResult* srm = result_of(results.srm);
  if (srm) all.insert(all.end(), srm->warnings.begin(), srm->warnings.end());
  const LemStageResult* lem = results.lem_result();
  if (lem && !lem->search.error.empty()) all.push_back(lem->search.error);
  if (const ComparisonResult* c = results.comparison_result(); c && !c->sph_surface_mass)
    all.push_back(c->sph_surface_for_lem_error);
  if (srm && !srm->bisection.error.empty()) all.push_back("srm: " + srm->bisection.error);
  if (results.srm && !results.srm->result) all.push_back(results.srm->error);
  if (lem) {
    std::map<std::string, std::string> errors;  // the report's lem.methods, in key order
    for (slope::Method method : lem->analysis.methods) {
      const std::string key(slope::method_key(method));
      const slope::CriticalSurface* c = last_of(lem->search.methods, key, method_key_of);
      if (!c)
        errors[key] = lem->search.error.empty() ? "the search returned no result for this method" : lem->search.error;
      else if (!solved_factor(*c))
        errors[key] = !c->result.error.empty() ? c->result.error
                                               : std::string("no admissible slip surface converged for this method");
      else
        errors.erase(key);
    }
    for (const auto& [key, error] : errors) all.push_back(key + ": " + error);
  }
  std::vector<std::string> unique;
  std::set<std::string> seen;
  for (std::string& w : all)
    if (seen.insert(w).second) unique.push_back(std::move(w));
  return unique;
}

std::string warnings_block(const RunResults& results, const RunPage& page) {
  const std::vector<std::string> list = warnings(results, page);
  std::ostringstream out;
  out << "<h2>Warnings and errors</h2>\n";
  if (list.empty()) return out.str() + "<p>None.</p>\n";
  out << "<ul class=\"warn\">";
  for (const std::string& w : list) out << "<li>" << esc(w) << "</li>";
  out << "</ul>\n";
  return out.str();
}

}  // namespace

std::string report_html(const Scene& scene, const RunResults& results, const RunPage& page,
                        const std::filesystem::path& dir) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << esc(scene.name)
      << " - sphslope report</title>\n"
      << kStyle << "</head><body>\n"
      << header(scene, results, page) << "<div class=\"cols\"><div>" << scene_summary(scene, results)
      << "</div><div>" << fs_table(results) << "</div></div>\n"
      << figures(page.figures, dir) << comparison(results) << warnings_block(results, page) << "</body></html>\n";
  return out.str();
}

}  // namespace coupling
