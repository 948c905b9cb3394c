#include "coupling/studies/study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <ostream>
#include <set>
#include <sstream>

#include "sph/engine/atomic_file.hpp"
#include "coupling/studies/convergence.hpp"
#include "coupling/scene/json_reader.hpp"
#include "coupling/output/json_values.hpp"
#include "coupling/output/report.hpp"
#include "coupling/analyses/sph_stage.hpp"
#include "study_cases.hpp"
#include "coupling/scene/json_text.hpp"
#include "sphslope/wall_clock.hpp"
#include "coupling/output/run_files.hpp"

namespace coupling {
namespace {

using namespace study_detail;
using Clock = std::chrono::steady_clock;
using sphslope::seconds_since;

constexpr const char* study_format = "sphslope-study/1";

std::string spacing_folder(double spacing) {
  std::ostringstream name;
  name << "dx_" << format_number(spacing) << "_m";
  return name.str();
}


// ---- the limit-equilibrium search against its finest setting --------------------------------------------------

struct SearchLevel {
  int entry_exit_samples;
  int slices;
  bool refine;
};

// Coarse to fine; the last is the reference.
constexpr SearchLevel search_levels[] = {{6, 10, false}, {11, 20, false}, {21, 30, false}, {41, 50, false},
                                         {41, 50, true}, {81, 100, true}, {161, 200, true}};

nlohmann::json lem_search_study(const Scene& scene, std::vector<StudySeries>& series, std::ostream* log) {
  const LemAnalysis analysis = scene.analyses.lem ? *scene.analyses.lem : default_lem_analysis();
  std::vector<slope::Method> methods = analysis.methods;
  if (!scene.analyses.lem || !scene.analyses.lem->methods_given)
    methods = {slope::Method::bishop, slope::Method::spencer};
  const std::size_t n_levels = std::size(search_levels);
  std::vector<slope::SearchResult> results;
  for (const SearchLevel& level : search_levels) {
    slope::SearchOptions options = analysis.search;
    options.entry_exit_samples = level.entry_exit_samples;
    options.slicing.slices = level.slices;
    options.refine = level.refine;
    results.push_back(slope::search_critical(scene.section->section, methods, options));
    if (log)
      *log << "study: LEM search with " << level.entry_exit_samples << " entry/exit points, " << level.slices
           << " slices" << (level.refine ? ", refined" : "") << ": " << results.back().trial_surfaces
           << " trial surfaces in " << results.back().seconds << " s\n";
  }
  const slope::SearchResult& finest = results.back();
  nlohmann::json out;
  out["reference"] = "the finest search: " + std::to_string(search_levels[n_levels - 1].entry_exit_samples) +
                     " entry/exit points, " + std::to_string(search_levels[n_levels - 1].slices) +
                     " slices, Nelder-Mead refinement";
  out["error_definition"] = "|FS - FS_finest| / FS_finest per method";
  nlohmann::json levels = nlohmann::json::array();
  for (std::size_t m = 0; m < methods.size(); ++m) {
    StudySeries s;
    s.label = "LEM search: " + std::string(slope::method_key(methods[m])) + " FS against the finest search";
    series.push_back(s);
  }
  const std::size_t first_series = series.size() - methods.size();
  for (std::size_t k = 0; k < n_levels; ++k) {
    const SearchLevel& level = search_levels[k];
    nlohmann::json entry = {{"entry_exit_samples", level.entry_exit_samples},
                            {"slices", level.slices},
                            {"refine", level.refine},
                            {"trial_surfaces", results[k].trial_surfaces},
                            {"seconds", results[k].seconds}};
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const std::string key(slope::method_key(methods[m]));
      const auto& fs = results[k].methods[m].result.factor_of_safety;
      const auto& reference = finest.methods[m].result.factor_of_safety;
      entry["factor_of_safety"][key] = optional_number(fs);
      if (fs && reference && k + 1 < n_levels) {
        const double error = std::fabs(*fs - *reference) / *reference;
        entry["relative_error"][key] = error;
        auto& s = series[first_series + m];
        s.seconds.push_back(results[k].seconds);
        s.errors.push_back(error);
        s.point_labels.push_back(std::to_string(level.entry_exit_samples) + "/" + std::to_string(level.slices) +
                                 (level.refine ? "+NM" : ""));
      } else {
        entry["relative_error"][key] = nullptr;
      }
    }
    levels.push_back(entry);
  }
  out["levels"] = levels;
  return out;
}

// ---- one run per spacing ---------------------------------------------------------------------------------------

struct RunRecord {
  double spacing = 0.0;
  nlohmann::json entry;  // the study.json "runs" element
  std::vector<std::optional<double>> values;
  double seconds = 0.0;
  bool ok = false;
};

RunRecord record_from_json(const nlohmann::json& entry, std::size_t n_quantities) {
  RunRecord r;
  r.entry = entry;
  r.spacing = entry.at("particle_spacing_m").get<double>();
  r.seconds = entry.value("wall_seconds", 0.0);
  r.ok = entry.value("status", std::string()) == "ok";
  r.values.resize(n_quantities);
  for (std::size_t q = 0; q < n_quantities; ++q) {
    const auto& v = entry["values"][q];
    if (v.is_number()) r.values[q] = v.get<double>();
  }
  return r;
}

// The study.json "runs" element's facts of a run: particles, steps, simulated time, why it stopped and the wall time
// of the particle run (sph, mps or isph, whichever the scene has).
template <class Result>
void describe_tank_run(const std::optional<StageRecord<Result>>& record, const char* seconds_key, std::size_t particles,
                       nlohmann::json& entry) {
  if (!record || !record->result) return;
  const sph::RunSummary& summary = record->result->summary;
  entry["particles"] = particles;
  entry["steps"] = summary.total_steps;
  entry["simulated_time_s"] = summary.simulated_time;
  entry["stopped_because"] = summary.stopped_because;
  entry[seconds_key] = summary.wall_seconds;
}

void describe_run(const RunResults& results, nlohmann::json& entry) {
  if (results.sph) {
    if (const SphStageResult* sph = results.sph->result ? &*results.sph->result : nullptr) {
      entry["soil_particles"] = sph->model.soil_particles;
      entry["particles"] = sph->model.particles;
      entry["steps"] = sph->summary.total_steps;
      entry["simulated_time_s"] = sph->summary.simulated_time;
      entry["stopped_because"] = sph->summary.stopped_because;
      entry["sph_seconds"] = sph->summary.wall_seconds;
    } else {
      entry["stopped_because"] = "error";
    }
  }
  if (results.mps)
    describe_tank_run(results.mps, "mps_seconds",
                      results.mps->result ? results.mps->result->moving_particles : 0, entry);
  if (results.isph)
    describe_tank_run(results.isph, "isph_seconds",
                      results.isph->result ? results.isph->result->fluid_particles : 0, entry);
}

RunRecord run_one_spacing(const Scene& scene, const CaseSetup& setup, double spacing,
                          const std::filesystem::path& folder, const StudyOptions& options) {
  RunRecord record;
  record.spacing = spacing;
  nlohmann::json& entry = record.entry;
  entry["particle_spacing_m"] = spacing;
  entry["folder"] = std::filesystem::path("runs") / folder.filename();
  const Clock::time_point start = Clock::now();
  Scene at_spacing;
  try {
    at_spacing = scene_at_spacing(scene, spacing);
  } catch (const SceneError& error) {
    entry["status"] = "refused";
    entry["errors"] = error.messages();
    record.values.resize(setup.quantities.size());
    entry["values"] = nlohmann::json::array();
    for (std::size_t q = 0; q < setup.quantities.size(); ++q) entry["values"].push_back(nullptr);
    return record;
  }
  WorkflowOptions run_options;
  run_options.mode = Mode::run;
  run_options.output_dir = folder;
  run_options.log = options.log;
  run_options.resume = options.resume && std::filesystem::exists(folder / "checkpoint.bin") &&
                       !std::filesystem::exists(folder / "quantities.json");
  const WorkflowResult run = run_scene(at_spacing, run_options);
  record.seconds = seconds_since(start);
  record.ok = run.status == ExitStatus::ok;
  entry["status"] = run.status == ExitStatus::ok ? "ok" : run.status == ExitStatus::failed ? "failed" : "refused";
  entry["errors"] = run.errors;
  entry["wall_seconds"] = record.seconds;
  describe_run(run.results, entry);
  // A run that did not finish (interrupted, blown up) measures nothing: its state is not the case's result.
  record.values = record.ok ? read_values(setup, run.results, folder)
                            : std::vector<std::optional<double>>(setup.quantities.size());
  entry["values"] = nlohmann::json::array();
  for (const auto& v : record.values) entry["values"].push_back(optional_number(v));
  return record;
}

}  // namespace

namespace {

// --spacings: positive, finite, each once; sorted coarse to fine. Returns the problems found.
std::vector<std::string> check_spacings(std::vector<double>& spacings) {
  std::vector<std::string> problems;
  if (spacings.empty()) problems.push_back("--spacings: give at least one particle spacing in metres, e.g. 0.4,0.2,0.1");
  for (double s : spacings)
    if (!(s > 0.0) || !std::isfinite(s))
      problems.push_back("--spacings: " + format_number(s) + " is not a positive spacing in metres");
  std::sort(spacings.begin(), spacings.end(), std::greater<>());
  if (std::adjacent_find(spacings.begin(), spacings.end()) != spacings.end())
    problems.push_back("--spacings: a spacing is given twice");
  return problems;
}

nlohmann::json quantities_json(const std::vector<Quantity>& quantities) {
  nlohmann::json out = nlohmann::json::array();
  for (const Quantity& q : quantities)
    out.push_back({{"key", q.key},
                   {"description", q.description},
                   {"reference", optional_number(q.reference)},
                   {"reference_source", q.reference_source},
                   {"error_definition", q.error_definition}});
  return out;
}

// Wall time already spent on unfinished spacings, from the study.json of an interrupted study.
std::map<double, double> earlier_seconds_of(const StudyOptions& options) {
  std::map<double, double> earlier_seconds;
  if (options.resume && std::filesystem::exists(options.output_dir / "study.json")) {
    std::ifstream in(options.output_dir / "study.json");
    const nlohmann::json earlier = nlohmann::json::parse(in, nullptr, false);
    if (earlier.is_object() && earlier.contains("runs") && earlier["runs"].is_array())
      for (const auto& run : earlier["runs"])
        if (run.value("status", std::string()) == "failed" && run.contains("wall_seconds"))
          earlier_seconds[run["particle_spacing_m"].get<double>()] = run["wall_seconds"].get<double>();
  }
  return earlier_seconds;
}

// Every spacing in turn (those finished by an earlier session are read back). Returns whether an interrupt
// stopped the study.
bool run_spacings(const Scene& scene, const CaseSetup& setup, const std::vector<double>& spacings,
                  const StudyOptions& options, std::vector<RunRecord>& runs) {
  const std::map<double, double> earlier_seconds = earlier_seconds_of(options);
  for (std::size_t k = 0; k < spacings.size(); ++k) {
    const double dx = spacings[k];
    const std::filesystem::path folder = options.output_dir / "runs" / spacing_folder(dx);
    const std::filesystem::path saved = folder / "quantities.json";
    if (options.resume && std::filesystem::exists(saved)) {
      std::ifstream in(saved);
      runs.push_back(record_from_json(nlohmann::json::parse(in), setup.quantities.size()));
      if (options.log) *options.log << "study: dx = " << dx << " m already done (" << saved.string() << ")\n";
      continue;
    }
    if (options.log)
      *options.log << "study: run " << k + 1 << " of " << spacings.size() << ", dx = " << dx << " m -> "
                   << folder.string() << "\n";
    std::filesystem::create_directories(folder);
    RunRecord record = run_one_spacing(scene, setup, dx, folder, options);
    // A resumed run also cost the wall time of the sessions before the interruption (from the last study.json).
    if (const auto before = earlier_seconds.find(dx); before != earlier_seconds.end() && options.resume &&
                                                      record.entry.contains("wall_seconds")) {
      record.seconds += before->second;
      record.entry["wall_seconds"] = record.seconds;
      record.entry["wall_seconds_before_resume"] = before->second;
    }
    if (interrupt_pending()) {
      runs.push_back(std::move(record));
      return true;
    }
    if (record.ok) sph::write_file_atomically(saved, json_text(record.entry));
    runs.push_back(std::move(record));
  }
  return false;
}

// Richardson self-convergence of the three finest runs (h, f coarse to fine), or why there is none.
nlohmann::json self_convergence_json(const std::vector<double>& h, const std::vector<double>& f) {
  const std::size_t n = f.size();
  if (auto sc = self_convergence(h[n - 3], f[n - 3], h[n - 2], f[n - 2], h[n - 1], f[n - 1])) {
    nlohmann::json out = {{"order", sc->order},
                          {"extrapolated_value", sc->extrapolated},
                          {"from_spacings_m", {h[n - 3], h[n - 2], h[n - 1]}}};
    if (sc->order < 0.5)
      out["note"] = "order below 0.5: the runs converge too slowly for Richardson "
                    "extrapolation, the extrapolated value is not reliable";
    return out;
  }
  return {{"order", nullptr},
          {"note", "the three finest runs are not monotone in dx (not yet in the asymptotic "
                   "range), so no order can be formed without the reference"}};
}

// Errors of quantity q against its reference in every run, its observed order, and its series for the figure.
StudySeries measure_quantity(const Quantity& quantity, std::size_t q, std::vector<RunRecord>& runs,
                             nlohmann::json& jq) {
  StudySeries s;
  s.label = quantity.key + " against " + quantity.reference_short;
  std::vector<double> h, e, f;
  for (RunRecord& r : runs) {
    nlohmann::json& errors = r.entry["errors_vs_reference"];
    if (!errors.is_array()) errors = nlohmann::json::array();
    if (errors.size() <= q) errors.push_back(nullptr);
    if (!r.values[q]) continue;
    const double error = relative_error(quantity, *r.values[q]);
    errors[q] = error;
    h.push_back(r.spacing);
    e.push_back(error);
    f.push_back(*r.values[q]);
    s.seconds.push_back(r.seconds);
    s.errors.push_back(error);
    s.point_labels.push_back("dx " + format_number(r.spacing) + " m");
  }
  jq["observed_order"] = optional_number(observed_order(h, e));
  jq["observed_order_note"] = "least-squares slope of log(error) against log(dx) over the runs";
  if (f.size() >= 3) jq["self_convergence"] = self_convergence_json(h, f);
  return s;
}

std::vector<std::string> study_failures(const std::vector<RunRecord>& runs, bool interrupted) {
  std::vector<std::string> failures;
  for (const RunRecord& r : runs)
    if (!r.ok)
      failures.push_back("dx = " + format_number(r.spacing) + " m: " +
                         (r.entry.contains("errors") && !r.entry["errors"].empty()
                              ? r.entry["errors"][0].get<std::string>()
                              : std::string("the run did not finish")));
  if (interrupted) failures.push_back("interrupted: run `sphslope study ... --resume` to continue");
  return failures;
}

}  // namespace

StudyResult run_study(const std::filesystem::path& scene_file, const StudyOptions& options) {
  StudyResult out;
  const Clock::time_point start = Clock::now();
  std::vector<double> spacings = options.spacings;
  if (std::vector<std::string> problems = check_spacings(spacings); !problems.empty()) {
    out.status = ExitStatus::invalid_input;
    out.errors = problems;
    return out;
  }
  Scene scene;
  CaseSetup setup;
  try {
    scene = load_scene(scene_file);
    setup = setup_case(scene);
  } catch (const SceneError& error) {
    out.status = ExitStatus::invalid_input;
    out.errors = error.messages();
    return out;
  }

  nlohmann::json& study = out.study;
  study = report_header(scene);
  study["format"] = study_format;
  study["reference_case"] = setup.kind_key;
  study["parameters"] = setup.parameters;
  study["spacings_m"] = spacings;
  nlohmann::json quantities = quantities_json(setup.quantities);

  std::filesystem::create_directories(options.output_dir / "runs");
  std::filesystem::create_directories(options.output_dir / "figures");
  install_interrupt_handler();
  std::vector<RunRecord> runs;
  const bool interrupted = run_spacings(scene, setup, spacings, options, runs);

  // Errors, orders and the figure.
  std::vector<StudySeries> series;
  for (std::size_t q = 0; q < setup.quantities.size(); ++q)
    series.push_back(measure_quantity(setup.quantities[q], q, runs, quantities[q]));
  study["quantities"] = quantities;
  study["runs"] = nlohmann::json::array();
  for (const RunRecord& r : runs) study["runs"].push_back(r.entry);
  if (setup.kind == CaseKind::slope_failure_surface && options.lem_search && !interrupted)
    study["lem_search"] = lem_search_study(scene, series, options.log);

  const std::vector<std::string> failures = study_failures(runs, interrupted);
  out.errors = failures;
  study["status"] = failures.empty() ? "ok" : "failed";
  study["errors"] = failures;
  study["seconds"] = seconds_since(start);
  study["figures"] = {{"error_vs_runtime", "figures/error_vs_runtime.svg"}};
  sph::write_file_atomically(options.output_dir / "figures" / "error_vs_runtime.svg",
               error_vs_runtime_svg(scene.name + ": error against run time", series));
  sph::write_file_atomically(options.output_dir / "study.json", json_text(study));
  out.status = failures.empty() ? ExitStatus::ok : ExitStatus::failed;
  return out;
}

}  // namespace coupling
