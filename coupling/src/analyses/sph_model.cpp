// Scene -> SPH particle model: the soil particles of a section or of the bodies of a particle scene, the wall
// particles, and the size checks that refuse a case before any particle is allocated.
#include "coupling/analyses/sph_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coupling/compare/sliding_mass.hpp"
#include "sph/engine/fill.hpp"
#include "sph/engine/kernel.hpp"
#include "sphslope/units.hpp"

namespace coupling {

namespace {

sph::soil::Material to_sph_material(const SoilMaterial& m) {
  sph::soil::Material out;
  out.name = m.name;
  out.density = m.density();
  out.youngs_modulus = m.youngs_modulus.value_or(0.0);
  out.poisson_ratio = m.poisson_ratio.value_or(0.0);
  out.cohesion = m.cohesion;
  out.friction_angle_deg = sphslope::degrees(m.friction_angle);
  out.dilatancy_angle_deg = sphslope::degrees(m.dilatancy_angle.value_or(0.0));
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
  const std::size_t bytes = sph::soil::estimate_memory_bytes(particles);
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
void plan_steps(const std::vector<sph::soil::Material>& materials, const sph::soil::Settings& settings, SphPlan& plan) {
  sph::soil::Model model;
  model.materials = materials;
  model.settings = settings;
  plan.p_wave_speed = 0.0;
  for (const auto& m : materials)
    plan.p_wave_speed = std::max(plan.p_wave_speed, sph::soil::MaterialConstants::from(m).sound_speed);
  plan.time_step = sph::soil::time_step_estimate(model);
  plan.planned_steps = settings.end_time / plan.time_step;
}

}  // namespace

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
  std::vector<sph::soil::Material> materials;
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
    double area = 0.0;
    for (const auto& body : *scene.bodies) {
      area += polygon_area(body.polygon);
      materials.push_back(to_sph_material(body.material));
    }
    plan.soil_particles = particle_count(area / (dx * dx));
    if (scene.walls)
      plan.wall_particles = wall_estimate(scene.walls->x_max - scene.walls->x_min, scene.walls->height,
                                          scene.walls->sides, dx, analysis.wall_layers);
  } else {
    return std::nullopt;
  }
  if (materials.empty()) return std::nullopt;
  plan.memory_bytes = sph::soil::estimate_memory_bytes(plan.soil_particles + plan.wall_particles);
  plan_steps(materials, analysis.settings, plan);
  return plan;
}

std::vector<std::string> sph_refusals(const SphAnalysis& analysis, const SphPlan& plan) {
  std::vector<std::string> out;
  if (auto why = size_refusal(analysis, plan.soil_particles + plan.wall_particles)) out.push_back(*why);
  if (plan.planned_steps > analysis.max_steps) {
    // A whole number of steps, as a reader counts them (scientific notation only beyond what an integer holds).
    const double steps = std::ceil(plan.planned_steps);
    const std::string steps_text =
        steps < 1e18 ? std::to_string(static_cast<long long>(steps)) : format_number(steps);
    out.push_back("analyses.sph: the run needs about " + steps_text +
                  " time steps (P-wave speed " + format_number(plan.p_wave_speed) + " m/s, time step " +
                  format_number(plan.time_step) + " s for " + format_number(analysis.settings.end_time) +
                  " s), more than analyses.sph.max_steps = " + std::to_string(std::llround(analysis.max_steps)) +
                  "; the explicit step is bounded by the wave speed: use a smaller youngs_modulus_MPa "
                  "(quasi-static runs tolerate a softer soil), a shorter end_time_s, a larger particle_spacing_m, "
                  "or raise max_steps");
  }
  return out;
}

namespace {

sph::BoxWalls box_walls(double x_min, double x_max, double y_min, double height, const WallSides& sides, int layers) {
  sph::BoxWalls box;
  box.x_min = x_min;
  box.x_max = x_max;
  box.y_min = y_min;
  box.height = height;
  box.left = sides.left;
  box.right = sides.right;
  box.bottom = sides.bottom;
  box.layers = layers;
  return box;
}

// Whether the SPH analysis carries a section load: not listed in analyses.sph.ignore_loads.
bool sph_carries(const SphAnalysis& analysis, SectionLoadKind load) { return !ignores(analysis, load); }

// The density of a particle (kg/m^3): the saturated unit weight of its material / g below the piezometric line
// where the material has one and the SPH analysis carries the water, its unit weight / g elsewhere.
double particle_density(const SoilMaterial& material, const slope::Section& section, bool water_carried, double x,
                        double y) {
  if (water_carried && section.water && material.saturated_unit_weight &&
      y < slope::polyline_y(section.water->piezometric_line, x))
    return *material.saturated_unit_weight / standard_gravity;
  return material.density();
}

// A slope section: its soil on the cell-centred lattice and the walls of the section box.
void build_section_particles(const SceneSection& scene_section, const SphAnalysis& analysis, sph::soil::Model& model,
                             SphSize& counted) {
  const double dx = model.settings.particle_spacing, h = model.settings.smoothing_length();
  const auto& section = scene_section.section;
  double top = section.bottom_y;
  for (const auto& p : section.profile_lines.front().points) top = std::max(top, p.y);
  const double width = section.x_max() - section.x_min(), height = top - section.bottom_y;
  // Refuse before allocating anything per particle.
  const auto soil_estimate = particle_count(section_area(section) / (dx * dx));
  refuse_if_too_large(analysis, soil_estimate + wall_estimate(width, height, analysis.section_walls, dx, analysis.wall_layers));

  for (const auto& m : scene_section.materials) model.materials.push_back(to_sph_material(m));
  const SectionFill fill = fill_section(section, dx);
  model.particles.reserve(fill.points.size() + wall_estimate(width, height, analysis.section_walls, dx, analysis.wall_layers));
  const bool water_carried = sph_carries(analysis, SectionLoadKind::water);
  for (std::size_t i = 0; i < fill.points.size(); ++i) {
    const double density = particle_density(scene_section.materials[fill.materials[i]], section, water_carried,
                                            fill.points[i].x, fill.points[i].y);
    model.particles.add(fill.points[i].x, fill.points[i].y, density * dx * dx, density,
                        static_cast<std::uint16_t>(fill.materials[i]), sph::ParticleKind::material);
  }
  counted.soil_particles = fill.points.size();
  const sph::BoxWalls box = box_walls(section.x_min(), section.x_min() + dx * std::floor(width / dx + 1e-9),
                                      section.bottom_y, height, analysis.section_walls, analysis.wall_layers);
  if (box.left || box.right || box.bottom)
    counted.wall_particles = sph::add_box_walls(model.particles, box, dx, h, 0, model.materials.front().density);
}

// The soil of one body: its fill points (the lattice points strictly inside its polygon, or its rows).
std::size_t add_body(const ParticleBody& body, const sph::Point& anchor, sph::soil::Model& model) {
  const double dx = model.settings.particle_spacing;
  const auto points = body_fill_points(body, dx, anchor);
  model.materials.push_back(to_sph_material(body.material));
  return sph::add_soil(model.particles, points, dx, static_cast<std::uint16_t>(model.materials.size() - 1),
                       body.material.density());
}

// A particle scene: every body on one lattice, and the wall box when there is one.
void build_body_particles(const std::vector<ParticleBody>& bodies, const std::optional<WallBox>& walls,
                          const SphAnalysis& analysis, sph::soil::Model& model, SphSize& counted) {
  const double dx = model.settings.particle_spacing, h = model.settings.smoothing_length();
  double area = 0.0;
  for (const auto& body : bodies) area += polygon_area(body.polygon);
  std::size_t wall_count = 0;
  if (walls) wall_count = wall_estimate(walls->x_max - walls->x_min, walls->height, walls->sides, dx, analysis.wall_layers);
  refuse_if_too_large(analysis, particle_count(area / (dx * dx)) + wall_count);

  // Bodies share the lattice of the wall box (or of the first body's lower-left corner).
  sph::Point anchor{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  if (walls) {
    anchor = {walls->x_min, walls->bottom_y};
  } else {
    for (const auto& p : bodies.front().polygon) anchor = {std::min(anchor.x, p.x), std::min(anchor.y, p.y)};
  }
  for (const auto& body : bodies) counted.soil_particles += add_body(body, anchor, model);
  if (walls) {
    const sph::BoxWalls box =
        box_walls(walls->x_min, walls->x_max, walls->bottom_y, walls->height, walls->sides, analysis.wall_layers);
    counted.wall_particles = sph::add_box_walls(model.particles, box, dx, h, 0, model.materials.front().density);
  }
}

// The section's loads on the SPH model (sph/soil/loads.hpp), except those analyses.sph.ignore_loads leaves out: the
// piezometric line, k_h toward the lower end of the ground (the direction limit equilibrium slides) and k_v, the
// strip surcharges and the line loads on the ground's particles.
void apply_section_loads(const slope::Section& section, const SphAnalysis& analysis, sph::soil::Model& model) {
  if (section.water && sph_carries(analysis, SectionLoadKind::water)) {
    sph::soil::PiezometricLine line;
    for (const auto& p : section.water->piezometric_line) {
      line.x.push_back(p.x);
      line.y.push_back(p.y);
    }
    line.unit_weight = section.water->unit_weight;
    model.loads.water = line;
  }
  if (section.seismic_coefficient != 0.0 && sph_carries(analysis, SectionLoadKind::seismic))
    model.loads.seismic_coefficient = slope::facing_direction(section) * section.seismic_coefficient;
  if (sph_carries(analysis, SectionLoadKind::seismic))
    model.loads.vertical_seismic_coefficient = section.vertical_seismic_coefficient;
  const double dx = model.settings.particle_spacing;
  if (sph_carries(analysis, SectionLoadKind::surcharges))
    for (const auto& strip : section.surcharges)
      sph::soil::add_strip_load(model.particles, model.loads, strip.from_x, strip.to_x, strip.pressure, dx,
                          strip.pressure_end ? *strip.pressure_end : std::nan(""));
  if (sph_carries(analysis, SectionLoadKind::line_loads))
    for (const auto& load : section.line_loads)
      sph::soil::add_line_load(model.particles, model.loads, load.x, load.force_x, load.force_y, dx);
}

}  // namespace

sph::soil::Model build_sph_model(const Scene& scene, SphSize* size) {
  const std::optional<SphAnalysis>& analysis = scene.analyses.sph;
  if (!analysis) throw SceneError({"analyses.sph: missing (the scene asks for no SPH analysis)"});
  sph::soil::Model model;
  model.settings = analysis->settings;
  SphSize counted;
  if (scene.section) {
    build_section_particles(*scene.section, *analysis, model, counted);
    apply_section_loads(scene.section->section, *analysis, model);
  } else if (scene.bodies) {
    build_body_particles(*scene.bodies, scene.walls, *analysis, model, counted);
  } else {
    throw SceneError({"section: missing (an SPH analysis needs a \"section\" or \"bodies\")"});
  }
  counted.memory_bytes = sph::soil::estimate_memory_bytes(model.particles.size());
  if (size) *size = counted;
  return model;
}

}  // namespace coupling
