// analyses.lem.probabilistic: the random variables, their correlations, the sampling plan and the surface the samples
// are analysed on, read into SI (coupling/scene/probabilistic_analysis.hpp). Keys, units and defaults:
// docs/scene-format.md.
#include <cmath>
#include <string>

#include "scene_internal.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

using sphslope::degree;

// What a parameter sets, its scene unit in SI, and the physical range its samples are kept in (SI).
struct ParameterRule {
  slope::RandomQuantity quantity;
  double unit;
  bool of_material;
  std::optional<double> lowest, highest;
  const char* range_reason;  // why, for messages
};

ParameterRule rule_of(RandomParameter p) {
  using Q = slope::RandomQuantity;
  switch (p) {
    case RandomParameter::cohesion: return {Q::cohesion, kilo, true, 0.0, {}, "a cohesion is >= 0"};
    case RandomParameter::friction_angle:
      return {Q::friction_angle, degree, true, 0.0, 89.9 * degree, "a friction angle is in [0, 89.9] deg"};
    case RandomParameter::tan_friction_angle:
      return {Q::friction_coefficient, 1.0, true, 0.0, {}, "tan(phi') is >= 0"};
    case RandomParameter::unit_weight: return {Q::unit_weight, kilo, true, 0.0, {}, "a unit weight is > 0"};
    case RandomParameter::saturated_unit_weight:
      return {Q::saturated_unit_weight, kilo, true, 0.0, {}, "a unit weight is > 0"};
    case RandomParameter::cohesion_increase:
      return {Q::cohesion_rate, kilo, true, 0.0, {}, "the cohesion's increase with depth is >= 0"};
    case RandomParameter::pore_pressure_ratio:
      return {Q::pore_pressure_ratio, 1.0, true, 0.0, 0.999, "r_u is in [0, 0.999]"};
    case RandomParameter::horizontal_seismic_coefficient:
      return {Q::seismic_coefficient, 1.0, false, 0.0, 0.999, "k_h is in [0, 0.999]"};
    case RandomParameter::water_level: return {Q::water_level, 1.0, false, {}, {}, ""};
    case RandomParameter::surcharge: return {Q::surcharge_pressure, kilo, false, 0.0, {}, "a surcharge is >= 0"};
  }
  return {Q::cohesion, 1.0, true, {}, {}, ""};
}

std::optional<std::size_t> material_index(const slope::Section& section, const std::string& name) {
  for (std::size_t i = 0; i < section.materials.size(); ++i)
    if (section.materials[i].name == name) return i;
  return std::nullopt;
}

// The deterministic value (SI) of the parameter in the section; nullopt after an error at `path`.
std::optional<double> deterministic_value(JsonReader& r, const slope::Section& section, RandomParameter p,
                                          std::size_t index) {
  const std::string path = r.path_of("parameter");
  const std::string name(sphslope::name_of(random_parameter_names, p));
  if (rule_of(p).of_material) {
    const slope::Material& m = section.materials[index];
    const bool strength = p == RandomParameter::cohesion || p == RandomParameter::friction_angle ||
                          p == RandomParameter::tan_friction_angle || p == RandomParameter::cohesion_increase;
    if (strength && m.envelope) {
      r.diagnostics().error(path, "material \"" + m.name + "\" has a strength envelope (" +
                                      envelope_key(m.envelope->kind) + "): " + name + " is not used");
      return std::nullopt;
    }
    switch (p) {
      case RandomParameter::cohesion: return m.cohesion;
      case RandomParameter::friction_angle: return m.friction_angle;
      case RandomParameter::tan_friction_angle: return std::tan(m.friction_angle);
      case RandomParameter::unit_weight: return m.unit_weight;
      case RandomParameter::saturated_unit_weight:
        if (!m.saturated_unit_weight)
          r.diagnostics().error(path, "material \"" + m.name + "\" has no saturated_unit_weight_kN_m3 to vary");
        return m.saturated_unit_weight;
      case RandomParameter::cohesion_increase: return m.cohesion_rate;
      case RandomParameter::pore_pressure_ratio:
        if (m.pore_pressure_ratio > 0.0) return m.pore_pressure_ratio;
        r.diagnostics().error(path, "material \"" + m.name + "\" has no pore_pressure_ratio (give it one > 0: the "
                                    "mean; with none its pore pressure comes from section.water)");
        return std::nullopt;
      default: break;
    }
  }
  if (p == RandomParameter::horizontal_seismic_coefficient) return section.seismic_coefficient;
  if (p == RandomParameter::water_level) {
    if (section.water) return 0.0;
    r.diagnostics().error(path, "water_level_m raises and lowers section.water's piezometric line: the section has none");
    return std::nullopt;
  }
  return section.surcharges[index].pressure;
}

// Which material (or surcharge) the variable belongs to; nullopt after an error.
std::optional<std::size_t> owner_of(JsonReader& r, const slope::Section& section, RandomParameter p,
                                    ProbabilisticVariableInput& out) {
  const auto material = r.string("material", Need::optional);
  const auto surcharge = r.integer("surcharge", Need::optional);
  Diagnostics& d = r.diagnostics();
  const std::string name(sphslope::name_of(random_parameter_names, p));
  if (rule_of(p).of_material) {
    if (!material) {
      if (!r.has("material")) d.error(r.path_of("material"), name + " is a material's: name the material");
      return std::nullopt;
    }
    const auto index = material_index(section, *material);
    if (!index) d.error(r.path_of("material"), "no material of section.materials is named \"" + *material + "\"");
    out.material = *material;
    return index;
  }
  if (material) d.error(r.path_of("material"), name + " is the section's, not a material's: leave \"material\" out");
  if (p != RandomParameter::surcharge) return material ? std::nullopt : std::optional<std::size_t>(0);
  if (!surcharge) {
    if (!r.has("surcharge")) d.error(r.path_of("surcharge"), "surcharge_kPa needs the index of the surcharge it varies");
    return std::nullopt;
  }
  if (static_cast<std::size_t>(*surcharge) >= section.surcharges.size()) {
    d.error(r.path_of("surcharge"), "section.surcharges has " + std::to_string(section.surcharges.size()) +
                                        " entries (index from 0)");
    return std::nullopt;
  }
  out.surcharge = static_cast<std::size_t>(*surcharge);
  return out.surcharge;
}

// min and max (scene units) into the variable (SI), within the parameter's physical range; false after an error.
bool read_range(JsonReader& r, const ParameterRule& rule, slope::RandomVariable& v) {
  bool ok = true;
  for (const char* key : {"min", "max"}) {
    const auto given = r.number(key, Need::optional);
    const bool is_min = key[1] == 'i';
    std::optional<double>& bound = is_min ? v.min : v.max;
    const std::optional<double>& physical = is_min ? rule.lowest : rule.highest;
    if (given) {
      bound = *given * rule.unit;
      if (physical && (is_min ? *bound < *physical : *bound > *physical)) {
        r.diagnostics().error(r.path_of(key), "must be " + std::string(is_min ? ">= " : "<= ") +
                                                  format_number(*physical / rule.unit) + " (" + rule.range_reason + ")");
        ok = false;
      }
    }
    if (!bound && physical && v.distribution == slope::Distribution::normal) bound = physical;
  }
  if (v.distribution == slope::Distribution::lognormal && v.min && *v.min <= 0.0) v.min.reset();  // (it is > 0)
  return ok;
}

// One variable; `sweep`: a range of analyses.lem.sensitivity (min and max, no distribution: taken as uniform).
std::optional<slope::RandomVariable> read_variable(JsonReader& r, const slope::Section& section,
                                                   ProbabilisticVariableInput& input, bool sweep) {
  const auto parameter = read_named_required(r, "parameter", random_parameter_names);
  slope::RandomVariable v;
  if (sweep) v.distribution = slope::Distribution::uniform;
  else read_named(r, "distribution", distribution_names, v.distribution);
  const auto std_dev = sweep ? std::nullopt : r.number("std_dev", Need::optional);
  const std::size_t faults = r.diagnostics().size();
  std::optional<std::size_t> owner;
  if (parameter) owner = owner_of(r, section, *parameter, input);
  const ParameterRule rule = parameter ? rule_of(*parameter) : ParameterRule{};
  const bool ranged = read_range(r, rule, v);
  r.finish();
  if (!parameter || !owner || !ranged || r.diagnostics().size() != faults) return std::nullopt;
  const auto mean = deterministic_value(r, section, *parameter, *owner);
  if (!mean) return std::nullopt;
  input.parameter = *parameter;
  input.scene_unit = rule.unit;
  input.lowest = rule.lowest;
  input.highest = rule.highest;
  v.quantity = rule.quantity;
  v.index = *owner;
  v.mean = *mean;
  const bool normal_family =
      v.distribution == slope::Distribution::normal || v.distribution == slope::Distribution::lognormal;
  if (normal_family && !std_dev) {
    r.diagnostics().error(r.path_of("std_dev"), "a " + std::string(sphslope::name_of(distribution_names, v.distribution)) +
                                                    " variable needs its standard deviation (in the parameter's unit)");
    return std::nullopt;
  }
  if (!normal_family && std_dev) {
    r.diagnostics().error(r.path_of("std_dev"), "a uniform or triangular variable is set by min and max, not std_dev");
    return std::nullopt;
  }
  v.std_dev = std_dev.value_or(0.0) * rule.unit;
  const std::string fault = slope::variable_error(v);
  if (!fault.empty()) {
    r.diagnostics().error(r.path(), fault + " (the mean, and a triangular variable's mode, is the scene's value: " +
                                        format_number(v.mean / rule.unit) + ")");
    return std::nullopt;
  }
  return v;
}

bool same_owner(const ProbabilisticVariableInput& a, const ProbabilisticVariableInput& b) {
  return a.parameter == b.parameter && a.material == b.material && a.surcharge == b.surcharge;
}

void read_variables(JsonReader& block, const slope::Section& section, std::vector<slope::RandomVariable>& variables,
                    std::vector<ProbabilisticVariableInput>& inputs, bool& ok, bool sweep) {
  const nlohmann::json* list = block.array("variables", Need::required, 1, limits::random_variables,
                                           sweep ? "an array of ranges, e.g. [{\"parameter\": \"cohesion_kPa\", "
                                                   "\"material\": \"clay\", \"min\": 10, \"max\": 26}]"
                                                 : "an array of random variables, e.g. [{\"parameter\": \"cohesion_kPa\", "
                                                   "\"material\": \"clay\", \"std_dev\": 3.6}]");
  if (list == nullptr) {
    ok = false;
    return;
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    JsonReader r((*list)[i], index_path(block.path_of("variables"), i), block.diagnostics());
    ProbabilisticVariableInput input;
    const auto v = read_variable(r, section, input, sweep);
    if (!v) {
      ok = false;
      continue;
    }
    for (const ProbabilisticVariableInput& earlier : inputs)
      if (same_owner(earlier, input)) {
        block.diagnostics().error(r.path(), variable_label(input) + " is listed twice (list each variable once)");
        ok = false;
      }
    variables.push_back(*v);
    inputs.push_back(std::move(input));
  }
}

// "mode" and "surface": the given surface's index into `surface` (mode given_surface); ok false after an error.
void resolve_surface(JsonReader& block, const LemAnalysis& lem, ProbabilisticMode mode,
                     const std::optional<std::string>& name, std::optional<std::size_t>& surface, bool& ok) {
  Diagnostics& d = block.diagnostics();
  if (mode == ProbabilisticMode::given_surface) {
    if (!name && !block.has("surface"))
      d.error(block.path_of("surface"), "mode \"given_surface\" needs the name of one of analyses.lem.surfaces");
    for (std::size_t i = 0; name && i < lem.surfaces.size(); ++i)
      if (lem.surfaces[i].name == *name) surface = i;
    if (name && !surface)
      d.error(block.path_of("surface"), "no surface of analyses.lem.surfaces is named \"" + *name + "\"");
    ok = ok && surface.has_value();
  } else if (name) {
    d.error(block.path_of("surface"), "a surface is named only with \"mode\": \"given_surface\"");
    ok = false;
  }
}

// The index of the material's variable of one of these parameters, if any.
std::optional<std::size_t> find_variable(const ProbabilisticAnalysis& a, const std::string& material,
                                         std::initializer_list<RandomParameter> parameters) {
  for (std::size_t i = 0; i < a.variables.size(); ++i)
    for (RandomParameter p : parameters)
      if (a.variables[i].material == material && a.variables[i].parameter == p) return i;
  return std::nullopt;
}

void read_correlations(JsonReader& block, ProbabilisticAnalysis& out, bool& ok) {
  const nlohmann::json* list = block.array("correlations", Need::optional, 0, limits::random_correlations,
                                           "an array, e.g. [{\"material\": \"clay\", \"cohesion_friction\": -0.5}]");
  if (list == nullptr) return;
  for (std::size_t i = 0; i < list->size(); ++i) {
    JsonReader r((*list)[i], index_path(block.path_of("correlations"), i), block.diagnostics());
    const auto material = r.string("material", Need::required);
    const auto rho = r.number("cohesion_friction", Need::required, Bounds::closed(-1.0, 1.0));
    r.finish();
    if (!material || !rho) {
      ok = false;
      continue;
    }
    const auto c = find_variable(out, *material, {RandomParameter::cohesion});
    const auto f = find_variable(out, *material, {RandomParameter::friction_angle, RandomParameter::tan_friction_angle});
    if (!c || !f) {
      block.diagnostics().error(r.path_of("material"), "correlating c' and phi' of \"" + *material +
                                                           "\" needs a variable of each (cohesion_kPa, and "
                                                           "friction_angle_deg or tan_friction_angle)");
      ok = false;
      continue;
    }
    for (const ProbabilisticCorrelationInput& earlier : out.correlations)
      if (earlier.material == *material) {
        block.diagnostics().error(r.path_of("material"), "\"" + *material + "\" is correlated twice (once each)");
        ok = false;
      }
    out.plan.correlations.push_back({*c, *f, *rho});
    out.correlations.push_back({*material});
  }
}

}  // namespace

std::optional<ProbabilisticAnalysis> read_probabilistic(JsonReader& block, const LemAnalysis& lem,
                                                        const slope::Section* section, slope::Method method) {
  ProbabilisticAnalysis out;
  out.method = method;
  read_named(block, "mode", probabilistic_mode_names, out.mode);
  read_named(block, "sampling", sampling_names, out.plan.sampling);
  out.plan.samples = block.integer_or("samples", out.plan.samples);
  out.plan.seed = static_cast<std::uint64_t>(block.integer_or("seed", static_cast<long>(out.plan.seed)));
  const auto surface = block.string("surface", Need::optional);
  bool ok = section != nullptr;
  if (section) read_variables(block, *section, out.plan.variables, out.variables, ok, false);
  read_correlations(block, out, ok);
  block.finish();
  resolve_surface(block, lem, out.mode, surface, out.surface, ok);
  if (!ok) return std::nullopt;
  return out;
}

std::optional<SensitivityAnalysis> read_sensitivity(JsonReader& block, const LemAnalysis& lem,
                                                    const slope::Section* section, slope::Method method) {
  SensitivityAnalysis out;
  out.method = method;
  read_named(block, "mode", probabilistic_mode_names, out.mode);
  out.points = static_cast<int>(block.integer_or("points", out.points));
  const auto surface = block.string("surface", Need::optional);
  bool ok = section != nullptr;
  if (section) read_variables(block, *section, out.variables, out.inputs, ok, true);
  block.finish();
  resolve_surface(block, lem, out.mode, surface, out.surface, ok);
  if (!ok) return std::nullopt;
  return out;
}

std::string variable_label(const ProbabilisticVariableInput& variable) {
  const std::string name(sphslope::name_of(random_parameter_names, variable.parameter));
  if (!variable.material.empty()) return variable.material + " " + name;
  if (variable.surcharge) return "surcharges[" + std::to_string(*variable.surcharge) + "] " + name;
  return name;
}

}  // namespace coupling
