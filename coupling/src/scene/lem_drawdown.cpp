// analyses.lem.rapid_drawdown: the water after drawdown and the K_c = 1 envelopes of the materials that do not drain
// freely, read into SI (DrawdownAnalysis, coupling/scene/scene.hpp). Keys, units and defaults: docs/scene-format.md.
#include <cmath>
#include <string>

#include "scene_internal.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

// analyses.lem.rapid_drawdown.materials[i] into out.envelopes; false after an error.
bool read_envelope(JsonReader& r, const slope::Section& section, DrawdownAnalysis& out) {
  const auto name = r.string("material", Need::required);
  const auto d = r.number("kc1_cohesion_kPa", Need::required);
  const auto psi = r.number("kc1_friction_angle_deg", Need::required);
  r.finish();
  if (!name || !d || !psi) return false;
  for (std::size_t i = 0; i < section.materials.size(); ++i) {
    if (section.materials[i].name != *name) continue;
    if (section.materials[i].envelope) {
      r.diagnostics().error(r.path_of("material"), "\"" + *name + "\" has a non-linear strength envelope: rapid "
                                                   "drawdown takes a material of c' and phi'");
      return false;
    }
    if (out.envelopes[i]) {
      r.diagnostics().error(r.path_of("material"), "\"" + *name + "\" is listed twice (once each)");
      return false;
    }
    out.envelopes[i] = slope::ConsolidatedEnvelope{*d * kilo, std::tan(sphslope::radians(*psi))};
    return true;
  }
  r.diagnostics().error(r.path_of("material"), "no material of section.materials is named \"" + *name + "\"");
  return false;
}

}  // namespace

std::optional<DrawdownAnalysis> read_drawdown(JsonReader& block, const LemAnalysis& lem, const slope::Section* section,
                                              slope::Method method) {
  DrawdownAnalysis out;
  out.method = method;
  bool ok = section != nullptr;
  std::optional<slope::Water> after;
  if (auto water = block.object("water_after", Need::required, "an object {\"piezometric_line_m\": [[x, y], ...]}"))
    if (section) after = read_other_water(*water, *section);
  if (section) out.envelopes.assign(section->materials.size(), std::nullopt);
  if (const nlohmann::json* list = block.array("materials", Need::required, 1, limits::materials,
                                               "an array of the materials that do not drain freely, e.g. "
                                               "[{\"material\": \"core\", \"kc1_cohesion_kPa\": 66, "
                                               "\"kc1_friction_angle_deg\": 18.2}]")) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      JsonReader r((*list)[i], index_path(block.path_of("materials"), i), block.diagnostics());
      if (section) ok = read_envelope(r, *section, out) && ok;
      else r.finish();
    }
  } else {
    ok = false;
  }
  block.finish();
  Diagnostics& d = block.diagnostics();
  if (section && !section->water) {
    d.error(block.path(), "rapid drawdown needs section.water: the water before drawdown");
    ok = false;
  }
  if (lem.surfaces.empty()) {
    d.error(block.path(), "rapid drawdown is analysed on the given slip surfaces: give at least one in "
                          "analyses.lem.surfaces");
    ok = false;
  }
  if (!after || !ok) return std::nullopt;
  out.water_after = *after;
  if (section && section->water) out.water_after.unit_weight = section->water->unit_weight;
  return out;
}

}  // namespace coupling
