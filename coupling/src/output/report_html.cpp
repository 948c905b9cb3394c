// report.html (coupling/output/report_html.hpp): one printable page per run.
#include "coupling/output/report_html.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "coupling/output/report.hpp"
#include "coupling/output/svg.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

using nlohmann::json;

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

std::string fixed(const json& v, int digits = 3) {
  if (!v.is_number()) return "&ndash;";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v.get<double>());
  return buffer;
}

const json& none() {
  static const json value;
  return value;
}

// The value at a path of keys, or null when any key is missing.
const json& at(const json& j, std::initializer_list<const char*> path) {
  const json* node = &j;
  for (const char* key : path) {
    if (!node->is_object() || !node->contains(key)) return none();
    node = &(*node)[key];
  }
  return *node;
}

std::string header(const Scene& scene, const json& report) {
  const std::string status = report.value("status", "ok");
  std::ostringstream out;
  out << "<h1>" << esc(scene.name) << "</h1>\n<p class=\"meta\">Scene " << esc(scene.file.string())
      << " &middot; sphslope " << esc(std::string(program_version())) << " &middot; analyses: ";
  const json& analyses = at(report, {"analyses"});
  for (std::size_t k = 0; analyses.is_array() && k < analyses.size(); ++k)
    out << (k ? ", " : "") << esc(analyses[k].get<std::string>());
  out << " &middot; run time " << fixed(at(report, {"timing_s", "total"}), 1) << " s &middot; <span class=\"status "
      << esc(status) << "\">" << esc(status) << "</span></p>\n";
  if (!scene.source.empty()) out << "<p class=\"meta source\">Source: " << esc(scene.source) << "</p>\n";
  out << "<p class=\"meta\">Every number of the run is in report.json beside this page (units in every key); "
         "forces per metre of slope width.</p>\n";
  return out.str();
}

std::string materials_table(const slope::Section& s) {
  std::ostringstream out;
  out << "<table><tr><th class=\"l\">material</th><th>&gamma; (kN/m&sup3;)</th><th>c&prime; (kPa)</th>"
         "<th>&phi;&prime; (&deg;)</th></tr>\n";
  char row[256];
  for (const slope::Material& m : s.materials) {
    std::snprintf(row, sizeof row, "<td>%.2f</td><td>%.1f</td><td>%.1f</td></tr>\n", m.unit_weight / 1e3,
                  m.cohesion / 1e3, sphslope::degrees(m.friction_angle));
    out << "<tr><td class=\"l\">" << esc(m.name) << "</td>" << row;
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
  for (const slope::Surcharge& q : s.surcharges) {
    std::snprintf(line, sizeof line, "surcharge %.1f kPa on x = %.2f to %.2f m; ", q.pressure / 1e3, q.from_x, q.to_x);
    loads += line;
  }
  if (s.seismic_coefficient != 0.0) {
    std::snprintf(line, sizeof line, "pseudo-static k<sub>h</sub> = %.3f; ", s.seismic_coefficient);
    loads += line;
  }
  out += "<p>Water and loads: " + (loads.empty() ? std::string("none (dry, unloaded)") : loads) + "</p>\n";
  return out;
}

std::string sph_lines(const json& report) {
  std::ostringstream out;
  if (const json& sph = at(report, {"sph"}); sph.is_object() && sph.contains("particles")) {
    out << "<p>SPH: spacing " << fixed(sph["particle_spacing_m"], 3) << " m, " << sph.value("soil_particles", 0)
        << " soil particles, " << fixed(sph["simulated_time_s"], 2) << " s simulated in " << sph.value("steps", 0)
        << " steps (" << fixed(sph["seconds"], 1) << " s wall); largest displacement "
        << fixed(sph["max_displacement_m"], 3) << " m, energy ratio " << fixed(at(sph, {"energy_balance", "ratio"}), 3)
        << ".</p>\n";
  }
  if (const json& isph = at(report, {"isph"}); isph.is_object() && isph.contains("steps")) {
    out << "<p>ISPH (" << esc(isph.value("pressure", "")) << " pressure): spacing " << fixed(isph["particle_spacing_m"], 4)
        << " m, " << at(isph, {"particles", "fluid"}).dump() << " fluid particles, " << fixed(isph["simulated_time_s"], 3)
        << " s simulated in " << isph.value("steps", 0) << " steps; front at x = " << fixed(isph["front_x_m"], 3)
        << " m; fluid mass " << fixed(at(isph, {"fluid_mass_kg_per_m", "start"}), 3) << " &rarr; "
        << fixed(at(isph, {"fluid_mass_kg_per_m", "end"}), 3) << " kg/m; largest density error "
        << fixed(isph["max_density_error"], 4) << ". Monitors: " << esc(at(isph, {"monitors", "file"}).dump())
        << ".</p>\n";
  }
  if (const json& mps = at(report, {"mps"}); mps.is_object() && mps.contains("steps")) {
    out << "<p>WC-MPS: spacing " << fixed(mps["particle_spacing_m"], 4) << " m, " << at(mps, {"particles", "moving"}).dump()
        << " particles, " << fixed(mps["simulated_time_s"], 3) << " s simulated in " << mps.value("steps", 0)
        << " steps; deposit front x = " << fixed(at(mps, {"deposit", "front_x_m", "end"}), 3)
        << " m, height at the left wall " << fixed(at(mps, {"deposit", "wall_height_m", "end"}), 3)
        << " m, largest speed at the end " << fixed(at(mps, {"deposit", "max_speed_end_m_s"}), 4)
        << " m/s. Monitors: " << esc(at(mps, {"monitors", "file"}).dump()) << ".</p>\n";
  }
  if (const json& srm = at(report, {"srm"}); srm.is_object() && srm.contains("factor_of_safety")) {
    out << "<p>SPH strength reduction: FS = <b>" << fixed(srm["factor_of_safety"]) << "</b> (spacing "
        << fixed(srm["particle_spacing_m"], 2) << " m; LE Bishop " << fixed(srm["lem_bishop"]) << ").</p>\n";
  }
  return out.str();
}

std::string scene_summary(const Scene& scene, const json& report) {
  std::ostringstream out;
  out << "<h2>Scene</h2>\n";
  if (scene.section) {
    out << geometry_lines(scene.section->section) << materials_table(scene.section->section) << sph_lines(report);
  } else {
    out << sph_lines(report);
  }
  return out.str();
}

// One column of the factor-of-safety table: a heading and the factor per method key.
struct FsColumn {
  std::string heading;
  std::function<const json&(const std::string&)> factor;
};

std::vector<FsColumn> fs_columns(const json& report) {
  std::vector<FsColumn> columns;
  columns.push_back({"critical circle", [&report](const std::string& k) -> const json& {
                       return at(report, {"lem", "methods", k.c_str(), "factor_of_safety"});
                     }});
  if (at(report, {"lem", "noncircular"}).is_object())
    columns.push_back({"non-circular search", [&report](const std::string& k) -> const json& {
                         // a method the search leaves alone (Ordinary, defined for circles) has no entry here
                         if (at(report, {"lem", "noncircular", "methods", k.c_str(), "searched"}) == false)
                           return none();
                         return at(report, {"lem", "noncircular", "methods", k.c_str(), "factor_of_safety"});
                       }});
  if (at(report, {"comparison", "methods"}).is_object())
    columns.push_back({"on the SPH surface", [&report](const std::string& k) -> const json& {
                         return at(report, {"comparison", "methods", k.c_str(), "factor_of_safety_on_sph_surface"});
                       }});
  const json& surfaces = at(report, {"lem", "surfaces"});
  for (std::size_t i = 0; surfaces.is_array() && i < surfaces.size() && i < 3; ++i)
    columns.push_back({"surface &ldquo;" + esc(surfaces[i].value("name", "")) + "&rdquo;",
                       [&surfaces, i](const std::string& k) -> const json& {
                         return at(surfaces[i], {"methods", k.c_str(), "factor_of_safety"});
                       }});
  return columns;
}

std::string fs_table(const json& report) {
  const json& keys = at(report, {"lem", "settings", "methods"});
  if (!keys.is_array() || keys.empty()) return "";
  const std::vector<FsColumn> columns = fs_columns(report);
  std::vector<double> lowest(columns.size(), INFINITY);
  for (const json& key : keys)
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (const json& f = columns[c].factor(key.get<std::string>()); f.is_number())
        lowest[c] = std::min(lowest[c], f.get<double>());
  std::ostringstream out;
  out << "<h2>Limit equilibrium: factor of safety</h2>\n<table><tr><th class=\"l\">method</th>";
  for (const FsColumn& c : columns) out << "<th>" << c.heading << "</th>";
  out << "</tr>\n";
  for (const json& key : keys) {
    const std::string k = key.get<std::string>();
    out << "<tr><td class=\"l\">" << esc(k) << "</td>";
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const json& f = columns[c].factor(k);
      const bool low = f.is_number() && f.get<double>() == lowest[c];
      out << "<td" << (low ? " class=\"low\"" : "") << ">" << fixed(f) << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</table>\n<p class=\"meta\">Lowest factor in each column in bold; &ndash;: not computed (see the "
         "warnings; Ordinary is defined for circles and is not searched off them). Search: "
      << fixed(at(report, {"lem", "search", "trial_surfaces"}), 0) << " trial circles in "
      << fixed(at(report, {"lem", "search", "seconds"}), 2) << " s.</p>\n";
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

std::string figures(const json& report, const std::filesystem::path& dir) {
  const json& list = at(report, {"figures"});
  if (!list.is_array() || list.empty()) return "";
  std::ostringstream out;
  out << "<h2>Figures</h2>\n";
  for (const json& name : list) {
    const std::string file = name.get<std::string>();
    if (file.size() < 4 || file.substr(file.size() - 4) != ".svg") continue;
    const std::string svg = read_svg(dir / file);
    out << "<figure>" << (svg.empty() ? "<p>(" + esc(file) + " could not be read)</p>" : svg) << "<figcaption>"
        << esc(file) << "</figcaption></figure>\n";
  }
  return out.str();
}

std::string comparison(const json& report) {
  const json& verdict = at(report, {"comparison", "verdict"});
  if (!verdict.is_string()) return "";
  return "<h2>SPH against limit equilibrium</h2>\n<p>" + esc(verdict.get<std::string>()) + "</p>\n";
}

void add_strings(const json& list, std::vector<std::string>& out) {
  for (std::size_t k = 0; list.is_array() && k < list.size(); ++k)
    if (list[k].is_string()) out.push_back(list[k].get<std::string>());
}

std::vector<std::string> warnings(const json& report) {
  std::vector<std::string> all;
  add_strings(at(report, {"errors"}), all);
  add_strings(at(report, {"sph", "warnings"}), all);
  add_strings(at(report, {"srm", "warnings"}), all);
  for (const auto& path : {std::initializer_list<const char*>{"lem", "search", "error"},
                           std::initializer_list<const char*>{"comparison", "sph_surface", "as_lem_surface", "error"},
                           std::initializer_list<const char*>{"srm", "error"}})
    if (const json& e = at(report, path); e.is_string()) all.push_back(e.get<std::string>());
  if (const json& methods = at(report, {"lem", "methods"}); methods.is_object())
    for (const auto& [key, m] : methods.items())
      if (m.contains("error") && m["error"].is_string()) all.push_back(key + ": " + m["error"].get<std::string>());
  std::vector<std::string> unique;
  std::set<std::string> seen;
  for (std::string& w : all)
    if (seen.insert(w).second) unique.push_back(std::move(w));
  return unique;
}

std::string warnings_block(const json& report) {
  const std::vector<std::string> list = warnings(report);
  std::ostringstream out;
  out << "<h2>Warnings and errors</h2>\n";
  if (list.empty()) return out.str() + "<p>None.</p>\n";
  out << "<ul class=\"warn\">";
  for (const std::string& w : list) out << "<li>" << esc(w) << "</li>";
  out << "</ul>\n";
  return out.str();
}

}  // namespace

std::string report_html(const Scene& scene, const json& report, const std::filesystem::path& dir) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << esc(scene.name)
      << " - sphslope report</title>\n"
      << kStyle << "</head><body>\n"
      << header(scene, report) << "<div class=\"cols\"><div>" << scene_summary(scene, report) << "</div><div>"
      << fs_table(report) << "</div></div>\n"
      << figures(report, dir) << comparison(report) << warnings_block(report) << "</body></html>\n";
  return out.str();
}

}  // namespace coupling
