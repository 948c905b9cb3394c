// The figures of a run: figures/section.svg, and figures/fs_map.svg after a limit-equilibrium search (with
// figures/newmark_record.svg and newmark_displacement.svg after Newmark's displacement, probabilistic_histogram.svg and
// probabilistic_cdf.svg after a probabilistic analysis).
#include "coupling/output/run_figures.hpp"

#include <cstdio>

#include "coupling/compare/comparison.hpp"
#include "coupling/output/figures.hpp"
#include "coupling/output/newmark_figures.hpp"
#include "coupling/output/probabilistic_output.hpp"
#include "sph/engine/atomic_file.hpp"

namespace coupling {

namespace {

// The safety map of the search for the scene's map method, with that method's critical surfaces.
FsMapFigureData fs_map_data(const LemAnalysis& analysis, const LemStageResult& lem, const slope::Section& section) {
  FsMapFigureData data;
  data.section = &section;
  data.trials = &lem.search.fs_map;
  data.scale_max = analysis.fs_map_scale_max;
  const slope::Method method = analysis.search.fs_map_method.value_or(slope::Method::bishop);
  const std::string key(slope::method_key(method));
  char label[128];
  for (const auto& critical : lem.search.methods)
    if (critical.method == method && critical.mass && critical.result.factor_of_safety) {
      std::snprintf(label, sizeof label, "critical circle, FS = %.3f", *critical.result.factor_of_safety);
      data.critical_circle = NamedSurface{label, lem_surface_polyline(*critical.mass)};
    }
  if (lem.noncircular)
    for (const auto& s : lem.noncircular->methods)
      if (s.method == method && s.searched && !s.from_circle && s.mass && s.result.factor_of_safety) {
        std::snprintf(label, sizeof label, "critical non-circular surface, FS = %.3f", *s.result.factor_of_safety);
        data.critical_noncircular = NamedSurface{label, s.mass->surface};
      }
  data.title = "Safety map of the search (" + key + "): lowest FS of the " + std::to_string(lem.search.fs_map.size()) +
               " trial circles through each point";
  return data;
}

// The probabilistic analysis's pair of figures and the sensitivity's spider plot.
void write_variation_figures(const LemStageResult& lem, const std::filesystem::path& figures,
                             std::vector<std::string>& written) {
  if (lem.probabilistic && lem.probabilistic->error.empty()) {
    sph::write_file_atomically(figures / "probabilistic_histogram.svg",
                               probabilistic_histogram_svg(*lem.probabilistic, "Probabilistic analysis"));
    sph::write_file_atomically(figures / "probabilistic_cdf.svg",
                               probabilistic_cdf_svg(*lem.probabilistic, "Probabilistic analysis"));
    written.push_back("figures/probabilistic_histogram.svg");
    written.push_back("figures/probabilistic_cdf.svg");
  }
  if (lem.sensitivity && lem.sensitivity->error.empty() && lem.analysis.sensitivity) {
    sph::write_file_atomically(figures / "sensitivity.svg",
                               sensitivity_svg(*lem.analysis.sensitivity, *lem.sensitivity, "Sensitivity"));
    written.push_back("figures/sensitivity.svg");
  }
}

}  // namespace

// figures/section.svg (and figures/fs_map.svg after a limit-equilibrium search) in the output folder.
std::optional<std::vector<std::string>> write_figures(const Scene& scene, const RunResults& results,
                                                      const std::filesystem::path& dir) {
  const std::optional<ParticleSnapshot>& final_state = results.sph_final_state;
  const std::optional<SphFailure>& failure = results.sph_failure;
  const LemStageResult* lem = results.lem_result();
  const slope::Section* section = scene.section ? &scene.section->section : nullptr;
  if (!section && !final_state) return std::nullopt;
  const std::filesystem::path figures = dir / "figures";
  std::filesystem::create_directories(figures);
  std::vector<std::string> written;

  SectionFigureData data;
  data.title = scene.name;
  data.section = section;
  if (final_state && !final_state->x.empty()) data.particles = &*final_state;
  if (lem) {
    for (const auto& critical : lem->search.methods) {
      if (!critical.mass || !critical.result.factor_of_safety) continue;
      char label[96];
      std::snprintf(label, sizeof label, "%s FS = %.3f", std::string(slope::method_key(critical.method)).c_str(),
                    *critical.result.factor_of_safety);
      data.lem_surfaces.push_back({label, lem_surface_polyline(*critical.mass)});
    }
  }
  if (lem && lem->noncircular) {
    for (const auto& s : lem->noncircular->methods) {
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
  if (lem && section && lem->probabilistic && lem->analysis.probabilistic &&
      lem->analysis.probabilistic->mode == ProbabilisticMode::overall) {
    data.sample_surfaces = sample_surface_lines(*section, *lem->probabilistic, lem->analysis.search.slicing);
    data.sample_surfaces_label = "critical circles of the first " + std::to_string(data.sample_surfaces.size()) +
                                 " samples (" + std::string(slope::method_key(lem->analysis.probabilistic->method)) + ")";
  }
  sph::write_file_atomically(figures / "section.svg", section_figure_svg(data));
  written.push_back("figures/section.svg");

  if (lem && section && !lem->search.fs_map.empty() && scene.analyses.lem) {
    sph::write_file_atomically(figures / "fs_map.svg", fs_map_svg(fs_map_data(*scene.analyses.lem, *lem, *section)));
    written.push_back("figures/fs_map.svg");
  }
  if (lem && lem->newmark && lem->analysis.acceleration_record && lem->critical_coefficient) {
    const AccelerationRecordInput& record = *lem->analysis.acceleration_record;
    sph::write_file_atomically(figures / "newmark_record.svg",
                               newmark_record_svg(record, *lem->critical_coefficient->coefficient, scene.name));
    sph::write_file_atomically(figures / "newmark_displacement.svg",
                               newmark_displacement_svg(record, *lem->newmark, scene.name));
    written.push_back("figures/newmark_record.svg");
    written.push_back("figures/newmark_displacement.svg");
  }
  if (lem) write_variation_figures(*lem, figures, written);
  return written;
}

}  // namespace coupling
