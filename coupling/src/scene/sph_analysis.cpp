// analyses.sph, "bodies" and "walls" read into typed settings, and what SPH needs from the rest of the scene. Keys
// and defaults are documented in docs/scene-format.md ("analyses.sph", "bodies", "walls").
#include "coupling/scene/sph_analysis.hpp"

// g++ 12 reports a false "may be used uninitialized" inside CGAL's polygon algorithms when they are inlined
// here; the warning is silenced for this file only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <initializer_list>
#include <map>
#include <string_view>
#include <utility>

#include "coupling/scene/scene.hpp"
#include "scene_internal.hpp"
#include "sph/engine/fill.hpp"
#include "sph/engine/kernel.hpp"

namespace coupling {

namespace {

// walls.sides or analyses.sph.walls.sides: `fallback` when absent.
std::optional<WallSides> read_sides(JsonReader& reader, const char* key, WallSides fallback) {
  const auto sides = read_named_list(reader, key, wall_side_names, "an array of \"left\", \"right\", \"bottom\"");
  if (!sides) return std::nullopt;
  if (!reader.has(key)) return fallback;
  WallSides out{false, false, false};
  for (const WallSide side : *sides)
    (side == WallSide::left ? out.left : side == WallSide::right ? out.right : out.bottom) = true;
  return out;
}

// The SPH model carries the section's loads (coupling/src/analyses/sph_model.cpp). What remains to check: a load
// listed in analyses.sph.ignore_loads that the section does not have (a slip of the pen), and k_h on a section whose
// ground is level at both ends, where SPH has no direction to apply it in (limit equilibrium takes each surface's).
bool has_load(const slope::Section& section, SectionLoadKind load) {
  switch (load) {
    case SectionLoadKind::water: return section.water.has_value();
    case SectionLoadKind::surcharges: return !section.surcharges.empty();
    case SectionLoadKind::line_loads: return !section.line_loads.empty();
    case SectionLoadKind::seismic:
      return section.seismic_coefficient != 0.0 || section.vertical_seismic_coefficient != 0.0;
  }
  return false;
}

void check_section_loads(const Scene& scene, const SphAnalysis& analysis, Diagnostics& diagnostics) {
  if (!scene.section) return;
  const slope::Section& section = scene.section->section;
  for (std::size_t k = 0; k < analysis.ignored_loads.size(); ++k) {
    const SectionLoadKind load = analysis.ignored_loads[k];
    if (!has_load(section, load))
      diagnostics.error(index_path("analyses.sph.ignore_loads", k),
                        "the section has no " + std::string(sphslope::name_of(section_load_names, load)) +
                            " to leave out (remove it from the list)");
  }
  if (section.seismic_coefficient != 0.0 && !ignores(analysis, SectionLoadKind::seismic) &&
      slope::facing_direction(section) == 0)
    diagnostics.error("section.seismic",
                      "the ground is level at both ends of the section, so SPH cannot tell which way the slope "
                      "faces to apply k_h (limit equilibrium applies it toward each surface's sliding); extend the "
                      "section so that one end is higher, or add \"seismic\" to analyses.sph.ignore_loads");
}

}  // namespace

std::vector<SectionLoad> loads_sph_leaves_out(const Scene& scene) {
  std::vector<SectionLoad> loads;
  if (!scene.section || !scene.analyses.sph) return loads;
  const slope::Section& section = scene.section->section;
  const std::string why = "listed in analyses.sph.ignore_loads";
  for (const auto& [name, load] : section_load_names)  // in the table's order, whatever the list's
    if (has_load(section, load) && ignores(*scene.analyses.sph, load))
      loads.push_back({std::string(name), "section." + std::string(name), why});
  const auto& materials = scene.section->materials;
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].pore_pressure_ratio > 0.0)
      loads.push_back({"the pore-pressure ratio r_u = " + format_number(materials[i].pore_pressure_ratio) +
                           " of material \"" + materials[i].name + "\"",
                       index_path("section.materials", i) + ".pore_pressure_ratio",
                       "the SPH soil model takes pore pressure from the piezometric line only"});
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].cohesion_rate > 0.0)
      loads.push_back({"the cohesion's increase with depth of material \"" + materials[i].name + "\" (" +
                           format_number(materials[i].cohesion_rate / 1e3) + " kPa/m)",
                       index_path("section.materials", i) + ".cohesion_increase_kPa_per_m",
                       "the SPH soil model gives each material one cohesion (cohesion_kPa)"});
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].saturated_unit_weight && section.water && ignores(*scene.analyses.sph, SectionLoadKind::water))
      loads.push_back({"the saturated unit weight of material \"" + materials[i].name + "\" (" +
                           format_number(*materials[i].saturated_unit_weight / 1e3) + " kN/m3)",
                       index_path("section.materials", i) + ".saturated_unit_weight_kN_m3",
                       "without the water (analyses.sph.ignore_loads) every particle has the density "
                       "unit_weight_kN_m3 / g"});
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].envelope)
      loads.push_back({"the strength envelope of material \"" + materials[i].name + "\" (" +
                           slope::describe_envelope(*materials[i].envelope) + ")",
                       index_path("section.materials", i) + "." + envelope_key(materials[i].envelope->kind),
                       "the SPH soil model takes its Mohr-Coulomb cohesion_kPa and friction_angle_deg"});
  if (!section.reinforcement.empty())
    loads.push_back({std::to_string(section.reinforcement.size()) + " reinforcement element" +
                         (section.reinforcement.size() == 1 ? "" : "s"),
                     "section.reinforcement", "the SPH soil model has no structural elements"});
  return loads;
}

namespace {

void read_choices(JsonReader& r, sph::soil::Settings& s) {
  read_named(r, "kernel", sph::kernel_names, s.kernel);
  read_named(r, "kernel_gradient", sph::soil::kernel_gradient_names, s.kernel_gradient);
  read_named(r, "time_integration", sph::soil::time_integration_names, s.integration);
  read_named(r, "gravity", sph::gravity_mode_names, s.gravity_mode);
}

void read_artificial_viscosity(JsonReader& r, sph::soil::Settings& s) {
  auto viscosity = r.object("artificial_viscosity", Need::optional);
  if (!viscosity) return;
  s.viscosity.alpha = viscosity->number_or("alpha", s.viscosity.alpha);
  s.viscosity.beta = viscosity->number_or("beta", s.viscosity.beta);
  viscosity->finish();
}

void read_artificial_stress(JsonReader& r, sph::soil::Settings& s) {
  auto stress = r.object("artificial_stress", Need::optional);
  if (!stress) return;
  read_named(*stress, "mode", sph::soil::artificial_stress_mode_names, s.artificial_stress.mode);
  s.artificial_stress.epsilon = stress->number_or("epsilon", s.artificial_stress.epsilon);
  s.artificial_stress.exponent = stress->number_or("exponent", s.artificial_stress.exponent);
  stress->finish();
}

// analyses.sph.walls: sides, slip and the layer count (returned when given; checked once the spacing is known).
std::optional<long> read_section_walls(JsonReader& r, SphAnalysis& a) {
  std::optional<long> wall_layers;
  auto walls = r.object("walls", Need::optional);
  if (!walls) return wall_layers;
  if (auto sides = read_sides(*walls, "sides", a.section_walls)) a.section_walls = *sides;
  wall_layers = walls->integer("layers", Need::optional);
  read_named(*walls, "slip", sph::soil::wall_slip_names, a.settings.wall_slip);
  const bool frictional = a.settings.wall_slip == sph::soil::WallSlip::frictional;
  const auto delta = walls->number("friction_angle_deg", Need::optional, Bounds::half_open(0.0, 90.0));
  if (delta && !frictional)
    walls->diagnostics().error(walls->path_of("friction_angle_deg"),
                               "is used only with \"slip\": \"frictional\" (the walls' Coulomb friction on the soil)");
  else if (frictional && !walls->has("friction_angle_deg"))
    walls->diagnostics().error(walls->path_of("friction_angle_deg"),
                               "is required with \"slip\": \"frictional\": the walls' friction angle delta on the "
                               "soil in [0, 90) degrees");
  if (delta && frictional) a.settings.wall_friction_angle_deg = *delta;
  walls->finish();
  return wall_layers;
}

// Stopping, checkpoint and the limits that refuse a case before it starts.
void read_run_limits(JsonReader& r, SphAnalysis& a) {
  sph::soil::Settings& s = a.settings;
  s.cfl = r.number_or("cfl", sph::soil::default_cfl(s.integration), Bounds{0.0, false, sph::soil::max_cfl(s.integration), true});
  s.stress_substeps = sph::soil::default_stress_substeps(s.integration);
  if (const auto n = r.integer("stress_substeps", Need::optional)) {
    s.stress_substeps = static_cast<int>(*n);
    if (*n > 1 && s.integration != sph::soil::TimeIntegration::verlet)
      r.diagnostics().error(r.path_of("stress_substeps"),
                            "a stress update in " + std::to_string(*n) + " sub-steps needs \"time_integration\": "
                            "\"verlet\" (the predictor-corrector updates the stress twice per step); give 1 or "
                            "leave it out");
  }
  s.damping = r.number_or("damping_per_s", s.damping);
  s.checkpoint_interval_wall_s =
      r.number_or("checkpoint_interval_s", s.checkpoint_interval_wall_s);
  a.quasi_static_speed = r.number_or("stop_below_speed_m_s", 0.0);
  a.quasi_static_min_time = r.number_or("stop_below_speed_after_s", 0.0);
  a.memory_limit_bytes = r.number_or("max_memory_GiB", 16.0) * gibibyte;
  a.max_particles = static_cast<std::size_t>(r.number_or("max_particles", 5.0e6));
  a.max_steps = r.number_or("max_steps", 5.0e6);
}

// Gravity ramp: only with "ramped"; default 10 % of the simulated time; full gravity must be reached.
bool resolve_gravity_ramp(JsonReader& r, std::optional<double> ramp, sph::soil::Settings& s) {
  if (ramp && s.gravity_mode != sph::GravityMode::ramped) {
    r.diagnostics().error(r.path_of("gravity_ramp_s"),
                          "is only used with \"gravity\": \"ramped\" (remove it, or set "
                          "gravity to \"ramped\")");
    return false;
  }
  if (s.gravity_mode == sph::GravityMode::ramped) {
    s.gravity_ramp_time = ramp.value_or(0.1 * s.end_time);
    if (s.gravity_ramp_time > s.end_time) {
      r.diagnostics().error(r.path_of("gravity_ramp_s"),
                            format_number(s.gravity_ramp_time) +
                                " s is longer than end_time_s = " + format_number(s.end_time) +
                                " s: full gravity would never be reached (use a ramp of "
                                "at most end_time_s, e.g. a few times the slope's first shear-mode period)");
      return false;
    }
  }
  return true;
}

// Wall thickness: the kernel support 2h must be covered, or soil beside a wall misses part of its neighbourhood.
bool resolve_wall_layers(std::optional<long> wall_layers, SphAnalysis& a, Diagnostics& diagnostics) {
  const sph::soil::Settings& s = a.settings;
  const int layers_needed = sph::wall_layers_for(s.particle_spacing, s.smoothing_length());
  if (!wall_layers) {
    a.wall_layers = layers_needed;
    return true;
  }
  if (*wall_layers < layers_needed) {
    diagnostics.error("analyses.sph.walls.layers",
                      std::to_string(*wall_layers) + " wall layer" + (*wall_layers == 1 ? "" : "s") + " of " +
                          format_number(s.particle_spacing) + " m do not cover the kernel support 2h = " +
                          format_number(2.0 * s.smoothing_length()) + " m (h = " + format_number(s.h_over_dx) +
                          " x particle_spacing_m): at least " + std::to_string(layers_needed) +
                          " layers are needed, or soil particles next to the wall miss part of their "
                          "neighbourhood (too little wall pressure) and can leak through it");
    return false;
  }
  a.wall_layers = static_cast<int>(*wall_layers);
  return true;
}

}  // namespace

std::optional<SphAnalysis> read_sph_analysis(const nlohmann::json& block, Diagnostics& diagnostics) {
  JsonReader r(block, "analyses.sph", diagnostics);
  const std::size_t errors_before = diagnostics.size();
  SphAnalysis a;
  sph::soil::Settings& s = a.settings;
  const auto spacing = r.number("particle_spacing_m", Need::required);
  const auto end_time = r.number("end_time_s", Need::required);
  s.h_over_dx = r.number_or("smoothing_length_ratio", s.h_over_dx,
                            Bounds::closed(sph::EngineSettings::h_over_dx_min, sph::EngineSettings::h_over_dx_max));
  read_choices(r, s);
  const auto ramp = r.number("gravity_ramp_s", Need::optional);
  read_artificial_viscosity(r, s);
  read_artificial_stress(r, s);
  const double chi = r.number_or("xsph", 0.0);
  s.xsph.enabled = chi > 0.0;
  if (chi > 0.0) s.xsph.chi = chi;
  const std::optional<long> wall_layers = read_section_walls(r, a);
  read_run_limits(r, a);
  const auto output_interval = r.number("output_interval_s", Need::optional);
  if (auto ignored = read_named_list(r, "ignore_loads", section_load_names, "an array of names"))
    a.ignored_loads = std::move(*ignored);
  r.finish();
  if (!spacing || !end_time || diagnostics.size() != errors_before) return std::nullopt;
  s.particle_spacing = *spacing;
  s.end_time = *end_time;
  s.output_interval = output_interval.value_or(*end_time / 20.0);
  if (!resolve_gravity_ramp(r, ramp, s)) return std::nullopt;
  if (!resolve_wall_layers(wall_layers, a, diagnostics)) return std::nullopt;
  s.gravity_x = 0.0;
  s.gravity_y = -standard_gravity;
  return a;
}

std::optional<std::vector<std::pair<double, double>>> read_simple_polygon(JsonReader& parent, std::string_view key,
                                                                       std::string_view what) {
  Diagnostics& diagnostics = parent.diagnostics();
  const nlohmann::json* polygon =
      parent.array(key, Need::required, 3, limits::polygon_vertices, "an array of at least 3 [x, y] points");
  if (!polygon) return std::nullopt;
  std::vector<std::pair<double, double>> out;
  for (std::size_t k = 0; k < polygon->size(); ++k)
    if (auto p = read_pair((*polygon)[k], index_path(parent.path_of(key), k), diagnostics)) out.push_back(*p);
  if (out.size() != polygon->size()) return std::nullopt;
  CGAL::Polygon_2<CGAL::Exact_predicates_inexact_constructions_kernel> cgal;
  for (const auto& [x, y] : out) cgal.push_back({x, y});
  if (!cgal.is_simple()) {
    diagnostics.error(parent.path_of(key),
                      "the polygon crosses itself (" + std::string(what) + " must be a simple polygon)");
    return std::nullopt;
  }
  if (!(std::abs(cgal.area()) > 0.0)) {
    diagnostics.error(parent.path_of(key), "the polygon has no area");
    return std::nullopt;
  }
  return out;
}

std::optional<std::vector<ParticleBody>> read_particle_bodies(const nlohmann::json& bodies, Diagnostics& diagnostics) {
  std::vector<ParticleBody> out;
  const std::size_t errors_before = diagnostics.size();
  if (!bodies.is_array() || bodies.empty()) {
    diagnostics.error("bodies", "expected a non-empty array of bodies ({\"name\", \"polygon_m\", \"material\"})");
    return std::nullopt;
  }
  if (!within_size_limit(bodies, "bodies", limits::bodies, diagnostics)) return std::nullopt;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    JsonReader b(bodies[i], index_path("bodies", i), diagnostics);
    ParticleBody body;
    body.name = b.string("name", Need::optional).value_or("body " + std::to_string(i));
    if (auto polygon = read_simple_polygon(b, "polygon_m", "a body"))
      for (const auto& [x, y] : *polygon) body.polygon.push_back({x, y});
    read_named(b, "fill", body_fill_names, body.fill);
    if (body.fill == BodyFill::rows && body.polygon.size() > max_rows_fill_vertices)
      diagnostics.error(b.path_of("fill"), "\"rows\" fills a polygon of at most " +
                                               std::to_string(max_rows_fill_vertices) + " vertices (this one has " +
                                               std::to_string(body.polygon.size()) +
                                               "): each row is tested against every edge; use \"lattice\"");
    if (auto m = b.object("material", Need::required)) {
      if (auto material = read_material(*m, MaterialOf::body)) {
        body.material = *material;
        std::string missing;
        if (!material->youngs_modulus) missing = "youngs_modulus_MPa";
        if (!material->poisson_ratio) missing += std::string(missing.empty() ? "" : " and ") + "poisson_ratio";
        if (!missing.empty())
          diagnostics.error(
              m->path(), "material \"" + material->name + "\" lacks " + missing + ", which the SPH soil model needs");
      }
    }
    b.finish();
    out.push_back(std::move(body));
  }
  if (diagnostics.size() != errors_before) return std::nullopt;
  return out;
}

std::optional<WallBox> read_wall_box(const nlohmann::json& walls, Diagnostics& diagnostics) {
  JsonReader w(walls, "walls", diagnostics);
  const std::size_t errors_before = diagnostics.size();
  WallBox box;
  std::optional<std::pair<double, double>> x_range;
  if (const nlohmann::json* range = w.raw("x_range_m", Need::required, "[x_min, x_max]"))
    x_range = read_pair(*range, w.path_of("x_range_m"), diagnostics, "[x_min, x_max]");
  const auto bottom = w.number("bottom_y_m", Need::required);
  const auto height = w.number("height_m", Need::required);
  const auto sides = read_sides(w, "sides", WallSides{});
  w.finish();
  if (x_range && x_range->second <= x_range->first)
    diagnostics.error(w.path_of("x_range_m"), "x_max must be greater than x_min (got " + format_number(x_range->first) +
                                                  ", " + format_number(x_range->second) + ")");
  if (!x_range || !bottom || !height || !sides || diagnostics.size() != errors_before) return std::nullopt;
  box = {x_range->first, x_range->second, *bottom, *height, *sides};
  return box;
}

namespace {

// As for a section: a body needs at least 4 particles across (its bounding box's smaller side).
void check_particles_across_bodies(const std::vector<ParticleBody>& bodies, double dx, Diagnostics& diagnostics) {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const auto& polygon = bodies[i].polygon;
    double x0 = polygon.front().x, x1 = x0, y0 = polygon.front().y, y1 = y0;
    for (const auto& p : polygon) {
      x0 = std::min(x0, p.x);
      x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y);
      y1 = std::max(y1, p.y);
    }
    const double across = std::min(x1 - x0, y1 - y0);
    if (across / dx < 4.0)
      diagnostics.error("analyses.sph.particle_spacing_m",
                        "spacing " + format_number(dx) + " m leaves fewer than 4 particles across bodies[" +
                            std::to_string(i) + "] (\"" + bodies[i].name + "\", " + format_number(across) +
                            " m across); use a spacing of at most " + format_number(across / 4.0) + " m");
  }
}

void check_bodies_inside_walls(const std::vector<ParticleBody>& bodies, const WallBox& box, Diagnostics& diagnostics) {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (std::size_t k = 0; k < bodies[i].polygon.size(); ++k) {
      const auto& p = bodies[i].polygon[k];
      const bool outside = p.x < box.x_min - 1e-9 || p.x > box.x_max + 1e-9 || p.y < box.bottom_y - 1e-9 ||
                           p.y > box.bottom_y + box.height + 1e-9;
      if (outside)
        diagnostics.error(index_path(join_path(index_path("bodies", i), "polygon_m"), k),
                          "point (" + format_number(p.x) + ", " + format_number(p.y) +
                              ") lies outside the wall box (walls.x_range_m, bottom_y_m, height_m)");
    }
}

// "bodies" and "walls" of a particle scene, read into the scene, with the checks against the SPH settings.
void read_particle_scene(const SphBlocks& blocks, const std::optional<SphAnalysis>& analysis, Scene& scene,
                         Diagnostics& diagnostics) {
  scene.bodies = read_particle_bodies(*blocks.bodies, diagnostics);
  if (blocks.walls) scene.walls = read_wall_box(*blocks.walls, diagnostics);
  if (scene.bodies && analysis)
    check_particles_across_bodies(*scene.bodies, analysis->settings.particle_spacing, diagnostics);
  if (scene.bodies && scene.walls) check_bodies_inside_walls(*scene.bodies, *scene.walls, diagnostics);
}

// A section needs at least 4 particles across its height and its width.
void check_particles_across_section(const slope::Section& section, double dx, Diagnostics& diagnostics) {
  double top = section.bottom_y;
  for (const auto& p : section.profile_lines.front().points) top = std::max(top, p.y);
  if ((top - section.bottom_y) / dx < 4.0 || (section.x_max() - section.x_min()) / dx < 4.0)
    diagnostics.error("analyses.sph.particle_spacing_m",
                      "spacing " + format_number(dx) + " m leaves fewer than 4 particles across the section (" +
                          format_number(top - section.bottom_y) + " m high); use a spacing of at most " +
                          format_number((top - section.bottom_y) / 4.0) + " m");
}

}  // namespace

void read_sph_scene(const SphBlocks& blocks, Scene& scene, Diagnostics& diagnostics) {
  if (!blocks.sph) return;
  const auto analysis = read_sph_analysis(*blocks.sph, diagnostics);
  if (blocks.bodies) {
    // analyses.sph.walls.sides lines a section's box; a particle scene's walls are its own (walls.sides): refused
    // rather than left unused
    const auto walls = blocks.sph->find("walls");
    if (walls != blocks.sph->end() && walls->is_object() && walls->contains("sides"))
      diagnostics.error("analyses.sph.walls.sides", "a particle scene's walls are the top-level \"walls\" (its "
                                                    "\"sides\"); analyses.sph.walls.sides is for a slope section");
    read_particle_scene(blocks, analysis, scene, diagnostics);
  } else if (blocks.walls) {
    diagnostics.error("walls",
                      "walls belong to particle scenes with \"bodies\"; for a slope section set "
                      "analyses.sph.walls.sides instead");
  }
  if (analysis) check_section_loads(scene, *analysis, diagnostics);
  if (analysis && scene.section)
    check_particles_across_section(scene.section->section, analysis->settings.particle_spacing, diagnostics);
  scene.analyses.sph = analysis;
}

void apply_sph_spacing(const Scene& scene, SphAnalysis& analysis, double spacing, Diagnostics& diagnostics) {
  analysis.settings.particle_spacing = spacing;
  if (scene.bodies) check_particles_across_bodies(*scene.bodies, spacing, diagnostics);
  if (scene.section) check_particles_across_section(scene.section->section, spacing, diagnostics);
}

std::vector<sph::Point> body_fill_points(const ParticleBody& body, double dx, sph::Point anchor) {
  if (body.fill == BodyFill::rows) {
    std::vector<sph::Point> polygon;
    double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
    for (const auto& p : body.polygon) {
      polygon.push_back({p.x, p.y});
      x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x), y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
    }
    // enough rows to reach the middle from every face (the fill stops once a row adds nothing)
    const double extent = std::max(x_hi - x_lo, y_hi - y_lo);
    return sph::boundary_layer_points(polygon, dx, static_cast<int>(std::ceil(extent / dx)) + 1);
  }
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  CGAL::Polygon_2<Kernel> polygon;
  double x_lo = std::numeric_limits<double>::infinity(), y_lo = x_lo, x_hi = -x_lo, y_hi = -x_lo;
  for (const auto& p : body.polygon) {
    polygon.push_back({p.x, p.y});
    x_lo = std::min(x_lo, p.x);
    y_lo = std::min(y_lo, p.y);
    x_hi = std::max(x_hi, p.x);
    y_hi = std::max(y_hi, p.y);
  }
  return sph::lattice_points_in_region(
      x_lo, y_lo, x_hi, y_hi, dx,
      [&](double x, double y) { return polygon.bounded_side(Kernel::Point_2(x, y)) == CGAL::ON_BOUNDED_SIDE; },
      anchor);
}

}  // namespace coupling
