// analyses.isph.snapshots_s and analyses.isph.front_reference (coupling/scene/isph_outputs.hpp).
#include "coupling/scene/isph_outputs.hpp"

#include "coupling/scene/isph_analysis.hpp"
#include "coupling/scene/tank_scene.hpp"

namespace coupling {

namespace {

constexpr SizeLimit snapshot_times_limit{100, "snapshots", "each time writes one figure of every particle"};

std::optional<FrontReference> read_front_reference(JsonReader& isph) {
  auto r = isph.object("front_reference", Need::optional,
                       "an object {data, column_width_m} and/or {ritter_dam_x_m, ritter_depth_m}");
  if (!r) return std::nullopt;
  FrontReference f;
  if (auto data = r->string("data", Need::optional)) {
    if (*data != martin_moyce_n2_2_key)
      r->diagnostics().error(r->path_of("data"), "expected \"" + std::string(martin_moyce_n2_2_key) +
                                                     "\" (the tabulated front the program holds), got \"" + *data +
                                                     "\"");
    f.data = *data;
    if (auto a = r->number("column_width_m", Need::required)) f.column_width = *a;
  } else if (r->has("column_width_m")) {
    r->diagnostics().error(r->path_of("column_width_m"), "given without \"data\" (the width scales its table)");
  }
  const bool dam = r->has("ritter_dam_x_m"), depth = r->has("ritter_depth_m");
  f.ritter_dam_x = r->number("ritter_dam_x_m", Need::optional);
  f.ritter_depth = r->number("ritter_depth_m", Need::optional);
  if (dam != depth)
    r->diagnostics().error(r->path_of(dam ? "ritter_depth_m" : "ritter_dam_x_m"),
                           "missing (Ritter's front needs both ritter_dam_x_m and ritter_depth_m)");
  if (!r->has("data") && !dam && !depth)
    r->diagnostics().error(r->path(), "names no reference (give \"data\": \"" + std::string(martin_moyce_n2_2_key) +
                                          "\" with column_width_m, or ritter_dam_x_m with ritter_depth_m)");
  r->finish();
  return f;
}

}  // namespace

IsphOutputs read_isph_outputs(JsonReader& isph) {
  IsphOutputs out;
  read_times(isph, "snapshots_s", Need::optional, std::nullopt, snapshot_times_limit, out.snapshot_times);
  out.front_reference = read_front_reference(isph);
  return out;
}

void check_isph_outputs(const IsphOutputs& outputs, const IsphAnalysis& a, const std::string& isph_path,
                        Diagnostics& diagnostics) {
  const double end = a.settings.end_time;
  for (std::size_t k = 0; k < outputs.snapshot_times.size(); ++k)
    if (outputs.snapshot_times[k] > end)
      diagnostics.error(index_path(join_path(isph_path, "snapshots_s"), k),
                        "must be at most end_time_s = " + format_number(end) + " s (got " +
                            format_number(outputs.snapshot_times[k]) + ")");
  if (!outputs.front_reference) return;
  const std::string path = join_path(isph_path, "front_reference");
  if (!a.monitors.front)
    diagnostics.error(path, "needs the front monitor (set analyses.isph.monitors.front to true): the reference is "
                            "drawn and measured against it");
  const std::optional<double>& dam = outputs.front_reference->ritter_dam_x;
  if (dam && (*dam < a.tank.x_min || *dam > a.tank.x_max))
    diagnostics.error(join_path(path, "ritter_dam_x_m"), "must lie in the tank (x " + format_number(a.tank.x_min) +
                                                             " to " + format_number(a.tank.x_max) + " m, got " +
                                                             format_number(*dam) + ")");
}

}  // namespace coupling
