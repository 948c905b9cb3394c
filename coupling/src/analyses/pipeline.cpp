#include "coupling/analyses/pipeline.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <ostream>
#include <system_error>

#include "sph/engine/atomic_file.hpp"
#include "coupling/compare/comparison.hpp"
#include "coupling/output/figures.hpp"
#include "coupling/output/report.hpp"
#include "coupling/analyses/sph_model.hpp"
#include "coupling/analyses/sph_stage.hpp"
#include "coupling/analyses/strength_reduction.hpp"

namespace coupling {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// What one analysis stage hands back to the workflow.
struct StageOutcome {
  ExitStatus status = ExitStatus::ok;
  std::vector<std::string> errors;  // invalid input: JSON-path messages; failed: reasons
};

StageOutcome run_lem_stage(const Scene& scene, const LemAnalysis& analysis, WorkflowResult& out) {
  StageOutcome outcome;
  const Clock::time_point start = Clock::now();
  const slope::Section& section = scene.section->section;
  slope::SearchResult result;
  try {
    result = slope::search_critical(section, analysis.methods, analysis.search);
  } catch (const std::exception& error) {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back(std::string("lem: the limit-equilibrium search failed: ") + error.what());
    out.report["lem"] = {{"error", outcome.errors.back()}};
    out.report["timing_s"]["lem"] = seconds_since(start);
    return outcome;
  }
  out.report["timing_s"]["lem"] = seconds_since(start);

  if (!result.error.empty()) {
    if (analysis.has_search_limits) {
      // The user's limits admit no slip circle: that is a fault of the input, reported at its JSON path.
      outcome.status = ExitStatus::invalid_input;
      outcome.errors.push_back("analyses.lem.search: the search limits admit no valid slip circle (" + result.error +
                               "); widen entry_x_m, exit_x_m, radius_m or centre_grid, or leave \"search\" out "
                               "for the automatic search");
      return outcome;
    }
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back("lem: the automatic search found no valid slip circle: " + result.error);
  }
  out.report["lem"] = lem_report(section, analysis, result);
  if (outcome.status == ExitStatus::ok) {
    bool any = false;
    for (const slope::CriticalSurface& critical : result.methods) {
      any = any || (critical.mass && critical.result.factor_of_safety && std::isfinite(*critical.result.factor_of_safety));
    }
    if (!any) {
      outcome.status = ExitStatus::failed;
      outcome.errors.push_back("lem: no method converged on any slip surface (see lem.methods.*.error)");
    }
  }
  out.lem = std::move(result);
  return outcome;
}

StageOutcome run_sph(const Scene& scene, const WorkflowOptions& options, WorkflowResult& out,
                     std::optional<ParticleSnapshot>& final_state) {
  StageOutcome outcome;
  const Clock::time_point start = Clock::now();
  SphStageOptions sph_options;
  sph_options.output_dir = options.output_dir;
  sph_options.resume = options.resume;
  sph_options.log = options.log;
  SphStageResult result;
  try {
    result = run_sph_stage(scene, sph_options);
  } catch (const SceneError& error) {
    // Refused before it started (memory, particle or step limits; nothing to resume): a fault of the input.
    outcome.status = ExitStatus::invalid_input;
    outcome.errors = error.messages();
    return outcome;
  } catch (const std::exception& error) {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back(std::string("sph: ") + error.what());
    out.report["sph"] = {{"error", outcome.errors.back()}, {"stopped_because", "error"}};
    out.report["timing_s"]["sph"] = seconds_since(start);
    return outcome;
  }
  out.report["sph"] = result.report;
  out.report["timing_s"]["sph"] = seconds_since(start);
  if (!result.ok) {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back("sph: " + result.error);
  }
  // After a blow-up the particle state is the diverged one (non-finite or meaningless values): no comparison or
  // figure is drawn from it (the last good frame is in frames/).
  if (result.report.value("stopped_because", std::string()) != "blow_up") final_state = std::move(result.final_state);
  return outcome;
}

StageOutcome run_compare(const Scene& scene, WorkflowResult& out, const std::optional<ParticleSnapshot>& final_state,
                         std::optional<SphFailure>& failure) {
  StageOutcome outcome;
  const Clock::time_point start = Clock::now();
  if (!final_state || !out.lem || !scene.section) {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back("compare: needs both a finished SPH run and a limit-equilibrium result");
    out.report["comparison"] = {{"error", outcome.errors.back()}};
    return outcome;
  }
  const ComparisonOptions& options = *scene.analyses.compare;
  const slope::Section& section = scene.section->section;
  failure = extract_sph_failure(*final_state, section.profile_lines.front().points, options);
  out.report["comparison"] = comparison_report(section, *failure, *out.lem, options);
  // Loads SPH left out on request (analyses.sph.ignore_loads): the two surfaces answer different problems.
  for (const SectionLoad& load : loads_sph_leaves_out(scene)) {
    nlohmann::json& comparison = out.report["comparison"];
    comparison["verdict"] = comparison["verdict"].get<std::string>() + " Caution: the SPH run leaves out " +
                            load.name + " (" + load.path + "), the limit-equilibrium analysis includes it.";
  }
  if (options.acceptance) {
    const double spacing = out.report["sph"].value("particle_spacing_m", 0.0);
    const AcceptanceResult acceptance = evaluate_acceptance(*options.acceptance, out.report["comparison"], spacing);
    out.report["comparison"]["acceptance"] = acceptance_json(acceptance);
    if (!acceptance.accepted) {
      outcome.status = ExitStatus::not_accepted;
      outcome.errors = failed_criteria_lines(acceptance);
    }
  }
  out.report["timing_s"]["compare"] = seconds_since(start);
  return outcome;
}

// SPH factor of safety by strength reduction (analyses.srm), next to the LEM factors.
StageOutcome run_srm(const Scene& scene, const WorkflowOptions& options, WorkflowResult& out) {
  StageOutcome outcome;
  const Clock::time_point start = Clock::now();
  std::optional<double> bishop;
  nlohmann::json lem_fs = nlohmann::json::object();
  if (out.lem)
    for (const auto& critical : out.lem->methods)
      if (critical.mass && critical.result.factor_of_safety && std::isfinite(*critical.result.factor_of_safety)) {
        const std::string key(slope::method_key(critical.method));
        lem_fs[key] = *critical.result.factor_of_safety;
        if (key == "bishop") bishop = *critical.result.factor_of_safety;
      }
  try {
    const SrmOptions& srm = *scene.analyses.srm;
    const SrmResult result = run_strength_reduction(scene, srm, bishop, lem_fs, options.log);
    out.report["srm"] = result.report;
    if (!result.ok) {
      outcome.status = ExitStatus::failed;
      outcome.errors.push_back(result.report.value("error", std::string("srm: no factor of safety")));
    }
    if (options.log) {
      char line[200];
      const std::string lem_text = bishop ? format_number(*bishop) : std::string("-");
      if (result.bisection.bracketed)
        std::snprintf(line, sizeof line, "srm: FS_SPH = %.3f in [%.3f, %.3f]; LEM Bishop = %s\n",
                      result.bisection.factor_of_safety, result.bisection.lo, result.bisection.hi, lem_text.c_str());
      else
        std::snprintf(line, sizeof line, "srm: FS_SPH not bracketed; LEM Bishop = %s\n", lem_text.c_str());
      *options.log << line;
    }
  } catch (const SceneError& error) {
    outcome.status = ExitStatus::invalid_input;
    outcome.errors = error.messages();
    return outcome;
  } catch (const std::exception& error) {
    outcome.status = ExitStatus::failed;
    outcome.errors.push_back(std::string("srm: ") + error.what());
    out.report["srm"] = {{"error", outcome.errors.back()}};
  }
  out.report["timing_s"]["srm"] = seconds_since(start);
  return outcome;
}

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

}  // namespace

std::filesystem::path default_output_dir(const std::filesystem::path& scene_file) {
  return std::filesystem::path("runs") / scene_file.stem();
}

WorkflowResult run_scene(const Scene& scene, const WorkflowOptions& options) {
  const Clock::time_point start = Clock::now();
  WorkflowResult out;
  out.scene = scene;
  if (options.mode == Mode::check) {
    // A valid scene whose SPH run would be refused before starting (particle, memory or step limits) is reported
    // by "check" as well, with the same messages (estimated without building particles).
    if (scene.analyses.sph) {
      if (const auto plan = plan_sph(scene, *scene.analyses.sph)) {
        out.errors = sph_refusals(*scene.analyses.sph, *plan);
        if (!out.errors.empty()) out.status = ExitStatus::invalid_input;
      }
    }
    return out;
  }

  out.report = report_header(scene);
  out.report["timing_s"] = nlohmann::json::object();

  std::vector<std::string> requested;
  std::optional<LemAnalysis> lem = scene.analyses.lem;
  if (options.mode == Mode::lem) {
    if (!scene.section) {
      out.status = ExitStatus::invalid_input;
      out.errors.push_back("section: missing (sphslope lem needs a slope \"section\"; this is a particle scene)");
      out.report = nullptr;
      return out;
    }
    if (!lem) lem = default_lem_analysis();
    requested.push_back("lem");
  } else {
    if (lem) requested.push_back("lem");
    if (scene.analyses.sph) requested.push_back("sph");
    if (scene.analyses.compare) requested.push_back("compare");
    if (scene.analyses.srm) requested.push_back("srm");
  }
  out.report["analyses"] = requested;

  std::vector<std::string> failures;
  auto absorb = [&](StageOutcome&& stage) {
    if (stage.status == ExitStatus::invalid_input) {
      out.status = ExitStatus::invalid_input;
      out.errors = std::move(stage.errors);
      return false;
    }
    if (stage.status == ExitStatus::not_accepted) {
      if (out.status == ExitStatus::ok) out.status = ExitStatus::not_accepted;
      out.rejections.insert(out.rejections.end(), stage.errors.begin(), stage.errors.end());
    }
    if (stage.status == ExitStatus::failed) {
      out.status = ExitStatus::failed;
      failures.insert(failures.end(), stage.errors.begin(), stage.errors.end());
    }
    return true;
  };

  // LEM first: it is fast and can still reject the input (search limits without a valid circle) before anything
  // is written.
  if (lem && !absorb(run_lem_stage(scene, *lem, out))) {
    out.report = nullptr;
    return out;
  }
  std::optional<ParticleSnapshot> final_state;
  std::optional<SphFailure> failure;
  if (options.mode == Mode::run) {
    if (scene.analyses.sph && !absorb(run_sph(scene, options, out, final_state))) {
      out.report = nullptr;
      return out;
    }
    if (scene.analyses.compare) absorb(run_compare(scene, out, final_state, failure));
    if (scene.analyses.srm && !absorb(run_srm(scene, options, out))) {
      out.report = nullptr;
      return out;
    }
  }
  if (options.output_dir && options.mode != Mode::check) {
    try {
      write_figures(scene, out, final_state, failure, *options.output_dir, out.report);
    } catch (const std::exception& error) {
      failures.push_back(std::string("cannot write the figures: ") + error.what());
      out.status = ExitStatus::failed;
    }
  }
  if (out.report.contains("comparison") && out.report["comparison"].contains("verdict") && options.log)
    *options.log << "comparison: " << out.report["comparison"]["verdict"].get<std::string>() << "\n";

  out.report["status"] = !failures.empty() ? "failed" : out.status == ExitStatus::not_accepted ? "not_accepted" : "ok";
  out.report["errors"] = failures;
  out.errors = failures;
  out.report["timing_s"]["total"] = seconds_since(start);

  if (options.output_dir) {
    try {
      std::filesystem::create_directories(*options.output_dir);
      const std::filesystem::path file = *options.output_dir / "report.json";
      sph::write_file_atomically(file, report_text(out.report));
      out.report_file = file;
    } catch (const std::exception& error) {
      out.status = ExitStatus::failed;
      out.errors.push_back(std::string("cannot write the report: ") + error.what());
    }
  }
  out.sph_final_state = std::move(final_state);
  return out;
}

WorkflowResult run_scene_file(const std::filesystem::path& scene_file, const WorkflowOptions& options) {
  const Clock::time_point start = Clock::now();
  Scene scene;
  try {
    scene = load_scene(scene_file);
  } catch (const SceneError& error) {
    WorkflowResult out;
    out.status = ExitStatus::invalid_input;
    out.errors = error.messages();
    return out;
  }
  const double load_seconds = seconds_since(start);
  WorkflowResult out = run_scene(scene, options);
  if (out.report.is_object() && out.report.contains("timing_s")) {
    out.report["timing_s"]["load"] = load_seconds;
    out.report["timing_s"]["total"] = seconds_since(start);
    // Rewrite with the load time included (same atomic write; cheap).
    if (out.report_file) {
      try {
        sph::write_file_atomically(*out.report_file, report_text(out.report));
      } catch (const std::exception& error) {
        out.status = ExitStatus::failed;
        out.errors.push_back(std::string("cannot write the report: ") + error.what());
      }
    }
  }
  return out;
}

std::string lem_table(const LemAnalysis& analysis, const slope::SearchResult& result) {
  std::string text;
  char line[512];
  std::snprintf(line, sizeof line, "%-27s %7s  %-19s %8s  %-17s %-17s\n", "method", "FS", "centre (x, y) m",
                "radius m", "entry (x, y) m", "exit (x, y) m");
  text += line;
  for (slope::Method method : analysis.methods) {
    const slope::CriticalSurface* found = nullptr;
    for (const slope::CriticalSurface& critical : result.methods) {
      if (critical.method == method) found = &critical;
    }
    const std::string key(slope::method_key(method));
    if (found == nullptr || !found->mass || !found->result.factor_of_safety) {
      const std::string why = found == nullptr ? result.error : found->result.error;
      std::snprintf(line, sizeof line, "%-27s %7s  %s\n", key.c_str(), "-",
                    ("failed: " + (why.empty() ? std::string("no converged surface") : why)).c_str());
      text += line;
      continue;
    }
    const slope::SlipMass& mass = *found->mass;
    char centre[64], entry[64], exit[64];
    std::snprintf(centre, sizeof centre, "(%.2f, %.2f)", mass.circle.xc, mass.circle.yc);
    std::snprintf(entry, sizeof entry, "(%.2f, %.2f)", mass.entry.x, mass.entry.y);
    std::snprintf(exit, sizeof exit, "(%.2f, %.2f)", mass.exit.x, mass.exit.y);
    std::snprintf(line, sizeof line, "%-27s %7.3f  %-19s %8.2f  %-17s %-17s\n", key.c_str(),
                  *found->result.factor_of_safety, centre, mass.circle.radius, entry, exit);
    text += line;
  }
  std::snprintf(line, sizeof line, "search: %ld trial surfaces in %.3f s\n", result.trial_surfaces, result.seconds);
  text += line;
  // No trailing blanks at the ends of the padded lines.
  std::string trimmed;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    std::string row = text.substr(start, end - start);
    row.erase(row.find_last_not_of(' ') + 1);
    trimmed += row + "\n";
    start = end + 1;
  }
  return trimmed;
}

}  // namespace coupling
