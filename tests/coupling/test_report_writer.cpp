// The JSON writer of the program's files (coupling/scene/json_text.hpp): JSON has no NaN or infinity, and a
// number that is not finite must never reach a file as a silent null (docs/reliability.md, "No NaN or infinity in
// a report").
#include <catch2/catch.hpp>

#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/scene/json_text.hpp"
#include "coupling/output/report.hpp"

namespace test_report_writer {

using Catch::Matchers::Contains;

namespace {

nlohmann::json report_with(double value) {
  nlohmann::json report = {{"format", "sphslope-report/1"}, {"status", "ok"}};
  report["lem"]["methods"]["bishop"]["factor_of_safety"] = 1.25;
  report["lem"]["methods"]["bishop"]["slices"] = nlohmann::json::array({{{"weight_kN_m", 10.0}},
                                                                       {{"weight_kN_m", value}}});
  report["lem"]["methods"]["spencer"] = {{"factor_of_safety", nullptr}, {"error", "did not converge"}};
  return report;
}

}  // namespace

TEST_CASE("report writer: a NaN or an infinity is refused with the key that holds it", "[report]") {
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
    const nlohmann::json report = report_with(bad);
    CHECK(coupling::non_finite_paths(report) ==
          std::vector<std::string>{"lem.methods.bishop.slices[1].weight_kN_m"});
    CHECK_THROWS_WITH(coupling::report_text(report), Contains("lem.methods.bishop.slices[1].weight_kN_m") &&
                                                         Contains("not finite"));
    CHECK_THROWS_AS(coupling::json_text(report), coupling::NonFiniteNumber);
  }
}

TEST_CASE("report writer: finite numbers and the documented nulls are written as they are", "[report]") {
  const nlohmann::json report = report_with(12.5);
  CHECK(coupling::non_finite_paths(report).empty());
  const std::string text = coupling::report_text(report);
  CHECK(text.back() == '\n');
  const nlohmann::json back = nlohmann::json::parse(text);
  CHECK(back == report);  // every number back bit for bit; the explained null stays null
  CHECK(back["lem"]["methods"]["spencer"]["factor_of_safety"].is_null());
}

TEST_CASE("report writer: the run's non-finite numbers become nulls named in the errors", "[report]") {
  nlohmann::json report = report_with(std::numeric_limits<double>::quiet_NaN());
  report["sph"]["final_energy_J_m"] = std::numeric_limits<double>::infinity();
  const std::vector<std::string> paths = coupling::null_non_finite_numbers(report);
  CHECK(paths == std::vector<std::string>{"lem.methods.bishop.slices[1].weight_kN_m", "sph.final_energy_J_m"});
  CHECK(report["lem"]["methods"]["bishop"]["slices"][1]["weight_kN_m"].is_null());
  CHECK(report["sph"]["final_energy_J_m"].is_null());
  CHECK(coupling::non_finite_paths(report).empty());
  CHECK_NOTHROW(coupling::report_text(report));
  // more than ten: the message names ten and counts the rest
  nlohmann::json many = nlohmann::json::array();
  for (int i = 0; i < 13; ++i) many.push_back(std::numeric_limits<double>::quiet_NaN());
  CHECK_THROWS_WITH(coupling::json_text(many), Contains("[9]") && Contains("and 3 more") && !Contains("[10]"));
}

}  // namespace test_report_writer
