// The pipeline: a scene's analyses run as the stages of pipeline_stages() (coupling/analyses/stage.hpp) into typed
// results. coupling/output/run_files.cpp writes the run folder from them; main.cpp only parses and prints.
#include "coupling/analyses/pipeline.hpp"

#include "coupling/analyses/sph_model.hpp"
#include "coupling/analyses/stage.hpp"

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
bool absorb(StageOutcome&& stage, WorkflowResult& out) {
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
    out.results.failures.insert(out.results.failures.end(), stage.errors.begin(), stage.errors.end());
  }
  return true;
}

}  // namespace

std::filesystem::path default_output_dir(const std::filesystem::path& scene_file) {
  return std::filesystem::path("runs") / scene_file.stem();
}

WorkflowResult run_analyses(const Scene& scene, const WorkflowOptions& options) {
  if (options.mode == Mode::check) return check_scene(scene);
  WorkflowResult out;
  out.scene = scene;
  StageContext context{options, out.results, scene.analyses.lem};
  if (options.mode == Mode::lem) {
    if (!scene.section) {
      out.status = ExitStatus::invalid_input;
      out.errors.push_back("section: missing (sphslope lem needs a slope \"section\"; this is a particle scene)");
      return out;
    }
    if (!context.lem) context.lem = default_lem_analysis();
  }
  if ((options.sample_part || !options.merge_samples.empty()) && !(context.lem && context.lem->probabilistic)) {
    out.status = ExitStatus::invalid_input;
    out.errors.push_back(std::string(options.sample_part ? "--sample-part" : "--merge-samples") +
                         ": the scene has no analyses.lem.probabilistic to split or merge");
    return out;
  }
  const std::vector<const Stage*> stages = requested_stages(scene, context);
  for (const Stage* stage : stages) out.results.analyses.emplace_back(stage->key);
  for (const Stage* stage : stages)
    if (!absorb(stage->run(scene, context), out)) return out;
  out.errors = out.results.failures;
  return out;
}

}  // namespace coupling
