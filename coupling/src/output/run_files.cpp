// A run of a scene and its run folder (coupling/output/run_files.hpp): the analyses into typed results, then the
// files, written from those results alone.
#include "coupling/output/run_files.hpp"
#include "coupling/output/probabilistic_output.hpp"

#include <cmath>
#include <exception>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "coupling/analyses/stage.hpp"
#include "coupling/output/comparison_report.hpp"
#include "coupling/output/isph_figures.hpp"
#include "coupling/output/coupled_report.hpp"
#include "coupling/output/isph_report.hpp"
#include "coupling/scene/json_text.hpp"
#include "coupling/output/mps_report.hpp"
#include "coupling/output/report.hpp"
#include "coupling/output/report_html.hpp"
#include "coupling/output/run_figures.hpp"
#include "coupling/output/sph_report.hpp"
#include "coupling/output/srm_report.hpp"
#include "sph/engine/atomic_file.hpp"

namespace coupling {

namespace {

using nlohmann::json;

// Each isph snapshot drawn into dir/figures while the run goes.
SnapshotFigure snapshot_drawer(const std::filesystem::path& dir, const std::string& title) {
  return [figures = dir / "figures", title](double requested, const IsphSnapshot& snapshot) {
    std::filesystem::create_directories(figures);
    const std::string name = snapshot_file_name(requested);
    sph::write_file_atomically(figures / name, isph_snapshot_svg(snapshot, title));
    return "figures/" + name;
  };
}

// figures/isph_gauges.svg (with gauges) and figures/isph_front.svg (with the front), appended to result.figures.
void write_isph_figures(const Scene& scene, const std::filesystem::path& dir, IsphStageResult& result) {
  const IsphAnalysis& a = *scene.analyses.isph;
  std::filesystem::create_directories(dir / "figures");
  if (!a.monitors.gauges.empty()) {
    sph::write_file_atomically(dir / "figures" / "isph_gauges.svg",
                               isph_gauges_svg(result.monitors, a.monitors.gauges, a.monitors.still_water, scene.name));
    result.figures.push_back("figures/isph_gauges.svg");
  }
  if (!a.monitors.front) return;
  FrontFigureReferences references;
  references.far_wall_x = a.tank.x_max;
  const double g = std::hypot(a.settings.gravity_x, a.settings.gravity_y);
  if (const std::optional<FrontReference>& ref = a.outputs.front_reference) {
    if (!ref->data.empty()) {
      references.points = martin_moyce_points({ref->column_width, g, a.tank.x_min});
      references.points_label = "Martin & Moyce (1952), n^2 = 2, a = " + format_number(ref->column_width) + " m";
    }
    references.ritter_dam_x = ref->ritter_dam_x;
    references.ritter_depth = ref->ritter_depth;
    references.gravity = g;
  }
  sph::write_file_atomically(dir / "figures" / "isph_front.svg", isph_front_svg(result.monitors, references, scene.name));
  result.figures.push_back("figures/isph_front.svg");
}

// The files of the flows in a tank, before the report that lists them: monitors.csv and the isph figures, or the
// mps profiles. A failure to write them fails the stage, as a failure of the run would.
void write_tank_files(const Scene& scene, const std::filesystem::path& dir, RunResults& results) {
  if (results.isph && results.isph->result) {
    IsphStageResult& isph = *results.isph->result;
    try {
      sph::write_file_atomically(dir / "monitors.csv", monitors_csv(isph.monitors));
      write_isph_figures(scene, dir, isph);
    } catch (const std::exception& error) {
      results.isph->error = std::string("isph: ") + error.what();
      results.isph->result.reset();
      results.failures.push_back(results.isph->error);
    }
  }
  if (results.coupled && results.coupled->result) {
    CoupledStageResult& coupled = *results.coupled->result;
    try {
      sph::write_file_atomically(dir / "monitors.csv", monitors_csv(coupled.monitors));
      sph::write_file_atomically(dir / "slide.csv", monitors_csv(coupled.slide));
      const IsphAnalysis& a = *scene.analyses.isph;
      if (!a.monitors.gauges.empty()) {
        std::filesystem::create_directories(dir / "figures");
        sph::write_file_atomically(dir / "figures" / "coupled_gauges.svg",
                                   isph_gauges_svg(coupled.monitors, a.monitors.gauges, a.monitors.still_water, scene.name));
        coupled.figures.push_back("figures/coupled_gauges.svg");
      }
    } catch (const std::exception& error) {
      results.coupled->error = std::string("coupled: ") + error.what();
      results.coupled->result.reset();
      results.failures.push_back(results.coupled->error);
    }
  }
  if (results.mps && results.mps->result) {
    const MpsStageResult& mps = *results.mps->result;
    try {
      sph::write_file_atomically(dir / "monitors.csv", monitors_csv(mps.monitors));
      if (!mps.profiles.empty()) {
        const MpsAnalysis& a = *scene.analyses.mps;
        sph::write_file_atomically(dir / "profiles.csv", profiles_csv(mps.profiles));
        sph::write_file_atomically(dir / "profiles.svg", profiles_svg(mps.profiles, a.tank, scene.name, a.dam_x));
      }
    } catch (const std::exception& error) {
      results.mps->error = std::string("mps: ") + error.what();
      results.mps->result.reset();
      results.failures.push_back(results.mps->error);
    }
  }
}

// probabilistic_samples.csv after a probabilistic analysis; a failure to write it fails the run.
void write_lem_files(const std::filesystem::path& dir, RunResults& results) {
  const LemStageResult* lem = results.lem_result();
  if (lem == nullptr || !lem->probabilistic || !lem->probabilistic->error.empty()) return;
  try {
    std::filesystem::create_directories(dir);
    sph::write_file_atomically(dir / probabilistic_samples_file,
                               probabilistic_samples_csv(*lem->analysis.probabilistic, *lem->probabilistic));
  } catch (const std::exception& error) {
    results.failures.push_back(std::string("lem: cannot write ") + probabilistic_samples_file + ": " + error.what());
  }
}

// The "lem" block: the search, the given surfaces and the non-circular search, or the error.
json lem_block(const Scene& scene, const StageRecord<LemStageResult>& record, const SrmResult* srm) {
  if (!record.result) return {{"error", record.error}};
  const LemStageResult& lem = *record.result;
  const slope::Section& section = scene.section->section;
  json block = lem_report(section, lem.analysis, lem.search, lem.surfaces);
  if (lem.noncircular) block["noncircular"] = noncircular_report(section, *lem.analysis.noncircular, *lem.noncircular);
  if (lem.critical_coefficient)
    block["critical_seismic_coefficient"] = critical_coefficient_report(
        section, *lem.analysis.critical_coefficient_method, *lem.critical_coefficient,
        lem.analysis.acceleration_record ? &*lem.analysis.acceleration_record : nullptr,
        lem.newmark ? &*lem.newmark : nullptr);
  if (lem.probabilistic)
    block["probabilistic"] =
        probabilistic_report(*lem.analysis.probabilistic, *lem.probabilistic, lem.analysis.surfaces, srm);
  if (lem.analysis.rapid_drawdown)
    block["rapid_drawdown"] = drawdown_report(*lem.analysis.rapid_drawdown, lem.rapid_drawdown);
  if (lem.sensitivity)
    block["sensitivity"] = sensitivity_report(*lem.analysis.sensitivity, *lem.sensitivity, lem.analysis.surfaces);
  return block;
}

template <class Result, class Report, class ErrorReport>
void add_block(json& report, const char* key, const std::optional<StageRecord<Result>>& record, Report to_json,
               ErrorReport error_json) {
  if (!record) return;
  report[key] = record->result ? to_json(*record->result) : error_json(record->error);
}

// A number the stages left NaN or infinite (where no null is documented) fails the run, naming the key; the report
// is still written, with null there, so that the reason is in it.
void refuse_non_finite_numbers(WorkflowResult& out) {
  const std::vector<std::string> bad = null_non_finite_numbers(out.report);
  if (bad.empty()) return;
  const std::string why = std::string("report.json: ") + NonFiniteNumber(bad).what();
  out.status = ExitStatus::failed;
  out.errors.push_back(why);
  out.report["status"] = "failed";
  out.report["errors"].push_back(why);
}

void write_report(const Scene& scene, const std::filesystem::path& dir, const std::vector<std::string>& figures,
                  WorkflowResult& out) {
  refuse_non_finite_numbers(out);
  try {
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "report.json";
    out.report["report_html"] = "report.html";
    const RunPage page{out.report["status"].get<std::string>(), out.errors, figures};
    sph::write_file_atomically(dir / "report.html", report_html(scene, out.results, page, dir));
    sph::write_file_atomically(file, report_text(out.report));
    out.report_file = file;
  } catch (const std::exception& error) {
    out.status = ExitStatus::failed;
    out.errors.push_back(std::string("cannot write the report: ") + error.what());
  }
}

// The run, timed from `start` (the scene file's loading included when load_seconds is given), and its folder.
WorkflowResult run_and_write(const Scene& scene, const WorkflowOptions& given, StageClock::time_point start,
                             std::optional<double> load_seconds) {
  WorkflowOptions options = given;
  if (options.output_dir && !options.draw_snapshot) options.draw_snapshot = snapshot_drawer(*options.output_dir, scene.name);
  WorkflowResult out = run_analyses(scene, options);
  if (options.mode == Mode::check || out.status == ExitStatus::invalid_input) return out;
  RunResults& results = out.results;
  std::optional<std::vector<std::string>> figures;
  if (options.output_dir) {
    write_tank_files(scene, *options.output_dir, results);
    write_lem_files(*options.output_dir, results);
    try {
      figures = write_figures(scene, results, *options.output_dir);
    } catch (const std::exception& error) {
      results.failures.push_back(std::string("cannot write the figures: ") + error.what());
    }
    if (!results.failures.empty()) out.status = ExitStatus::failed;
  }
  if (const ComparisonResult* comparison = results.comparison_result(); comparison && options.log)
    *options.log << "comparison: " << comparison->verdict << "\n";
  if (load_seconds) results.seconds["load"] = *load_seconds;
  results.seconds["total"] = seconds_since(start);
  out.errors = results.failures;
  out.report = run_report(scene, results, figures ? &*figures : nullptr);
  out.report["status"] = !results.failures.empty()                ? "failed"
                         : out.status == ExitStatus::not_accepted ? "not_accepted"
                                                                  : "ok";
  if (options.output_dir) write_report(scene, *options.output_dir, figures.value_or(std::vector<std::string>{}), out);
  return out;
}

}  // namespace

json run_report(const Scene& scene, const RunResults& results, const std::vector<std::string>* figures) {
  json report = report_header(scene);
  report["timing_s"] = json::object();
  for (const auto& [key, seconds] : results.seconds) report["timing_s"][key] = seconds;
  report["analyses"] = results.analyses;
  if (results.lem)
    report["lem"] = lem_block(scene, *results.lem, results.srm && results.srm->result ? &*results.srm->result : nullptr);
  add_block(report, "sph", results.sph, sph_report, sph_error_report);
  add_block(report, "comparison", results.comparison, comparison_report, comparison_error_report);
  add_block(report, "srm", results.srm, srm_report, srm_error_report);
  add_block(report, "isph", results.isph, isph_report, isph_error_report);
  add_block(report, "mps", results.mps, mps_report, mps_error_report);
  add_block(report, "coupled", results.coupled, coupled_report, coupled_error_report);
  if (figures) report["figures"] = *figures;
  report["errors"] = results.failures;
  return report;
}

WorkflowResult run_scene(const Scene& scene, const WorkflowOptions& options) {
  return run_and_write(scene, options, StageClock::now(), std::nullopt);
}

WorkflowResult run_scene_file(const std::filesystem::path& scene_file, const WorkflowOptions& options) {
  const StageClock::time_point start = StageClock::now();
  Scene scene;
  try {
    scene = load_scene(scene_file);
  } catch (const SceneError& error) {
    WorkflowResult out;
    out.status = ExitStatus::invalid_input;
    out.errors = error.messages();
    return out;
  }
  return run_and_write(scene, options, start, seconds_since(start));
}

}  // namespace coupling
