// The summary files of `sphslope batch`: summary.csv and junit.xml, from the rows of summary.json.
#include "coupling/output/batch_summary.hpp"

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "coupling/output/svg.hpp"

namespace coupling {

namespace fs = std::filesystem;

namespace {

std::string csv_field(const nlohmann::json& value) {
  if (value.is_null()) return "";
  if (value.is_string()) {
    std::string text = value.get<std::string>();
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
  }
  if (value.is_array() && value.size() == 2 && value[0].is_number())  // an [dx, dy] offset: its length
    return csv_field(std::hypot(value[0].get<double>(), value[1].get<double>()));
  return value.dump();
}

}  // namespace

std::string summary_csv(const nlohmann::json& rows) {
  std::set<std::string> methods;
  for (const auto& row : rows)
    for (const auto& [key, value] : row["factor_of_safety"].items()) methods.insert(key);
  std::ostringstream out;
  out << "scene,status,exit_status,seconds";
  for (const auto& m : methods) out << ",fs_" << m;
  out << ",comparison_method,entry_offset_m,exit_offset_m,mean_normal_distance_m,intersection_over_union,accepted,"
         "folder\n";
  const nlohmann::json none;
  for (const auto& row : rows) {
    out << csv_field(row["scene"]) << "," << csv_field(row["status"]) << "," << row["exit_status"].dump() << ","
        << csv_field(row["seconds"]);
    for (const auto& m : methods) out << "," << csv_field(row["factor_of_safety"].value(m, none));
    const nlohmann::json& c = row.contains("comparison") ? row["comparison"] : none;
    for (const char* key : {"method", "entry_offset_m", "exit_offset_m", "mean_normal_distance_m",
                            "intersection_over_union"})
      out << "," << (c.is_object() ? csv_field(c.value(key, none)) : std::string());
    out << "," << csv_field(row.value("accepted", none)) << "," << csv_field(row["folder"]) << "\n";
  }
  return out.str();
}

// JUnit XML: one test case per scene (the run) and one per acceptance criterion.
std::string junit_xml(const nlohmann::json& rows) {
  std::ostringstream cases;
  int tests = 0, failures = 0, errors = 0;
  double total_seconds = 0.0;
  for (const auto& row : rows) {
    const std::string scene = xml_escape(fs::path(row["scene"].get<std::string>()).stem().string());
    const double seconds = row["seconds"].get<double>();
    total_seconds += seconds;
    ++tests;
    cases << "    <testcase classname=\"" << scene << "\" name=\"run\" time=\"" << seconds << "\">\n";
    const int exit_status = row["exit_status"];
    if (exit_status == 1 || exit_status == 2) {
      ++errors;
      cases << "      <error message=\"" << xml_escape(row["status"].get<std::string>()) << "\">"
            << xml_escape(row.value("reason", "")) << "</error>\n";
    }
    cases << "    </testcase>\n";
    if (!row.contains("criteria")) continue;
    for (const auto& c : row["criteria"]) {
      ++tests;
      cases << "    <testcase classname=\"" << scene << "\" name=\""
            << xml_escape(c["method"].get<std::string>() + " " + c["criterion"].get<std::string>())
            << "\" time=\"0\">\n";
      if (!c["passed"].get<bool>()) {
        ++failures;
        const std::string measured = c["measured"].is_null() ? "not measured" : c["measured"].dump();
        cases << "      <failure message=\"" << xml_escape(measured + " against the limit " + c["limit"].dump())
              << "\">" << xml_escape(c.value("note", "")) << "</failure>\n";
      }
      cases << "    </testcase>\n";
    }
  }
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites tests=\"" << tests << "\" failures=\"" << failures
      << "\" errors=\"" << errors << "\" time=\"" << total_seconds << "\">\n  <testsuite name=\"sphslope batch\" tests=\""
      << tests << "\" failures=\"" << failures << "\" errors=\"" << errors << "\" time=\"" << total_seconds << "\">\n"
      << cases.str() << "  </testsuite>\n</testsuites>\n";
  return out.str();
}

}  // namespace coupling
