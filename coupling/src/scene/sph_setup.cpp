// Scene -> SPH particle model. Keys and defaults are documented in docs/scene-format.md ("analyses.sph",
// "bodies", "walls").
#include "coupling/scene/sph_setup.hpp"

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
#include <map>

#include "coupling/compare/sliding_mass.hpp"
#include "scene_internal.hpp"
#include "sph/engine/fill.hpp"
#include "sph/engine/kernel.hpp"

namespace coupling {

namespace {

constexpr double gibibyte = 1024.0 * 1024.0 * 1024.0;

std::optional<WallSides> read_sides(JsonReader& reader, std::string_view key, WallSides fallback) {
  const nlohmann::json* sides = reader.array(key, Need::optional, 0, limits::name_list,
                                             "an array of \"left\", \"right\", \"bottom\"");
  if (!sides) return reader.has(key) ? std::nullopt : std::optional<WallSides>(fallback);
  WallSides out{false, false, false};
  bool ok = true;
  for (std::size_t i = 0; i < sides->size(); ++i) {
    const auto side = read_string((*sides)[i], index_path(reader.path_of(key), i), reader.diagnostics());
    if (!side) {
      ok = false;
    } else if (*side == "left") {
      out.left = true;
    } else if (*side == "right") {
      out.right = true;
    } else if (*side == "bottom") {
      out.bottom = true;
    } else {
      reader.diagnostics().error(index_path(reader.path_of(key), i),
                                 "unknown wall side \"" + *side + "\" (allowed: left, right, bottom)");
      ok = false;
    }
  }
  return ok ? std::optional<WallSides>(out) : std::nullopt;
}

sph::Material to_sph_material(const SoilMaterial& m) {
  sph::Material out;
  out.name = m.name;
  out.density = m.density();
  out.youngs_modulus = m.youngs_modulus.value_or(0.0);
  out.poisson_ratio = m.poisson_ratio.value_or(0.0);
  out.cohesion = m.cohesion;
  out.friction_angle_deg = m.friction_angle * 180.0 / M_PI;
  out.dilatancy_angle_deg = m.dilatancy_angle.value_or(0.0) * 180.0 / M_PI;
  out.plastic = !m.elastic;
  return out;
}

double section_area(const slope::Section& section) {
  const auto& ground = section.profile_lines.front().points;
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < ground.size(); ++k)
    area += 0.5 * (ground[k].y + ground[k + 1].y - 2.0 * section.bottom_y) * (ground[k + 1].x - ground[k].x);
  return area;
}

// A particle count estimated in floating point, as an integer. Absurd inputs (a spacing of 1e-50 m) give counts
// no machine holds; they saturate at 1e15 so that the sums and the memory estimate built on them cannot overflow and
// the size check refuses the case with its message.
constexpr std::size_t particle_count_cap = 1'000'000'000'000'000;

std::size_t particle_count(double count) {
  if (!(count < static_cast<double>(particle_count_cap))) return particle_count_cap;
  return static_cast<std::size_t>(std::ceil(std::max(count, 0.0)));
}

// Wall particles of a box, counted as add_box_walls lays them (layers of the kernel support around the box).
std::size_t wall_estimate(double width, double height, const WallSides& sides, double dx, int wall_layers) {
  const double layers = wall_layers;
  double count = 0.0;
  if (sides.bottom) count += (width / dx + 2.0 * layers) * layers;
  if (sides.left) count += (height / dx) * layers;
  if (sides.right) count += (height / dx) * layers;
  return particle_count(count);
}

// Why a case of this many particles must be refused (particle or memory limit), or nothing.
std::optional<std::string> size_refusal(const SphAnalysis& analysis, std::size_t particles) {
  const std::size_t bytes = sph::estimate_memory_bytes(particles);
  const std::string count = particles >= particle_count_cap ? std::string("more than 1e15")
                                                            : "about " + std::to_string(particles);
  if (analysis.max_particles > 0 && particles > analysis.max_particles) {
    return "analyses.sph.particle_spacing_m: the case would need " + count +
           " particles, more than analyses.sph.max_particles = " + std::to_string(analysis.max_particles) +
           " (use a larger spacing or raise max_particles)";
  }
  if (static_cast<double>(bytes) > analysis.memory_limit_bytes) {
    return "analyses.sph.particle_spacing_m: the case would need about " +
           format_number(static_cast<double>(bytes) / gibibyte) + " GiB for " + count +
           " particles, more than analyses.sph.max_memory_GiB = " + format_number(analysis.memory_limit_bytes / gibibyte) +
           " (use a larger spacing or raise max_memory_GiB)";
  }
  return std::nullopt;
}

void refuse_if_too_large(const SphAnalysis& analysis, std::size_t particles) {
  if (auto why = size_refusal(analysis, particles)) throw SceneError({*why});
}

// Time step and planned step count from the materials and settings alone (no particles needed).
void plan_steps(const std::vector<sph::Material>& materials, const sph::Settings& settings, SphPlan& plan) {
  sph::Model model;
  model.materials = materials;
  model.settings = settings;
  plan.p_wave_speed = 0.0;
  for (const auto& m : materials)
    plan.p_wave_speed = std::max(plan.p_wave_speed, sph::MaterialConstants::from(m).sound_speed);
  plan.time_step = sph::time_step_estimate(model);
  plan.planned_steps = settings.end_time / plan.time_step;
}

}  // namespace

namespace {

const char* const section_load_names[] = {"water", "surcharges", "seismic"};

// analyses.sph.ignore_loads: the section loads the user accepts SPH leaves out (each at most once).
std::vector<std::string> read_ignored_loads(JsonReader& r) {
  std::vector<std::string> names;
  const nlohmann::json* list = r.array("ignore_loads", Need::optional, 0, limits::name_list);
  if (list == nullptr) return names;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string path = index_path(r.path_of("ignore_loads"), i);
    const auto name = read_string((*list)[i], path, r.diagnostics());
    if (!name) continue;
    if (std::find(std::begin(section_load_names), std::end(section_load_names), *name) == std::end(section_load_names))
      r.diagnostics().error(path, "unknown load \"" + *name + "\" (allowed: water, surcharges, seismic)");
    else if (std::find(names.begin(), names.end(), *name) != names.end())
      r.diagnostics().error(path, "\"" + *name + "\" is listed twice");
    else
      names.push_back(*name);
  }
  return names;
}

// Until SPH carries a load, a scene asking SPH (or strength reduction) for a loaded section is refused unless
// the user lists the load in analyses.sph.ignore_loads: SPH must never solve a different problem than limit
// equilibrium without saying so.
void check_unmodelled_loads(const Scene& scene, const SphAnalysis& analysis, Diagnostics& diagnostics) {
  for (const SectionLoad& load : loads_sph_leaves_out(scene)) {
    const auto& ignored = analysis.ignored_loads;
    if (std::find(ignored.begin(), ignored.end(), load.name) != ignored.end()) continue;
    diagnostics.error(load.path, "the SPH model does not carry " + load.name +
                                     " yet: SPH (and strength reduction and the comparison) would analyse the "
                                     "slope without it, unlike limit equilibrium. Remove analyses.sph, or add \"" +
                                     load.name + "\" to analyses.sph.ignore_loads to run SPH without it (the "
                                     "report then warns)");
  }
}

}  // namespace

std::vector<SectionLoad> loads_sph_leaves_out(const Scene& scene) {
  std::vector<SectionLoad> loads;
  if (!scene.section) return loads;
  const slope::Section& section = scene.section->section;
  if (section.water) loads.push_back({"water", "section.water"});
  if (!section.surcharges.empty()) loads.push_back({"surcharges", "section.surcharges"});
  if (section.seismic_coefficient != 0.0) loads.push_back({"seismic", "section.seismic"});
  return loads;
}

std::optional<SphAnalysis> read_sph_analysis(const nlohmann::json& block, Diagnostics& diagnostics) {
  JsonReader r(block, "analyses.sph", diagnostics);
  const std::size_t errors_before = diagnostics.size();
  SphAnalysis a;
  sph::Settings& s = a.settings;
  const auto spacing = r.number("particle_spacing_m", Need::required, Bounds::positive());
  const auto end_time = r.number("end_time_s", Need::required, Bounds::positive());
  s.h_over_dx = r.number_or("smoothing_length_ratio", 1.2, Bounds::closed(1.0, 2.0));
  if (const auto kernel = r.string("kernel", Need::optional)) {
    if (*kernel == "cubic_spline") {
      s.kernel = sph::KernelType::cubic_spline;
    } else if (*kernel == "wendland_c2") {
      s.kernel = sph::KernelType::wendland_c2;
    } else {
      diagnostics.error(r.path_of("kernel"), "unknown kernel \"" + *kernel + "\" (allowed: cubic_spline, wendland_c2)");
    }
  }
  if (const auto gravity = r.string("gravity", Need::optional)) {
    if (*gravity == "sudden") {
      s.gravity_mode = sph::GravityMode::sudden;
    } else if (*gravity == "geostatic_k0") {
      s.gravity_mode = sph::GravityMode::geostatic_k0;
    } else if (*gravity == "ramped") {
      s.gravity_mode = sph::GravityMode::ramped;
    } else {
      diagnostics.error(r.path_of("gravity"),
                        "unknown gravity mode \"" + *gravity + "\" (allowed: sudden, geostatic_k0, ramped)");
    }
  }
  const auto ramp = r.number("gravity_ramp_s", Need::optional, Bounds::positive());
  if (auto viscosity = r.object("artificial_viscosity", Need::optional)) {
    s.viscosity.alpha = viscosity->number_or("alpha", s.viscosity.alpha, Bounds::non_negative());
    s.viscosity.beta = viscosity->number_or("beta", s.viscosity.beta, Bounds::non_negative());
    viscosity->finish();
  }
  if (auto stress = r.object("artificial_stress", Need::optional)) {
    if (const auto mode = stress->string("mode", Need::optional)) {
      if (*mode == "auto") {
        s.artificial_stress.mode = sph::ArtificialStressMode::automatic;
      } else if (*mode == "on") {
        s.artificial_stress.mode = sph::ArtificialStressMode::on;
      } else if (*mode == "off") {
        s.artificial_stress.mode = sph::ArtificialStressMode::off;
      } else {
        diagnostics.error(stress->path_of("mode"), "unknown mode \"" + *mode + "\" (allowed: auto, on, off)");
      }
    }
    s.artificial_stress.epsilon = stress->number_or("epsilon", s.artificial_stress.epsilon, Bounds::closed(0.0, 1.0));
    s.artificial_stress.exponent = stress->number_or("exponent", s.artificial_stress.exponent, Bounds::positive());
    stress->finish();
  }
  const double chi = r.number_or("xsph", 0.0, Bounds::closed(0.0, 1.0));
  s.xsph.enabled = chi > 0.0;
  if (chi > 0.0) s.xsph.chi = chi;
  std::optional<long> wall_layers;
  if (auto walls = r.object("walls", Need::optional)) {
    if (auto sides = read_sides(*walls, "sides", a.section_walls)) a.section_walls = *sides;
    wall_layers = walls->integer("layers", Need::optional, Bounds::closed(1, 50));
    if (const auto slip = walls->string("slip", Need::optional)) {
      if (*slip == "no_slip") {
        s.wall_slip = sph::WallSlip::no_slip;
      } else if (*slip == "free_slip") {
        s.wall_slip = sph::WallSlip::free_slip;
      } else {
        diagnostics.error(walls->path_of("slip"), "unknown slip \"" + *slip + "\" (allowed: no_slip, free_slip)");
      }
    }
    walls->finish();
  }
  s.cfl = r.number_or("cfl", s.cfl, Bounds{0.0, false, 0.5, true});  // sph::Settings accepts (0, 0.5]
  s.damping = r.number_or("damping_per_s", 0.0, Bounds::non_negative());
  s.checkpoint_interval_wall_s = r.number_or("checkpoint_interval_s", 300.0, Bounds::non_negative());
  a.quasi_static_speed = r.number_or("stop_below_speed_m_s", 0.0, Bounds::non_negative());
  a.quasi_static_min_time = r.number_or("stop_below_speed_after_s", 0.0, Bounds::non_negative());
  a.memory_limit_bytes = r.number_or("max_memory_GiB", 16.0, Bounds::positive()) * gibibyte;
  a.max_particles = static_cast<std::size_t>(r.number_or("max_particles", 5.0e6, Bounds::at_least(1.0)));
  a.max_steps = r.number_or("max_steps", 5.0e6, Bounds::at_least(1.0));
  const auto output_interval = r.number("output_interval_s", Need::optional, Bounds::positive());
  a.ignored_loads = read_ignored_loads(r);
  r.finish();
  if (!spacing || !end_time || diagnostics.size() != errors_before) return std::nullopt;
  s.particle_spacing = *spacing;
  s.end_time = *end_time;
  s.output_interval = output_interval.value_or(*end_time / 20.0);
  // Gravity ramp: only with "ramped"; default 10 % of the simulated time; full gravity must be reached.
  if (ramp && s.gravity_mode != sph::GravityMode::ramped) {
    diagnostics.error(r.path_of("gravity_ramp_s"), "is only used with \"gravity\": \"ramped\" (remove it, or set "
                                                   "gravity to \"ramped\")");
    return std::nullopt;
  }
  if (s.gravity_mode == sph::GravityMode::ramped) {
    s.gravity_ramp_time = ramp.value_or(0.1 * *end_time);
    if (s.gravity_ramp_time > *end_time) {
      diagnostics.error(r.path_of("gravity_ramp_s"),
                        format_number(s.gravity_ramp_time) + " s is longer than end_time_s = " +
                            format_number(*end_time) + " s: full gravity would never be reached (use a ramp of "
                            "at most end_time_s, e.g. a few times the slope's first shear-mode period)");
      return std::nullopt;
    }
  }
  // Wall thickness: the kernel support 2h must be covered, or soil beside a wall misses part of its neighbourhood.
  const int layers_needed = sph::wall_layers_for(s.particle_spacing, s.smoothing_length());
  if (wall_layers) {
    if (*wall_layers < layers_needed) {
      diagnostics.error("analyses.sph.walls.layers",
                        std::to_string(*wall_layers) + " wall layer" + (*wall_layers == 1 ? "" : "s") + " of " +
                            format_number(s.particle_spacing) + " m do not cover the kernel support 2h = " +
                            format_number(2.0 * s.smoothing_length()) + " m (h = " + format_number(s.h_over_dx) +
                            " x particle_spacing_m): at least " + std::to_string(layers_needed) +
                            " layers are needed, or soil particles next to the wall miss part of their "
                            "neighbourhood (too little wall pressure) and can leak through it");
      return std::nullopt;
    }
    a.wall_layers = static_cast<int>(*wall_layers);
  } else {
    a.wall_layers = layers_needed;
  }
  s.gravity_x = 0.0;
  s.gravity_y = -standard_gravity;
  return a;
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
    if (const nlohmann::json* polygon = b.array("polygon_m", Need::required, 3, limits::polygon_vertices,
                                                "an array of at least 3 [x, y] points")) {
      for (std::size_t k = 0; k < polygon->size(); ++k)
        if (auto p = read_pair((*polygon)[k], index_path(b.path_of("polygon_m"), k), diagnostics))
          body.polygon.push_back({p->first, p->second});
      if (body.polygon.size() == polygon->size()) {
        CGAL::Polygon_2<CGAL::Exact_predicates_inexact_constructions_kernel> cgal;
        for (const auto& p : body.polygon) cgal.push_back({p.x, p.y});
        if (!cgal.is_simple()) {
          diagnostics.error(b.path_of("polygon_m"), "the polygon crosses itself (a body must be a simple polygon)");
        } else if (polygon_area(body.polygon) <= 0.0) {
          diagnostics.error(b.path_of("polygon_m"), "the polygon has no area");
        }
      }
    }
    if (auto m = b.object("material", Need::required)) {
      if (auto material = read_material(*m)) {
        body.material = *material;
        std::string missing;
        if (!material->youngs_modulus) missing = "youngs_modulus_MPa";
        if (!material->poisson_ratio) missing += std::string(missing.empty() ? "" : " and ") + "poisson_ratio";
        if (!missing.empty())
          diagnostics.error(m->path(), "material \"" + material->name + "\" lacks " + missing +
                                           ", which the SPH soil model needs");
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
  const auto height = w.number("height_m", Need::required, Bounds::positive());
  const auto sides = read_sides(w, "sides", WallSides{});
  w.finish();
  if (x_range && x_range->second <= x_range->first)
    diagnostics.error(w.path_of("x_range_m"), "x_max must be greater than x_min (got " +
                                                  format_number(x_range->first) + ", " +
                                                  format_number(x_range->second) + ")");
  if (!x_range || !bottom || !height || !sides || diagnostics.size() != errors_before) return std::nullopt;
  box = {x_range->first, x_range->second, *bottom, *height, *sides};
  return box;
}

void check_sph_scene(const Scene& scene, Diagnostics& diagnostics) {
  if (!scene.analyses.sph) return;
  const auto analysis = read_sph_analysis(*scene.analyses.sph, diagnostics);
  if (scene.bodies) {
    const auto bodies = read_particle_bodies(*scene.bodies, diagnostics);
    std::optional<WallBox> box;
    if (scene.walls) box = read_wall_box(*scene.walls, diagnostics);
    // As for a section: a body needs at least 4 particles across (its bounding box's smaller side).
    if (bodies && analysis) {
      const double dx = analysis->settings.particle_spacing;
      for (std::size_t i = 0; i < bodies->size(); ++i) {
        const auto& polygon = (*bodies)[i].polygon;
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
                                std::to_string(i) + "] (\"" + (*bodies)[i].name + "\", " + format_number(across) +
                                " m across); use a spacing of at most " + format_number(across / 4.0) + " m");
      }
    }
    if (bodies && box) {
      for (std::size_t i = 0; i < bodies->size(); ++i)
        for (std::size_t k = 0; k < (*bodies)[i].polygon.size(); ++k) {
          const auto& p = (*bodies)[i].polygon[k];
          const bool outside = p.x < box->x_min - 1e-9 || p.x > box->x_max + 1e-9 || p.y < box->bottom_y - 1e-9 ||
                               p.y > box->bottom_y + box->height + 1e-9;
          if (outside)
            diagnostics.error(index_path(join_path(index_path("bodies", i), "polygon_m"), k),
                              "point (" + format_number(p.x) + ", " + format_number(p.y) +
                                  ") lies outside the wall box (walls.x_range_m, bottom_y_m, height_m)");
        }
    }
  } else if (scene.walls) {
    diagnostics.error("walls", "walls belong to particle scenes with \"bodies\"; for a slope section set "
                               "analyses.sph.walls.sides instead");
  }
  if (analysis) check_unmodelled_loads(scene, *analysis, diagnostics);
  if (analysis && scene.section) {
    const double dx = analysis->settings.particle_spacing;
    const auto& section = scene.section->section;
    const double height = section.ground_y(section.x_min());
    double top = section.bottom_y;
    for (const auto& p : section.profile_lines.front().points) top = std::max(top, p.y);
    (void)height;
    if ((top - section.bottom_y) / dx < 4.0 || (section.x_max() - section.x_min()) / dx < 4.0)
      diagnostics.error("analyses.sph.particle_spacing_m",
                        "spacing " + format_number(dx) + " m leaves fewer than 4 particles across the section (" +
                            format_number(top - section.bottom_y) + " m high); use a spacing of at most " +
                            format_number((top - section.bottom_y) / 4.0) + " m");
  }
}

SectionFill fill_section(const slope::Section& section, double dx) {
  SectionFill fill;
  const double x_min = section.x_min(), x_max = section.x_max();
  const auto nx = static_cast<long>(std::floor((x_max - x_min) / dx + 1e-9));
  double top = section.bottom_y;
  for (const auto& p : section.profile_lines.front().points) top = std::max(top, p.y);
  const auto ny = static_cast<long>(std::ceil((top - section.bottom_y) / dx));
  for (long i = 0; i < nx; ++i) {
    const double x = x_min + (static_cast<double>(i) + 0.5) * dx;
    const double ground = section.ground_y(x);
    for (long j = 0; j < ny; ++j) {
      const double y = section.bottom_y + (static_cast<double>(j) + 0.5) * dx;
      if (y >= ground - 1e-9 * dx) break;  // strictly inside: a particle on the ground line is left out
      // The material is that of the lowest profile line at or above the point: the top of its layer.
      std::size_t material = section.profile_lines.front().material;
      double best = std::numeric_limits<double>::infinity();
      for (const auto& line : section.profile_lines) {
        const double line_y = slope::polyline_y(line.points, x);
        if (line_y >= y && line_y < best) {
          best = line_y;
          material = line.material;
        }
      }
      fill.points.push_back({x, y});
      fill.materials.push_back(material);
    }
  }
  return fill;
}

std::optional<SphPlan> plan_sph(const Scene& scene, const SphAnalysis& analysis) {
  SphPlan plan;
  const double dx = analysis.settings.particle_spacing;
  std::vector<sph::Material> materials;
  if (scene.section) {
    const auto& section = scene.section->section;
    for (const auto& m : scene.section->materials) {
      if (!m.youngs_modulus || !m.poisson_ratio) return std::nullopt;
      materials.push_back(to_sph_material(m));
    }
    double top = section.bottom_y;
    for (const auto& p : section.profile_lines.front().points) top = std::max(top, p.y);
    plan.soil_particles = particle_count(section_area(section) / (dx * dx));
    plan.wall_particles = wall_estimate(section.x_max() - section.x_min(), top - section.bottom_y,
                                        analysis.section_walls, dx, analysis.wall_layers);
  } else if (scene.bodies) {
    Diagnostics ignored;
    const auto bodies = read_particle_bodies(*scene.bodies, ignored);
    if (!bodies) return std::nullopt;
    double area = 0.0;
    for (const auto& body : *bodies) {
      area += polygon_area(body.polygon);
      materials.push_back(to_sph_material(body.material));
    }
    plan.soil_particles = particle_count(area / (dx * dx));
    if (scene.walls) {
      const auto walls = read_wall_box(*scene.walls, ignored);
      if (!walls) return std::nullopt;
      plan.wall_particles =
          wall_estimate(walls->x_max - walls->x_min, walls->height, walls->sides, dx, analysis.wall_layers);
    }
  } else {
    return std::nullopt;
  }
  if (materials.empty()) return std::nullopt;
  plan.memory_bytes = sph::estimate_memory_bytes(plan.soil_particles + plan.wall_particles);
  plan_steps(materials, analysis.settings, plan);
  return plan;
}

std::vector<std::string> sph_refusals(const SphAnalysis& analysis, const SphPlan& plan) {
  std::vector<std::string> out;
  if (auto why = size_refusal(analysis, plan.soil_particles + plan.wall_particles)) out.push_back(*why);
  if (plan.planned_steps > analysis.max_steps) {
    out.push_back("analyses.sph: the run needs about " + format_number(std::ceil(plan.planned_steps)) +
                  " time steps (P-wave speed " + format_number(plan.p_wave_speed) + " m/s, time step " +
                  format_number(plan.time_step) + " s for " + format_number(analysis.settings.end_time) +
                  " s), more than analyses.sph.max_steps = " + std::to_string(std::llround(analysis.max_steps)) +
                  "; the explicit step is bounded by the wave speed: use a smaller youngs_modulus_MPa "
                  "(quasi-static runs tolerate a softer soil), a shorter end_time_s, a larger particle_spacing_m, "
                  "or raise max_steps");
  }
  return out;
}

sph::Model build_sph_model(const Scene& scene, SphSize* size) {
  Diagnostics diagnostics;
  const auto analysis = scene.analyses.sph ? read_sph_analysis(*scene.analyses.sph, diagnostics) : std::nullopt;
  if (!analysis) {
    if (diagnostics.empty()) diagnostics.error("analyses.sph", "missing (the scene asks for no SPH analysis)");
    throw SceneError(diagnostics.messages());
  }
  sph::Model model;
  model.settings = analysis->settings;
  const double dx = model.settings.particle_spacing, h = model.settings.smoothing_length();
  SphSize counted;

  if (scene.section) {
    const auto& section = scene.section->section;
    double top = section.bottom_y;
    for (const auto& p : section.profile_lines.front().points) top = std::max(top, p.y);
    const double width = section.x_max() - section.x_min(), height = top - section.bottom_y;
    // Refuse before allocating anything per particle.
    const auto soil_estimate = particle_count(section_area(section) / (dx * dx));
    refuse_if_too_large(*analysis, soil_estimate + wall_estimate(width, height, analysis->section_walls, dx, analysis->wall_layers));

    for (const auto& m : scene.section->materials) model.materials.push_back(to_sph_material(m));
    const SectionFill fill = fill_section(section, dx);
    model.particles.reserve(fill.points.size() + wall_estimate(width, height, analysis->section_walls, dx, analysis->wall_layers));
    for (std::size_t i = 0; i < fill.points.size(); ++i) {
      const double density = model.materials[fill.materials[i]].density;
      model.particles.add(fill.points[i].x, fill.points[i].y, density * dx * dx, density,
                          static_cast<std::uint16_t>(fill.materials[i]), sph::ParticleKind::soil);
    }
    counted.soil_particles = fill.points.size();
    sph::BoxWalls box;
    box.x_min = section.x_min();
    box.x_max = section.x_min() + dx * std::floor(width / dx + 1e-9);
    box.y_min = section.bottom_y;
    box.height = height;
    box.left = analysis->section_walls.left;
    box.right = analysis->section_walls.right;
    box.bottom = analysis->section_walls.bottom;
    box.layers = analysis->wall_layers;
    if (box.left || box.right || box.bottom)
      counted.wall_particles =
          sph::add_box_walls(model.particles, box, dx, h, 0, model.materials.front().density);
  } else if (scene.bodies) {
    const auto bodies = read_particle_bodies(*scene.bodies, diagnostics);
    std::optional<WallBox> walls;
    if (scene.walls) walls = read_wall_box(*scene.walls, diagnostics);
    if (!bodies || (scene.walls && !walls)) throw SceneError(diagnostics.messages());
    double area = 0.0;
    for (const auto& body : *bodies) area += polygon_area(body.polygon);
    std::size_t wall_count = 0;
    if (walls) wall_count = wall_estimate(walls->x_max - walls->x_min, walls->height, walls->sides, dx, analysis->wall_layers);
    refuse_if_too_large(*analysis, particle_count(area / (dx * dx)) + wall_count);

    // Bodies share the lattice of the wall box (or of the first body's lower-left corner).
    sph::Point anchor{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    if (walls) {
      anchor = {walls->x_min, walls->bottom_y};
    } else {
      for (const auto& p : bodies->front().polygon) anchor = {std::min(anchor.x, p.x), std::min(anchor.y, p.y)};
    }
    for (const auto& body : *bodies) {
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
      const auto points = sph::lattice_points_in_region(
          x_lo, y_lo, x_hi, y_hi, dx,
          [&](double x, double y) { return polygon.bounded_side(Kernel::Point_2(x, y)) == CGAL::ON_BOUNDED_SIDE; },
          anchor);
      model.materials.push_back(to_sph_material(body.material));
      counted.soil_particles += sph::add_soil(model.particles, points, dx,
                                              static_cast<std::uint16_t>(model.materials.size() - 1),
                                              body.material.density());
    }
    if (walls) {
      sph::BoxWalls box;
      box.x_min = walls->x_min;
      box.x_max = walls->x_max;
      box.y_min = walls->bottom_y;
      box.height = walls->height;
      box.left = walls->sides.left;
      box.right = walls->sides.right;
      box.bottom = walls->sides.bottom;
      box.layers = analysis->wall_layers;
      counted.wall_particles = sph::add_box_walls(model.particles, box, dx, h, 0, model.materials.front().density);
    }
  } else {
    throw SceneError({"section: missing (an SPH analysis needs a \"section\" or \"bodies\")"});
  }
  counted.memory_bytes = sph::estimate_memory_bytes(model.particles.size());
  if (size) *size = counted;
  return model;
}

}  // namespace coupling
