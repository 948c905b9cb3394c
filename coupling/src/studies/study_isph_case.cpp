// The ISPH dam break of Martin & Moyce (1952) as a reference case of `sphslope study` (study_cases.hpp): the
// run's surge front, read back from its monitors.csv, against the tabulated front.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "coupling/analyses/isph_front.hpp"
#include "coupling/scene/json_reader.hpp"
#include "study_cases.hpp"

namespace coupling::study_detail {

namespace {

constexpr const char* martin_moyce_source =
    "Martin & Moyce (1952), Phil. Trans. R. Soc. Lond. A 244:312-324, the tabulated surge front of the n^2 = 2 column "
    "(Tables 2 and 6; sph/src/fluid/reference_fronts.cpp, provenance there)";

MartinMoyceColumn column_of(const CaseSetup& setup) {
  const nlohmann::json& p = setup.parameters;
  return {p["column_width_m"].get<double>(), p["gravity_m_s2"].get<double>(), p["wall_x_m"].get<double>()};
}

}  // namespace

CaseSetup isph_dam_break_case(const Scene& scene) {
  const IsphAnalysis& a = *scene.analyses.isph;
  const std::optional<FrontReference>& ref = a.outputs.front_reference;
  if (!ref || ref->data != martin_moyce_n2_2_key)
    throw SceneError({"study: analyses.isph.front_reference: the dam-break reference needs \"data\": \"" +
                      std::string(martin_moyce_n2_2_key) + "\" with column_width_m (the table the front is measured "
                      "against) and monitors.front = true"});
  const MartinMoyceColumn column{ref->column_width, std::hypot(a.settings.gravity_x, a.settings.gravity_y),
                                 a.tank.x_min};
  const double t_needed = front_error_T_max / column.time_scale();
  if (a.settings.end_time + 1e-12 < t_needed)
    throw SceneError({"study: analyses.isph.end_time_s: the front is compared up to T = 3.33, t = " +
                      format_number(t_needed) + " s for a = " + format_number(column.a) + " m; got " +
                      format_number(a.settings.end_time) + " s"});
  CaseSetup setup;
  setup.kind = CaseKind::isph_dam_break;
  setup.kind_key = "isph_dam_break_martin_moyce";
  const std::string over = "root-mean-square over the table's points with 0.84 <= T <= 3.33 of Z_run(T) / Z - 1, "
                           "Z_run = (front_x_m - x_wall) / a from the run's monitors.csv, linear between its rows";
  setup.quantities = {
      {"front_rms_error", "RMS relative error of the surge front Z = x/a against the table, no time shift (-)",
       std::nullopt, martin_moyce_source, "Martin & Moyce (1952)", over + ", no time shift", 1.0},
      {"front_rms_error_shifted",
       "the same error with the best single time shift dT in [-0.3, 0] (the gate's opening time) (-)", std::nullopt,
       martin_moyce_source, "Martin & Moyce (1952), shifted",
       over + ", at T + dT with the dT in [-0.3, 0] (steps of 0.01) that gives the smallest", 1.0},
  };
  setup.parameters = {{"column_width_m", column.a},         {"n2", 2},
                      {"wall_x_m", column.x_wall},           {"gravity_m_s2", column.g},
                      {"T_range", {front_error_T_min, front_error_T_max}},
                      {"shift_range_T", {front_error_min_shift, 0.0}}};
  return setup;
}

std::vector<std::optional<double>> isph_dam_break_values(const CaseSetup& setup, const std::filesystem::path& folder) {
  std::vector<std::optional<double>> values(setup.quantities.size());
  std::ifstream in(folder / "monitors.csv");
  const MonitorTable monitors = parse_monitors_csv(std::string(std::istreambuf_iterator<char>(in), {}));
  if (const std::optional<FrontErrors> e = martin_moyce_front_errors(monitors, column_of(setup))) {
    values[0] = e->rms;
    values[1] = e->rms_shifted;
  }
  return values;
}

}  // namespace coupling::study_detail
