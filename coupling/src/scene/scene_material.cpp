// A soil material of a scene (section.materials[i] or a particle body's): validation and conversion to SI, with the
// limit-equilibrium-only keys (r_u, cohesion with depth, strength envelopes, saturated unit weight) and the check of
// what the SPH analysis needs.
#include <algorithm>
#include <array>
#include <cmath>

#include "scene_internal.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

// The cohesion's increase with depth (already read; checked here against each other): a datum or a maximum
// without a rate is an error, as is a maximum below the cohesion at the datum or top. Fills `material` when valid.
bool read_cohesion_with_depth(JsonReader& m, const std::optional<double>& cohesion, const std::optional<double>& rate,
                              const std::optional<double>& datum, const std::optional<double>& maximum,
                              SoilMaterial& material) {
  if ((m.has("cohesion_increase_kPa_per_m") && !rate) || (m.has("cohesion_datum_y_m") && !datum) ||
      (m.has("cohesion_max_kPa") && !maximum))
    return false;
  if ((datum || maximum) && !rate) {
    m.diagnostics().error(m.path_of(datum ? "cohesion_datum_y_m" : "cohesion_max_kPa"),
                          "needs cohesion_increase_kPa_per_m (the cohesion's increase with depth, kPa/m)");
    return false;
  }
  if (maximum && cohesion && *maximum < *cohesion) {
    m.diagnostics().error(m.path_of("cohesion_max_kPa"), "must be at least cohesion_kPa = " + format_number(*cohesion) +
                                                             " (got " + format_number(*maximum) + ")");
    return false;
  }
  if (rate) material.cohesion_rate = *rate * kilo;
  material.cohesion_datum_y = datum;
  if (maximum) material.cohesion_max = *maximum * kilo;
  return true;
}

// section.materials[i].hoek_brown: sigma_ci with either GSI, m_i and D or m_b, s and a.
std::optional<slope::StrengthEnvelope> read_hoek_brown(JsonReader& hb) {
  const auto sigma_ci = hb.number("intact_strength_MPa", Need::required);
  const auto gsi = hb.number("gsi", Need::optional);
  const auto mi = hb.number("mi", Need::optional);
  const auto d = hb.number("disturbance", Need::optional);
  const auto mb = hb.number("mb", Need::optional);
  const auto s = hb.number("s", Need::optional);
  const auto a = hb.number("a", Need::optional);
  hb.finish();
  const bool by_gsi = hb.has("gsi") || hb.has("mi") || hb.has("disturbance");
  const bool by_parameters = hb.has("mb") || hb.has("s") || hb.has("a");
  if (by_gsi == by_parameters) {
    hb.diagnostics().error(hb.path(), by_gsi ? "give gsi and mi (and disturbance), or mb, s and a, not both"
                                             : "needs gsi and mi (and disturbance, default 0), or mb, s and a");
    return std::nullopt;
  }
  const std::vector<const char*> needed = by_gsi ? std::vector<const char*>{"gsi", "mi"}
                                                 : std::vector<const char*>{"mb", "s", "a"};
  for (const char* key : needed)
    if (!hb.has(key)) hb.diagnostics().error(hb.path_of(key), "required with the other Hoek-Brown parameters");
  slope::StrengthEnvelope e;
  e.kind = slope::StrengthEnvelope::Kind::hoek_brown;
  if (!sigma_ci) return std::nullopt;
  if (by_gsi) {
    if (!gsi || !mi || (hb.has("disturbance") && !d)) return std::nullopt;
    e.hoek_brown = slope::hoek_brown_from_gsi(*sigma_ci * mega, *gsi, *mi, d.value_or(0.0));
  } else {
    if (!mb || !s || !a) return std::nullopt;
    e.hoek_brown = slope::HoekBrown{*sigma_ci * mega, *mb, *s, *a};
  }
  return e;
}

// section.materials[i].power_curve: tau = a (sigma' + d)^b + c, stresses in kPa.
std::optional<slope::StrengthEnvelope> read_power_curve(JsonReader& pc) {
  const auto a = pc.number("a", Need::required);
  const auto b = pc.number("b", Need::required);
  const auto c = pc.number("c_kPa", Need::optional);
  const auto d = pc.number("d_kPa", Need::optional);
  pc.finish();
  if (!a || !b || (pc.has("c_kPa") && !c) || (pc.has("d_kPa") && !d)) return std::nullopt;
  slope::StrengthEnvelope e;
  e.kind = slope::StrengthEnvelope::Kind::power_curve;
  e.power_a = *a * std::pow(kilo, 1.0 - *b);  // kPa^(1 - b) to Pa^(1 - b)
  e.power_b = *b;
  e.power_c = c.value_or(0.0) * kilo;
  e.power_d = d.value_or(0.0) * kilo;
  return e;
}

// section.materials[i].shear_normal_kPa: [[sigma', tau], ...] in kPa, sigma' strictly increasing, tau not decreasing
// (tau >= 0: the schema).
std::optional<slope::StrengthEnvelope> read_shear_normal(const nlohmann::json& points, const std::string& path,
                                                         Diagnostics& diagnostics) {
  slope::StrengthEnvelope e;
  e.kind = slope::StrengthEnvelope::Kind::shear_normal;
  bool ok = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string point_path = index_path(path, i);
    const auto point = read_pair(points[i], point_path, diagnostics, "a point [normal_stress_kPa, shear_kPa]");
    // tau >= 0 is the schema's bound: a point it refused is not compared with its neighbours
    if (!point || diagnostics.is_invalid(index_path(point_path, 1))) {
      ok = false;
      continue;
    }
    const slope::StressPoint p{point->first * kilo, point->second * kilo};
    std::string wrong;
    if (!e.points.empty() && ok && !(p.normal > e.points.back().normal))
      wrong = "the normal stress must increase strictly from point to point";
    if (wrong.empty() && !e.points.empty() && ok && !(p.shear >= e.points.back().shear))
      wrong = "the shear strength must not decrease as the normal stress increases";
    if (!wrong.empty()) {
      diagnostics.error(point_path, wrong + " (got " + points[i].dump() + ")");
      ok = false;
    }
    e.points.push_back(p);
  }
  if (!ok) return std::nullopt;
  return e;
}

// The material's non-linear strength envelope (at most one of hoek_brown, power_curve, shear_normal_kPa). False
// when one is given but wrong.
bool read_strength_envelope(JsonReader& m, std::optional<slope::StrengthEnvelope>& out) {
  const char* given = nullptr;
  for (const char* key : {"hoek_brown", "power_curve", "shear_normal_kPa"}) {
    if (!m.has(key)) continue;
    if (given != nullptr) {
      m.diagnostics().error(m.path_of(key), std::string("a material has one strength envelope: remove ") + key +
                                                " or " + given);
      return false;
    }
    given = key;
  }
  if (given == nullptr) return true;
  const std::string key = given;
  if (key == "hoek_brown") {
    if (auto hb = m.object(key, Need::required)) out = read_hoek_brown(*hb);
  } else if (key == "power_curve") {
    if (auto pc = m.object(key, Need::required)) out = read_power_curve(*pc);
  } else if (const nlohmann::json* points =
                 m.array(key, Need::required, 2, limits::polyline_points, "an array of [normal_stress_kPa, shear_kPa]")) {
    out = read_shear_normal(*points, m.path_of(key), m.diagnostics());
  }
  return out.has_value();
}

constexpr std::array<const char*, 3> envelope_keys{"hoek_brown", "power_curve", "shear_normal_kPa"};

// The keys only a section's material may have (limit equilibrium): a strength envelope and a saturated unit weight,
// read into `material`; a body's material with them is an error (the schema's). False when one is wrong.
bool read_section_only_keys(JsonReader& m, MaterialOf owner, bool has_envelope, SoilMaterial& material) {
  constexpr const char* saturated_key = "saturated_unit_weight_kN_m3";
  if (owner == MaterialOf::body) {
    // The scene schema refuses these keys for a body, with the reason ("x-refused" in docs/scene.schema.json).
    bool ok = true;
    for (const char* key : {envelope_keys[0], envelope_keys[1], envelope_keys[2], saturated_key})
      if (m.has(key) && m.diagnostics().skip_invalid(m.path_of(key))) ok = false;
    return ok;
  }
  const bool envelope_ok = !has_envelope || read_strength_envelope(m, material.envelope);
  const auto saturated = m.number(saturated_key, Need::optional);
  if (saturated) material.saturated_unit_weight = *saturated * kilo;
  return envelope_ok && (saturated || !m.has(saturated_key));
}

// Beside an envelope: no cohesion increase with depth, and cohesion_kPa with friction_angle_deg or neither.
bool envelope_companions_ok(JsonReader& m, bool has_cohesion_rate) {
  if (has_cohesion_rate) {
    m.diagnostics().error(m.path_of("cohesion_increase_kPa_per_m"),
                          "a material with a strength envelope takes its strength from the envelope alone: remove "
                          "the cohesion's increase with depth or the envelope");
    return false;
  }
  if (m.has("cohesion_kPa") != m.has("friction_angle_deg")) {
    m.diagnostics().error(m.path_of(m.has("cohesion_kPa") ? "friction_angle_deg" : "cohesion_kPa"),
                          "give both cohesion_kPa and friction_angle_deg (the SPH soil model's Mohr-Coulomb strength "
                          "beside the envelope) or neither");
    return false;
  }
  return true;
}

}  // namespace

std::optional<SoilMaterial> read_material(JsonReader& m, MaterialOf owner) {
  SoilMaterial material;
  const bool has_envelope = std::any_of(envelope_keys.begin(), envelope_keys.end(), [&](auto k) { return m.has(k); });
  const bool section_keys_ok = read_section_only_keys(m, owner, has_envelope, material);
  const auto name = m.string("name", Need::required);
  const auto unit_weight = m.number("unit_weight_kN_m3", Need::required);
  // With an envelope, limit equilibrium does not use them; the SPH soil model needs both.
  const Need mohr_coulomb = has_envelope ? Need::optional : Need::required;
  const auto cohesion = m.number("cohesion_kPa", mohr_coulomb);
  const auto friction = m.number("friction_angle_deg", mohr_coulomb);
  const auto dilatancy = m.number("dilatancy_angle_deg", Need::optional);
  const auto youngs = m.number("youngs_modulus_MPa", Need::optional);
  const auto poisson = m.number("poisson_ratio", Need::optional);
  bool elastic = false;
  read_named(m, "constitutive_model", constitutive_model_names, elastic);
  const auto ru = m.number("pore_pressure_ratio", Need::optional);
  const auto c_rate = m.number("cohesion_increase_kPa_per_m", Need::optional);
  const auto c_datum = m.number("cohesion_datum_y_m", Need::optional);
  const auto c_max = m.number("cohesion_max_kPa", Need::optional);
  m.finish();
  if (!read_cohesion_with_depth(m, cohesion, c_rate, c_datum, c_max, material) || !section_keys_ok) return std::nullopt;
  if (has_envelope && !envelope_companions_ok(m, c_rate.has_value())) return std::nullopt;
  if (dilatancy && friction && *dilatancy > *friction) {
    m.diagnostics().error(m.path_of("dilatancy_angle_deg"),
                          "must not exceed friction_angle_deg = " + format_number(*friction) + " (got " +
                              format_number(*dilatancy) + "; 0 <= dilatancy <= friction angle)");
    return std::nullopt;
  }
  if (!name || !unit_weight || (m.has("cohesion_kPa") && !cohesion) || (m.has("friction_angle_deg") && !friction))
    return std::nullopt;
  if (!has_envelope && (!cohesion || !friction)) return std::nullopt;
  if (m.has("dilatancy_angle_deg") && !dilatancy) return std::nullopt;
  if (m.has("youngs_modulus_MPa") && !youngs) return std::nullopt;
  if (m.has("poisson_ratio") && !poisson) return std::nullopt;
  if (m.has("pore_pressure_ratio") && !ru) return std::nullopt;
  material.name = *name;
  material.unit_weight = *unit_weight * kilo;
  material.mohr_coulomb = cohesion.has_value();
  material.cohesion = cohesion.value_or(0.0) * kilo;
  material.friction_angle = sphslope::radians(friction.value_or(0.0));
  if (dilatancy) material.dilatancy_angle = sphslope::radians(*dilatancy);
  if (youngs) material.youngs_modulus = *youngs * mega;
  material.poisson_ratio = poisson;
  material.elastic = elastic;
  if (ru) material.pore_pressure_ratio = *ru;
  return material;
}

void check_materials_for_sph(const std::string& section_path, const SceneSection& section, Diagnostics& diagnostics) {
  for (std::size_t i = 0; i < section.materials.size(); ++i) {
    const SoilMaterial& m = section.materials[i];
    std::string missing;
    if (!m.mohr_coulomb) missing += "cohesion_kPa and friction_angle_deg (beside its strength envelope)";
    if (!m.youngs_modulus) missing += std::string(missing.empty() ? "" : ", ") + "youngs_modulus_MPa";
    if (!m.poisson_ratio) missing += std::string(missing.empty() ? "" : " and ") + "poisson_ratio";
    if (missing.empty()) continue;
    diagnostics.error(index_path(join_path(section_path, "materials"), i),
                      "material \"" + m.name + "\" lacks " + missing +
                          ", which the SPH analysis (analyses.sph) needs for every material (elastic constants of the "
                          "soil model; dilatancy_angle_deg is optional, default 0)");
  }
}

}  // namespace coupling
