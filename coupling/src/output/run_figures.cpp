// The figures of a run: figures/section.svg, and figures/fs_map.svg after a limit-equilibrium search.
#include "coupling/output/run_figures.hpp"

#include <cstdio>

#include "coupling/compare/comparison.hpp"
#include "coupling/output/figures.hpp"
#include "sph/engine/atomic_file.hpp"

namespace coupling {

// figures/section.svg (and figures/fs_map.svg after a limit-equilibrium search) in the output folder.
void write_figures(const Scene& scene, const WorkflowResult& out, const std::optional<ParticleSnapshot>& final_state,
                   const std::optional<SphFailure>& failure, const std::filesystem::path& dir,
                   nlohmann::json& report) {
  const slope::Section* section = scene.section ? &scene.section->section : nullptr;
  if (!section && !final_state) return;
  const std::filesystem::path figures = dir / "figures";
  std::filesystem::create_directories(figures);
  nlohmann::json written = nlohmann::json::array();

  SectionFigureData data;
  data.title = scene.name;
  data.section = section;
  if (final_state && !final_state->x.empty()) data.particles = &*final_state;
  if (out.lem) {
    for (const auto& critical : out.lem->methods) {
      if (!critical.mass || !critical.result.factor_of_safety) continue;
      char label[96];
      std::snprintf(label, sizeof label, "%s FS = %.3f", std::string(slope::method_key(critical.method)).c_str(),
                    *critical.result.factor_of_safety);
      data.lem_surfaces.push_back({label, lem_surface_polyline(*critical.mass)});
    }
  }
  if (out.lem_noncircular) {
    for (const auto& s : out.lem_noncircular->methods) {
      if (!s.mass || !s.result.factor_of_safety || s.from_circle || !s.searched) continue;
      char label[96];
      std::snprintf(label, sizeof label, "%s non-circular FS = %.3f", std::string(slope::method_key(s.method)).c_str(),
                    *s.result.factor_of_safety);
      data.lem_surfaces.push_back({label, s.mass->surface});
    }
  }
  if (failure) {
    data.final_ground = failure->final_ground;
    if (failure->band.points.size() >= 2) {
      char label[96];
      std::snprintf(label, sizeof label, "SPH surface (plastic strain >= %g)", failure->band.plastic_strain_threshold);
      data.sph_surface = NamedSurface{label, failure->band.points};
    }
    if (failure->fitted_circle && failure->band.points.size() >= 2)
      data.sph_fitted_circle = NamedSurface{
          "circle fitted to the SPH surface",
          circle_arc(failure->fitted_circle->circle, failure->band.points.front().x, failure->band.points.back().x)};
  }
  sph::write_file_atomically(figures / "section.svg", section_figure_svg(data));
  written.push_back("figures/section.svg");

  if (out.lem && section && !out.lem->fs_map.empty()) {
    std::optional<slope::Circle> critical;
    for (const auto& c : out.lem->methods)
      if (c.mass && c.result.factor_of_safety) {
        critical = c.mass->circle;
        break;
      }
    const std::string method =
        out.lem->methods.empty() ? std::string() : std::string(slope::method_key(out.lem->methods.front().method));
    sph::write_file_atomically(figures / "fs_map.svg",
                 fs_map_svg(*section, out.lem->fs_map, critical, "Factor-of-safety map of the search (" + method + ")"));
    written.push_back("figures/fs_map.svg");
  }
  report["figures"] = written;
}

}  // namespace coupling
