// The pipeline: a scene's analyses run as the stages of pipeline_stages() (coupling/analyses/stage.hpp), then the
// figures and report.json. main.cpp only parses the command line and prints.
#include "coupling/analyses/pipeline.hpp"

#include <exception>
#include <ostream>

#include "coupling/analyses/sph_model.hpp"
#include "coupling/analyses/stage.hpp"
#include "coupling/output/json_text.hpp"
#include "coupling/output/report.hpp"
#include "coupling/output/report_html.hpp"
#include "coupling/output/run_figures.hpp"
#include "sph/engine/atomic_file.hpp"

namespace coupling {

namespace {

// "sphslope check": a valid scene whose SPH run would be refused before starting (particle, memory or step
// limits) is reported as well, with the same messages (estimated without building particles).
WorkflowResult check_scene(const Scene& scene) {
  WorkflowResult out;
  out.scene = scene;
  if (scene.analyses.sph) {
    if (const auto plan = plan_sph(scene, *scene.analyses.sph)) {
      out.errors = sph_refusals(*scene.analyses.sph, *plan);
      if (!out.errors.empty()) out.status = ExitStatus::invalid_input;
    }
  }
  return out;
}

// The stages this run asks for, in pipeline order ("sphslope lem" runs limit equilibrium only).
std::vector<const Stage*> requested_stages(const Scene& scene, const StageContext& context) {
  std::vector<const Stage*> stages;
  for (const Stage& stage : pipeline_stages()) {
    if (context.options.mode == Mode::lem && stage.key != "lem") continue;
    if (stage.requested(scene, context)) stages.push_back(&stage);
  }
  return stages;
}

// Folds a stage's outcome into the run's status. Returns false when the stage found the input invalid: the run
// stops there and writes nothing.
bool absorb(StageOutcome&& stage, WorkflowResult& out, std::vector<std::string>& failures) {
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
}

void write_run_figures(const Scene& scene, StageContext& context, std::vector<std::string>& failures) {
  WorkflowResult& out = context.out;
  try {
    write_figures(scene, out, context.final_state, context.failure, *context.options.output_dir, out.report);
  } catch (const std::exception& error) {
    failures.push_back(std::string("cannot write the figures: ") + error.what());
    out.status = ExitStatus::failed;
  }
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

void write_report(const Scene& scene, const std::filesystem::path& dir, WorkflowResult& out) {
  refuse_non_finite_numbers(out);
  try {
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "report.json";
    out.report["report_html"] = "report.html";
    sph::write_file_atomically(dir / "report.html", report_html(scene, out.report, dir));
    sph::write_file_atomically(file, report_text(out.report));
    out.report_file = file;
  } catch (const std::exception& error) {
    out.status = ExitStatus::failed;
    out.errors.push_back(std::string("cannot write the report: ") + error.what());
  }
}

// After the stages: figures, the verdict on the log, the status and errors of the report, and report.json.
void finish_run(const Scene& scene, StageContext& context, std::vector<std::string>& failures,
                StageClock::time_point start) {
  const WorkflowOptions& options = context.options;
  WorkflowResult& out = context.out;
  if (options.output_dir) write_run_figures(scene, context, failures);
  if (out.report.contains("comparison") && out.report["comparison"].contains("verdict") && options.log)
    *options.log << "comparison: " << out.report["comparison"]["verdict"].get<std::string>() << "\n";

  out.report["status"] = !failures.empty() ? "failed" : out.status == ExitStatus::not_accepted ? "not_accepted" : "ok";
  out.report["errors"] = failures;
  out.errors = failures;
  out.report["timing_s"]["total"] = seconds_since(start);
  if (options.output_dir) write_report(scene, *options.output_dir, out);
  out.sph_final_state = std::move(context.final_state);
}

}  // namespace

std::filesystem::path default_output_dir(const std::filesystem::path& scene_file) {
  return std::filesystem::path("runs") / scene_file.stem();
}

WorkflowResult run_scene(const Scene& scene, const WorkflowOptions& options) {
  const StageClock::time_point start = StageClock::now();
  if (options.mode == Mode::check) return check_scene(scene);
  WorkflowResult out;
  out.scene = scene;
  out.report = report_header(scene);
  out.report["timing_s"] = nlohmann::json::object();

  StageContext context{options, out, scene.analyses.lem, std::nullopt, std::nullopt};
  if (options.mode == Mode::lem) {
    if (!scene.section) {
      out.status = ExitStatus::invalid_input;
      out.errors.push_back("section: missing (sphslope lem needs a slope \"section\"; this is a particle scene)");
      out.report = nullptr;
      return out;
    }
    if (!context.lem) context.lem = default_lem_analysis();
  }
  const std::vector<const Stage*> stages = requested_stages(scene, context);
  std::vector<std::string> requested;
  for (const Stage* stage : stages) requested.emplace_back(stage->key);
  out.report["analyses"] = requested;

  std::vector<std::string> failures;
  for (const Stage* stage : stages) {
    if (!absorb(stage->run(scene, context), out, failures)) {
      out.report = nullptr;
      return out;
    }
  }
  finish_run(scene, context, failures, start);
  return out;
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

}  // namespace coupling
