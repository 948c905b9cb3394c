#include "study_cases.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coupling/compare/comparison.hpp"
#include "coupling/scene/json_reader.hpp"
#include "coupling/analyses/sph_model.hpp"

namespace coupling::study_detail {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Nguyen, Bui & Fukagawa (2015), "Failure mechanism of true 2D granular flows", arXiv:1512.05180 (J. Chem. Eng.
// Jpn.): collapses of columns of aluminium rods (the material of Bui et al. 2008) on a rigid bed.
constexpr const char* true_2d_collapse_source =
    "Nguyen, Bui & Fukagawa (2015), Failure mechanism of true 2D granular flows, arXiv:1512.05180: aluminium-rod "
    "columns (the material of Bui et al. 2008); h_f/h_0 = 1 for a < 0.65, h_0/h_f = 1.42 a^(2/3) above; "
    "(d - d_0)/d_0 = 3.25 a^0.96 for 0.65 < a < 1.5 and 3.80 a^0.73 for a > 1.5";

// The dry collapse of the WC-MPS (issue 12): the 2-D scaling laws of Lube et al. (2005) and Lajeunesse et al.
// (2005) as quoted second-hand (the quotes disagree: lambda 1.2 to 1.8).
constexpr const char* slump_law_source =
    "Lube et al. (2005) and Lajeunesse, Monnier & Homsy (2005, Phys. Fluids 17:103302), 2-D scaling laws as quoted "
    "second-hand: (L - l0)/l0 = lambda a for small a, lambda 1.2 to 1.8 "
    "(the quotes disagree; the reference takes the middle, 1.5; the band 1.2-1.8 is L = 0.172-0.208 m for the "
    "seed's column, a = 0.6, l0 = 0.1 m); the column's top corner "
    "stays in place, so the height at the wall is h0, for a below about 0.7";
constexpr double slump_lambda = 1.5, slump_max_aspect = 0.7;

double polygon_min(const std::vector<slope::Point>& polygon, double slope::Point::*coordinate) {
  double v = std::numeric_limits<double>::infinity();
  for (const auto& p : polygon) v = std::min(v, p.*coordinate);
  return v;
}
double polygon_max(const std::vector<slope::Point>& polygon, double slope::Point::*coordinate) {
  double v = -std::numeric_limits<double>::infinity();
  for (const auto& p : polygon) v = std::max(v, p.*coordinate);
  return v;
}

double max_depth_below(const Polyline& ground, const Polyline& surface) {
  double depth = nan;
  for (const auto& p : surface) {
    const double d = polyline_height(ground, p.x) - p.y;
    if (std::isfinite(d) && !(d <= depth)) depth = d;
  }
  return depth;
}

CaseSetup slope_case(const Scene& scene) {
  CaseSetup setup;
  setup.kind = CaseKind::slope_failure_surface;
  setup.kind_key = "slope_failure_surface";
  const slope::Section& section = scene.section->section;
  setup.ground = section.profile_lines.front().points;
  const LemAnalysis analysis = scene.analyses.lem ? *scene.analyses.lem : default_lem_analysis();
  const slope::SearchResult lem = slope::search_critical(section, {slope::Method::bishop}, analysis.search);
  if (lem.methods.empty() || !lem.methods.front().mass || !lem.methods.front().result.factor_of_safety)
    throw SceneError({"study: the limit-equilibrium search found no Bishop critical circle to measure the SPH "
                      "surface against (" + (lem.methods.empty() ? lem.error : lem.methods.front().result.error) +
                      ")"});
  setup.lem_reference = lem.methods.front();
  const slope::SlipMass& mass = *setup.lem_reference->mass;
  double y_min = std::numeric_limits<double>::infinity(), y_max = -y_min;
  for (const auto& p : setup.ground) {
    y_min = std::min(y_min, p.y);
    y_max = std::max(y_max, p.y);
  }
  const double height = y_max - y_min;
  const double lem_depth = max_depth_below(setup.ground, lem_surface_polyline(mass));
  const std::string source = "the limit-equilibrium critical circle of this program (Bishop simplified, automatic "
                             "search of analyses.lem), validated in docs/validation.md";
  const std::string by_height = "|value - reference| / H, H = " + format_number(height) + " m (slope height)";
  setup.quantities = {
      {"entry_x_m", "x where the SPH failure surface enters the ground behind the crest (m)", mass.entry.x, source,
       "LEM Bishop circle", by_height, height},
      {"exit_x_m", "x where the SPH failure surface leaves the ground near the toe (m)", mass.exit.x, source,
       "LEM Bishop circle", by_height, height},
      {"max_depth_m", "largest vertical depth of the SPH failure surface below the initial ground (m)", lem_depth,
       source, "LEM Bishop circle", "|value - reference| / reference", lem_depth},
      {"sliding_mass_iou", "intersection over union of the SPH and LEM sliding masses (-)", 1.0,
       "identical sliding masses (IoU = 1) with the Bishop critical circle", "LEM Bishop mass", "1 - value", 1.0},
  };
  setup.parameters = {{"slope_height_m", height},
                      {"lem_method", "bishop"},
                      {"lem_factor_of_safety", *setup.lem_reference->result.factor_of_safety},
                      {"lem_circle", {{"center_m", {mass.circle.xc, mass.circle.yc}},
                                      {"radius_m", mass.circle.radius},
                                      {"entry_m", {mass.entry.x, mass.entry.y}},
                                      {"exit_m", {mass.exit.x, mass.exit.y}}}}};
  return setup;
}

// The elastic-column reference of a rectangular body [x0, x1] x [y0, y0 + height] (setup's body filled in).
CaseSetup elastic_column_case(CaseSetup setup, const Scene& scene, double x0, double x1, double y0, double height) {
  const WallBox* box = scene.walls ? &*scene.walls : nullptr;
  const std::optional<SphAnalysis>& analysis = scene.analyses.sph;
  const double length = x1 - x0;
  setup.kind = CaseKind::elastic_column;
  setup.kind_key = "elastic_column";
  if (!box || !box->sides.left || !box->sides.right || !box->sides.bottom ||
      std::fabs(box->x_min - x0) > 1e-9 || std::fabs(box->x_max - x1) > 1e-9 || std::fabs(box->bottom_y - y0) > 1e-9)
    throw SceneError({"study: walls: the elastic-column reference (closed-form stress of a laterally confined "
                      "column) needs left, right and bottom walls touching the column (walls.x_range_m = [" +
                      format_number(x0) + ", " + format_number(x1) + "], bottom_y_m = " + format_number(y0) + ")"});
  if (analysis->settings.wall_slip != sph::soil::WallSlip::free_slip)
    throw SceneError({"study: analyses.sph.walls.slip: the elastic-column reference needs frictionless walls "
                      "(\"free_slip\"); with no-slip walls the closed form does not hold"});
  const double k0 = setup.poisson_ratio / (1.0 - setup.poisson_ratio);
  const std::string source =
      "closed form of a laterally confined (oedometric) elastic column under its own weight: sigma_yy = -rho g d, "
      "sigma_xx = nu/(1 - nu) sigma_yy (d = initial depth below the top)";
  const std::string rms =
      "root-mean-square over the particles between 0.2 H and 0.8 H of depth of (SPH - closed form), divided by the "
      "root-mean-square of the closed form";
  setup.quantities = {
      {"sigma_yy_error", "relative error of the vertical stress sigma_yy (-)", std::nullopt, source, "closed form", rms, 1.0},
      {"sigma_xx_error", "relative error of the horizontal stress sigma_xx (-)", std::nullopt, source, "closed form", rms,
       1.0},
  };
  setup.parameters = {{"column_height_m", height}, {"column_width_m", length}, {"density_kg_m3", setup.density},
                      {"poisson_ratio", setup.poisson_ratio}, {"k0", k0},
                      {"gravity_m_s2", std::hypot(analysis->settings.gravity_x, analysis->settings.gravity_y)}};
  return setup;
}

// The column-collapse reference of a rectangular body [x0, x0 + length] x [y0, y0 + height] (setup's body filled
// in).
CaseSetup column_collapse_case(CaseSetup setup, const Scene& scene, double x0, double y0, double length, double height) {
  const WallBox* box = scene.walls ? &*scene.walls : nullptr;
  setup.kind = CaseKind::column_collapse;
  setup.kind_key = "column_collapse";
  if (!box || !box->sides.bottom || !box->sides.left || std::fabs(box->x_min - x0) > 1e-9 ||
      std::fabs(box->bottom_y - y0) > 1e-9)
    throw SceneError({"study: walls: the column-collapse reference needs a floor and a back wall at the column's "
                      "left face (walls.x_range_m starting at " + format_number(x0) + ", bottom_y_m = " +
                      format_number(y0) + ", sides left and bottom)"});
  const double a = height / length;
  const double final_height = a < 0.65 ? height : height / (1.42 * std::pow(a, 2.0 / 3.0));
  const double runout_ratio = a < 1.5 ? 3.25 * std::pow(a, 0.96) : 3.80 * std::pow(a, 0.73);
  const double final_length = length * (1.0 + runout_ratio);
  const std::string extrapolated =
      a < 0.65 ? " (a = " + format_number(a) + " is below the fitted range 0.65 < a < 1.5: the run-out law is "
                 "extrapolated)" : "";
  setup.quantities = {
      {"final_length_m", "distance from the back wall to the front of the deposit, d (m)", final_length,
       std::string(true_2d_collapse_source) + extrapolated, "true-2-D experiments (Nguyen et al. 2015)",
       "|value - reference| / reference", final_length},
      {"final_height_m", "final height of the deposit, h_f (m)", final_height, true_2d_collapse_source,
       "true-2-D experiments (Nguyen et al. 2015)", "|value - reference| / reference", final_height},
  };
  setup.parameters = {{"initial_length_m", length}, {"initial_height_m", height}, {"aspect_ratio", a}};
  return setup;
}

CaseSetup particle_case(const Scene& scene) {
  const std::optional<std::vector<ParticleBody>>& bodies = scene.bodies;
  if (bodies->size() != 1)
    throw SceneError({"study: bodies: the column references need exactly one body (got " +
                      std::to_string(bodies->size()) + ")"});
  const ParticleBody& body = bodies->front();
  CaseSetup setup;
  setup.body_polygon = body.polygon;
  setup.density = body.material.density();
  setup.poisson_ratio = body.material.poisson_ratio.value_or(0.0);
  const double x0 = polygon_min(body.polygon, &slope::Point::x), x1 = polygon_max(body.polygon, &slope::Point::x);
  const double y0 = polygon_min(body.polygon, &slope::Point::y), y1 = polygon_max(body.polygon, &slope::Point::y);
  const double length = x1 - x0, height = y1 - y0;
  const double area = [&] {
    double a = 0.0;
    for (std::size_t k = 0; k < body.polygon.size(); ++k) {
      const auto& p = body.polygon[k];
      const auto& q = body.polygon[(k + 1) % body.polygon.size()];
      a += p.x * q.y - q.x * p.y;
    }
    return std::fabs(0.5 * a);
  }();
  if (std::fabs(area - length * height) > 1e-6 * length * height)
    throw SceneError({"study: bodies[0].polygon_m: the column references need a rectangular column (axis-aligned "
                      "rectangle; got a polygon of area " + format_number(area) + " m2 in a " +
                      format_number(length) + " x " + format_number(height) + " m box)"});

  if (body.material.elastic) return elastic_column_case(std::move(setup), scene, x0, x1, y0, height);
  return column_collapse_case(std::move(setup), scene, x0, y0, length, height);
}

// Relative root-mean-square error of the closed-form stresses of a confined elastic column.
std::pair<double, double> column_stress_errors(const CaseSetup& setup, const ParticleSnapshot& p, double gravity) {
  const double top = polygon_max(setup.body_polygon, &slope::Point::y);
  const double bottom = polygon_min(setup.body_polygon, &slope::Point::y);
  const double height = top - bottom, k0 = setup.poisson_ratio / (1.0 - setup.poisson_ratio);
  double e_yy = 0, n_yy = 0, e_xx = 0, n_xx = 0;
  std::size_t used = 0;
  for (std::size_t i = 0; i < p.y0.size() && i < p.stress_yy.size(); ++i) {
    const double depth = top - p.y0[i];
    if (depth < 0.2 * height || depth > 0.8 * height) continue;
    const double exact_yy = -setup.density * gravity * depth, exact_xx = k0 * exact_yy;
    e_yy += (p.stress_yy[i] - exact_yy) * (p.stress_yy[i] - exact_yy);
    n_yy += exact_yy * exact_yy;
    e_xx += (p.stress_xx[i] - exact_xx) * (p.stress_xx[i] - exact_xx);
    n_xx += exact_xx * exact_xx;
    ++used;
  }
  if (used == 0 || !(n_yy > 0)) return {nan, nan};
  return {std::sqrt(e_yy / n_yy), n_xx > 0 ? std::sqrt(e_xx / n_xx) : nan};
}

std::optional<double> finite(double v) { return std::isfinite(v) ? std::optional<double>(v) : std::nullopt; }

// The WC-MPS dry collapse: one granular block against the tank's left wall, on its floor.
CaseSetup mps_case(const Scene& scene) {
  const MpsAnalysis& a = *scene.analyses.mps;
  const bool one_granular_block =
      a.blocks.size() == 1 &&
      a.materials[a.block_material[0]].material.type == sph::mps::Material::Type::granular;
  if (!one_granular_block)
    throw SceneError({"study: analyses.mps: the dry-collapse reference needs exactly one block, of a granular "
                      "material"});
  const TankRectangle& b = a.blocks[0];
  if (std::fabs(b.x_min - a.tank.x_min) > 1e-9 || std::fabs(b.y_min - a.tank.y_min) > 1e-9)
    throw SceneError({"study: analyses.mps.blocks[0]: the dry-collapse reference needs the column against the "
                      "tank's left wall and on its floor (x_min_m = " + format_number(a.tank.x_min) +
                      ", y_min_m = " + format_number(a.tank.y_min) + ")"});
  const double length = b.x_max - b.x_min, height = b.y_max - b.y_min, aspect = height / length;
  if (!(aspect < slump_max_aspect))
    throw SceneError({"study: analyses.mps.blocks[0]: aspect ratio h0/l0 = " + format_number(aspect) +
                      ": the dry-collapse reference (the height at the wall stays h0) covers a < 0.7"});
  CaseSetup setup;
  setup.kind = CaseKind::mps_dry_collapse;
  setup.kind_key = "mps_dry_collapse";
  const double runout = length * (1.0 + slump_lambda * aspect);
  setup.quantities = {
      {"runout_m", "distance from the left wall to the deposit's front, L (m)", runout, slump_law_source,
       "2-D scaling laws (Lube, Lajeunesse 2005)", "|value - reference| / reference", runout},
      {"wall_height_m", "height of the deposit at the left wall (m)", height, slump_law_source,
       "2-D scaling laws (Lube, Lajeunesse 2005)", "|value - reference| / reference", height},
  };
  setup.parameters = {{"initial_length_m", length}, {"initial_height_m", height}, {"aspect_ratio", aspect},
                      {"wall_x_m", a.tank.x_min}, {"lambda", slump_lambda}};
  return setup;
}

}  // namespace

CaseSetup setup_case(const Scene& scene) {
  if (scene.analyses.mps) return mps_case(scene);
  if (scene.analyses.isph) return isph_dam_break_case(scene);
  if (!scene.analyses.sph)
    throw SceneError({"study: the scene has no analyses.sph, analyses.mps or analyses.isph (the study runs it at "
                      "each --spacings value, replacing its particle_spacing_m)"});
  if (scene.section) return slope_case(scene);
  if (scene.bodies) return particle_case(scene);
  throw SceneError({"study: the scene has neither a section nor bodies"});
}

Scene scene_at_spacing(const Scene& scene, double spacing) {
  Scene out = scene_with_spacing(scene, spacing);
  if (out.analyses.mps || out.analyses.isph || !out.section) return out;
  // A slope: the SPH surface is measured against limit equilibrium's, so both run ("lem": {} and "compare": {} when
  // the scene has none); a study measures the collapse, not the strength-reduction FS.
  if (!out.analyses.lem) out.analyses.lem = lem_analysis_of_empty_block();
  if (!out.analyses.compare) out.analyses.compare = ComparisonOptions{};
  out.analyses.srm.reset();
  return out;
}

std::vector<std::optional<double>> read_values(const CaseSetup& setup, const RunResults& run,
                                               const std::filesystem::path& folder) {
  std::vector<std::optional<double>> values(setup.quantities.size());
  switch (setup.kind) {
    case CaseKind::slope_failure_surface: {
      const ComparisonResult* c = run.comparison_result();
      if (!c) break;
      if (c->sph.entry) values[0] = c->sph.entry->x;
      if (c->sph.exit) values[1] = c->sph.exit->x;
      if (!c->sph.band.points.empty()) values[2] = finite(max_depth_below(setup.ground, c->sph.band.points));
      if (const MethodComparison* bishop = c->find("bishop"); bishop && bishop->has_geometry)
        values[3] = finite(bishop->intersection_over_union);
      break;
    }
    case CaseKind::elastic_column: {
      if (!run.sph_final_state) break;
      const double gravity = setup.parameters["gravity_m_s2"].get<double>();
      const auto [yy, xx] = column_stress_errors(setup, *run.sph_final_state, gravity);
      values[0] = finite(yy);
      values[1] = finite(xx);
      break;
    }
    case CaseKind::column_collapse:
      if (run.sph && run.sph->result && run.sph->result->deposit) {
        values[0] = run.sph->result->deposit->final_length_m;
        values[1] = run.sph->result->deposit->final_height_m;
      }
      break;
    case CaseKind::mps_dry_collapse:
      if (run.mps && run.mps->result) {
        values[0] = run.mps->result->front_end - setup.parameters["wall_x_m"].get<double>();
        values[1] = run.mps->result->wall_height_end;
      }
      break;
    case CaseKind::isph_dam_break:
      return isph_dam_break_values(setup, folder);
  }
  return values;
}

double relative_error(const Quantity& quantity, double value) {
  if (!quantity.reference) return std::fabs(value);
  return std::fabs(value - *quantity.reference) / quantity.error_scale;
}

}  // namespace coupling::study_detail
