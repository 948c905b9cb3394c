// Fixed-width text tables for the terminal.
#include "coupling/output/tables.hpp"

#include <cstdio>

namespace coupling {

std::string lem_table(const LemAnalysis& analysis, const slope::SearchResult& result) {
  std::string text;
  char line[512];
  std::snprintf(line, sizeof line, "%-27s %7s  %-19s %8s  %-17s %-17s\n", "method", "FS", "centre (x, y) m",
                "radius m", "entry (x, y) m", "exit (x, y) m");
  text += line;
  for (slope::Method method : analysis.methods) {
    const slope::CriticalSurface* found = nullptr;
    for (const slope::CriticalSurface& critical : result.methods) {
      if (critical.method == method) found = &critical;
    }
    const std::string key(slope::method_key(method));
    if (found == nullptr || !found->mass || !found->result.factor_of_safety) {
      const std::string why = found == nullptr ? result.error : found->result.error;
      std::snprintf(line, sizeof line, "%-27s %7s  %s\n", key.c_str(), "-",
                    ("failed: " + (why.empty() ? std::string("no converged surface") : why)).c_str());
      text += line;
      continue;
    }
    const slope::SlipMass& mass = *found->mass;
    char centre[64], entry[64], exit[64];
    std::snprintf(centre, sizeof centre, "(%.2f, %.2f)", mass.circle.xc, mass.circle.yc);
    std::snprintf(entry, sizeof entry, "(%.2f, %.2f)", mass.entry.x, mass.entry.y);
    std::snprintf(exit, sizeof exit, "(%.2f, %.2f)", mass.exit.x, mass.exit.y);
    std::snprintf(line, sizeof line, "%-27s %7.3f  %-19s %8.2f  %-17s %-17s\n", key.c_str(),
                  *found->result.factor_of_safety, centre, mass.circle.radius, entry, exit);
    text += line;
  }
  std::snprintf(line, sizeof line, "search: %ld trial surfaces in %.3f s\n", result.trial_surfaces, result.seconds);
  text += line;
  // No trailing blanks at the ends of the padded lines.
  std::string trimmed;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    std::string row = text.substr(start, end - start);
    row.erase(row.find_last_not_of(' ') + 1);
    trimmed += row + "\n";
    start = end + 1;
  }
  return trimmed;
}

std::string critical_coefficient_line(slope::Method method, const slope::CriticalCoefficient& k) {
  char line[512];
  if (k.coefficient)
    std::snprintf(line, sizeof line, "critical seismic coefficient (%s): k_c = %.4f (FS %.3f without k_h; %d searches "
                  "in %.2f s)\n", std::string(slope::method_key(method)).c_str(), *k.coefficient,
                  k.factor_of_safety_without, k.searches, k.seconds);
  else
    std::snprintf(line, sizeof line, "critical seismic coefficient (%s): none: %s\n",
                  std::string(slope::method_key(method)).c_str(), k.why.c_str());
  return line;
}

std::string drawdown_lines(const DrawdownAnalysis& analysis, const std::vector<DrawdownSurfaceResult>& surfaces) {
  std::string text;
  char line[512];
  for (const DrawdownSurfaceResult& s : surfaces) {
    const slope::DrawdownResult& r = s.result;
    if (!r.factor_of_safety) {
      std::snprintf(line, sizeof line, "rapid drawdown (%s, Duncan-Wright-Wong) on \"%s\": no factor of safety: %s\n",
                    std::string(slope::method_key(analysis.method)).c_str(), s.name.c_str(), r.error.c_str());
    } else {
      std::snprintf(line, sizeof line,
                    "rapid drawdown (%s, Duncan-Wright-Wong) on \"%s\": FS %.3f (before drawdown %.3f, undrained "
                    "%.3f%s)\n",
                    std::string(slope::method_key(analysis.method)).c_str(), s.name.c_str(), *r.factor_of_safety,
                    r.stage1.value_or(NAN), r.stage2.value_or(NAN),
                    r.stage3 ? (", drained where lower " + format_number(*r.stage3)).c_str() : "");
    }
    text += line;
  }
  return text;
}

std::string newmark_line(const AccelerationRecordInput& record, const NewmarkOutcome& newmark, double yield_coefficient) {
  char line[512];
  std::snprintf(line, sizeof line,
                "Newmark displacement at k_c = %.4f under %s (peak %.3f g): %.3f m as given, %.3f m reversed\n",
                yield_coefficient, record.file.c_str(), newmark.peak_acceleration, newmark.as_given.displacement,
                newmark.reversed.displacement);
  return line;
}

std::string noncircular_table(const slope::NonCircularResult& result) {
  std::string text = "non-circular search (polylines from the critical circles):\n";
  char line[512];
  for (const slope::NonCircularSurface& s : result.methods) {
    const std::string key(slope::method_key(s.method));
    if (!s.result.factor_of_safety || !s.mass) {
      std::snprintf(line, sizeof line, "  %-27s %7s  failed: ", key.c_str(), "-");
      text += line + s.result.error + "\n";
      continue;
    }
    const char* what = !s.searched ? "its critical circle (not searched: defined for circles)"
                       : s.from_circle ? "its critical circle (no lower polyline found)"
                                       : "polyline";
    std::snprintf(line, sizeof line, "  %-27s %7.3f  %s, entry (%.2f, %.2f), exit (%.2f, %.2f)\n", key.c_str(),
                  *s.result.factor_of_safety, what, s.mass->entry.x, s.mass->entry.y, s.mass->exit.x, s.mass->exit.y);
    text += line;
  }
  std::snprintf(line, sizeof line, "  %ld trial surfaces in %.3f s\n", result.trial_surfaces, result.seconds);
  return text + line;
}

std::string given_surfaces_table(const std::vector<GivenSurfaceResult>& surfaces) {
  std::string text;
  char line[512];
  for (const GivenSurfaceResult& surface : surfaces) {
    text += "given surface \"" + surface.name + "\":\n";
    for (const slope::CriticalSurface& method : surface.methods) {
      const std::string key(slope::method_key(method.method));
      if (method.result.factor_of_safety) {
        std::snprintf(line, sizeof line, "  %-27s %7.3f\n", key.c_str(), *method.result.factor_of_safety);
        text += line;
      } else {
        std::snprintf(line, sizeof line, "  %-27s %7s  failed: ", key.c_str(), "-");
        text += line + method.result.error + "\n";
      }
    }
  }
  return text;
}

}  // namespace coupling
