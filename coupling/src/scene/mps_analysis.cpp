// analyses.mps: settings, materials, tank, blocks and monitors of the WC-MPS (docs/scene-format.md).
#include "coupling/scene/mps_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <set>
#include <sstream>

#include "sph/mps/terms.hpp"

namespace coupling {

namespace {

constexpr SizeLimit materials_limit{100, "materials", "each block names one of them"};
constexpr SizeLimit profile_times_limit{1000, "times", "each time writes one profile of the whole tank"};

void read_numerics(JsonReader& r, sph::mps::Settings& s) {
  using Settings = sph::mps::Settings;
  if (auto v = r.number("particle_spacing_m", Need::required)) s.particle_spacing = *v;
  if (auto v = r.number("end_time_s", Need::required)) s.end_time = *v;
  s.re_over_dx = r.number_or("re_over_dx", s.re_over_dx, Bounds::closed(Settings::min_re_over_dx, Settings::max_re_over_dx));
  s.rest_density = r.number_or("rest_density_kg_m3", s.rest_density);
  s.sound_speed = r.number_or("sound_speed_m_s", s.sound_speed);
  s.surface_beta =
      r.number_or("surface_beta", s.surface_beta, Bounds::closed(Settings::min_surface_beta, Settings::max_surface_beta));
  s.viscosity_cap = r.number_or("viscosity_cap_Pa_s", s.viscosity_cap);
  s.pressure_split = r.number_or("pressure_split", s.pressure_split);
  s.cfl = r.number_or("cfl", s.cfl, Bounds{0.0, false, sph::mps::Settings::max_cfl, true});
  s.output_interval = r.number_or("output_interval_s", s.output_interval);
  read_named(r, "regularisation", sph::mps::regularisation_names, s.regularisation);
  read_named(r, "effective_pressure", sph::mps::effective_pressure_names, s.effective_pressure);
  read_named(r, "pore_pressure", sph::mps::pore_pressure_names, s.pore_pressure);
  read_named(r, "stress_divergence", sph::mps::stress_divergence_names, s.stress_divergence);
  read_named(r, "interaction_viscosity", sph::mps::interaction_viscosity_names, s.interaction_viscosity);
}

// One material: {name, type: "granular", consistency_Pa_sN, flow_index, regularisation_growth_s,
// friction_angle_deg, cohesion_kPa} or {name, type: "water", viscosity_Pa_s}.
MpsMaterial read_mps_material(JsonReader& m) {
  MpsMaterial out;
  out.name = m.string("name", Need::required).value_or("");
  const auto type = read_named_required(m, "type", sph::mps::material_type_names);
  if (type == sph::mps::Material::Type::water) {
    out.material = sph::mps::Material::water(m.number_or("viscosity_Pa_s", 1.0e-3));
  } else if (type == sph::mps::Material::Type::granular) {
    sph::mps::HerschelBulkley hb;
    hb.consistency = m.number_or("consistency_Pa_sN", hb.consistency);
    hb.flow_index = m.number_or("flow_index", hb.flow_index);
    hb.growth = m.number_or("regularisation_growth_s", hb.growth);
    hb.friction_angle_deg = m.number_or("friction_angle_deg", hb.friction_angle_deg);
    hb.cohesion = 1.0e3 * m.number_or("cohesion_kPa", 0.0);
    out.material = sph::mps::Material::granular_material(hb);
    out.material.grain_volume_fraction =
        m.number_or("grain_volume_fraction", out.material.grain_volume_fraction);
  } else {
    // without a known type the other keys cannot be checked: one error, not one per key
    for (const char* key : {"viscosity_Pa_s", "consistency_Pa_sN", "flow_index", "regularisation_growth_s",
                            "friction_angle_deg", "cohesion_kPa", "grain_volume_fraction"})
      m.allow(key);
  }
  out.material.density = m.number_or("density_kg_m3", 0.0);  // 0: rest_density_kg_m3
  return out;
}

void read_mps_materials(JsonReader& r, std::vector<MpsMaterial>& materials) {
  const nlohmann::json* list = r.array("materials", Need::required, 1, materials_limit, "an array of materials");
  if (!list) return;
  std::set<std::string> names;
  for (std::size_t k = 0; k < list->size(); ++k) {
    JsonReader m((*list)[k], index_path(r.path_of("materials"), k), r.diagnostics());
    MpsMaterial material = read_mps_material(m);
    if (!material.name.empty() && !names.insert(material.name).second)
      m.diagnostics().error(m.path_of("name"), "used twice (each material needs its own name)");
    materials.push_back(std::move(material));
    m.finish();
  }
}

// The block's "material": one of the names in materials.
void read_block_material(JsonReader& b, const std::vector<MpsMaterial>& materials, MpsAnalysis& a) {
  const auto name = b.string("material", Need::required);
  std::string known;
  for (std::size_t k = 0; k < materials.size(); ++k) {
    if (name && materials[k].name == *name) {
      a.block_material.push_back(static_cast<std::uint16_t>(k));
      return;
    }
    known += (k ? ", " : "") + materials[k].name;
  }
  a.block_material.push_back(0);
  if (name) b.diagnostics().error(b.path_of("material"), "unknown material \"" + *name + "\" (known: " + known + ")");
}

// The gate at x (ceil(r_e/dx) spacings thick, from x to the right) inside the tank and clear of every block; the
// fault at analyses.mps.gate.x_m when it is not.
bool gate_fits(const MpsAnalysis& a, double x, Diagnostics& diagnostics) {
  const std::string path = "analyses.mps.gate.x_m";
  const double thickness = sph::mps::gate_thickness(a.settings);
  const double x_max = x + thickness;
  if (x < a.tank.x_min || x_max > a.tank.x_max) {
    diagnostics.error(path, "the gate (" + format_number(thickness) +
                                " m thick, ceil(r_e/dx) spacings, from x_m to the right) must lie inside the tank: x_m "
                                "from " +
                                format_number(a.tank.x_min) + " to " + format_number(a.tank.x_max - thickness) + " m");
    return false;
  }
  for (std::size_t k = 0; k < a.blocks.size(); ++k)
    if (a.blocks[k].x_max > x + 1e-9 && a.blocks[k].x_min < x_max - 1e-9) {
      diagnostics.error(path, "the gate from " + format_number(x) + " to " + format_number(x_max) +
                                  " m overlaps blocks[" + std::to_string(k) +
                                  "]; put it at a block's face (its thickness is ceil(r_e/dx) spacings)");
      return false;
    }
  return true;
}

// analyses.mps.gate {x_m, lift_speed_m_s}: a gate of the tank's height and r_e thick from x_m to the right, inside
// the tank and clear of every block, lifted from t = 0 at the speed until it has risen the tank's height.
void read_gate(JsonReader& mps, MpsAnalysis& a) {
  auto g = mps.object("gate", Need::optional, "an object {x_m, lift_speed_m_s}");
  if (!g) return;
  const auto x = g->number("x_m", Need::required);
  const auto speed = g->number("lift_speed_m_s", Need::required);
  g->finish();
  if (!x || !speed || !gate_fits(a, *x, g->diagnostics())) return;
  a.gate_x = *x;
  a.settings.gate_lift_speed = *speed;
  a.settings.gate_lift_distance = a.tank.height;
}

// analyses.mps.profiles {times_s, dam_x_m}: the profile times inside (0, end_time_s], and the dam inside the tank.
void read_profiles(JsonReader& mps, MpsAnalysis& a) {
  auto pr = mps.object("profiles", Need::optional, "an object {times_s, dam_x_m}");
  if (!pr) return;
  read_times(*pr, "times_s", Need::required, a.settings.end_time, profile_times_limit, a.profile_times);
  if (auto x = pr->number("dam_x_m", Need::optional, Bounds::open(a.tank.x_min, a.tank.x_max))) a.dam_x = *x;
  pr->finish();
}

// pore_pressure "hydrostatic" takes the pore water's density from a water material.
void check_pore_water(JsonReader& mps, const MpsAnalysis& a) {
  if (a.settings.pore_pressure != sph::mps::PorePressure::hydrostatic) return;
  for (const MpsMaterial& m : a.materials)
    if (m.material.type == sph::mps::Material::Type::water) return;
  mps.diagnostics().error(mps.path_of("pore_pressure"), "\"hydrostatic\" takes the pore water's density from a "
                                                          "material of type \"water\", and materials has none; "
                                                          "add one or use \"none\"");
}

// A run planned to need more than max_steps time steps is refused before it starts, with the figures.
void refuse_too_many_steps(const MpsAnalysis& a, Diagnostics& diagnostics) {
  const MpsPlan plan = plan_mps(a);
  if (!(plan.planned_steps > a.max_steps)) return;
  const sph::mps::Settings& s = a.settings;
  std::ostringstream why;
  why << "the run needs about " << std::llround(std::min(plan.planned_steps, 1e18)) << " time steps (eq. 30: time step "
      << plan.time_step << " s for end_time_s = " << s.end_time << " s; ";
  if (plan.viscous_limit)
    why << "the viscous limit cfl rho0 dx^2 / (4 mu) with mu = " << plan.viscosity
        << " Pa s, the viscosity_cap_Pa_s a granular material reaches at rest), more than max_steps = "
        << std::llround(a.max_steps)
        << "; lower viscosity_cap_Pa_s, use a larger particle_spacing_m or a shorter end_time_s, or raise max_steps";
  else
    why << "the acoustic limit cfl dx / c0 with sound_speed_m_s = " << s.sound_speed << " m/s), more than max_steps = "
        << std::llround(a.max_steps)
        << "; use a larger particle_spacing_m or a shorter end_time_s, or raise max_steps";
  diagnostics.error("analyses.mps.max_steps", why.str());
}

// The settings' and the materials' own checks; the fault at analyses.mps when one fails.
bool validate(const MpsAnalysis& a, Diagnostics& diagnostics) {
  try {
    a.settings.validate();
    for (const MpsMaterial& m : a.materials) m.material.validate();
  } catch (const std::exception& error) {
    diagnostics.error("analyses.mps", error.what());
    return false;
  }
  return true;
}

}  // namespace

MpsPlan plan_mps(const MpsAnalysis& a) {
  const sph::mps::Settings& s = a.settings;
  MpsPlan plan;
  for (const std::uint16_t k : a.block_material) {  // the largest mu rho0 / rho_i, as the stepper takes it
    if (k >= a.materials.size()) continue;
    const sph::mps::Material& m = a.materials[k].material;
    const bool granular = m.type == sph::mps::Material::Type::granular;
    const double density = m.density > 0 ? m.density : s.rest_density;
    plan.viscosity = std::max(plan.viscosity, (granular ? s.viscosity_cap : m.viscosity) * (s.rest_density / density));
  }
  plan.time_step = sph::mps::terms::time_step(s.cfl, s.particle_spacing, s.sound_speed, s.gate_lift_speed,
                                              s.rest_density, plan.viscosity);
  plan.viscous_limit = plan.time_step < s.cfl * s.particle_spacing / s.sound_speed;
  plan.planned_steps = s.end_time / plan.time_step;
  return plan;
}

MpsAnalysis read_mps_analysis(JsonReader& mps) {
  MpsAnalysis a;
  read_numerics(mps, a.settings);
  read_mps_materials(mps, a.materials);
  read_tank(mps, a.tank);
  read_tank_rectangles(mps, "blocks", a.tank, a.blocks,
                       [&](JsonReader& b) { read_block_material(b, a.materials, a); });
  read_gate(mps, a);
  read_tank_monitors(mps, a.monitors, true);
  read_profiles(mps, a);
  check_pore_water(mps, a);
  a.max_steps = mps.number_or("max_steps", a.max_steps);
  mps.finish();
  if (validate(a, mps.diagnostics()) && mps.diagnostics().empty()) refuse_too_many_steps(a, mps.diagnostics());
  return a;
}

void apply_mps_spacing(MpsAnalysis& analysis, double spacing, Diagnostics& diagnostics) {
  analysis.settings.particle_spacing = spacing;
  if (analysis.gate_x) gate_fits(analysis, *analysis.gate_x, diagnostics);
  if (validate(analysis, diagnostics) && diagnostics.empty()) refuse_too_many_steps(analysis, diagnostics);
}

}  // namespace coupling
