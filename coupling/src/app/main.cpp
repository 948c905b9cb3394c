// sphslope: the command-line program. Parses the command line and prints; the work is in workflow.cpp.
//
//   sphslope check SCENE            validate a scene file, explain every error
//   sphslope lem SCENE [-o DIR]     limit equilibrium only; table on stdout, DIR/report.json with -o
//   sphslope run SCENE [-o DIR]     every analysis of the scene; report in DIR (default runs/<scene stem>)
//
// Exit status: 0 every requested analysis ran; 1 a run failed (report written with the reason); 2 invalid input
// (nothing written; the message names the JSON path of the fault); 3 every analysis ran but the comparison did
// not meet analyses.compare.acceptance (report written). Errors go to stderr.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/app/batch.hpp"
#include "coupling/output/report.hpp"
#include "coupling/output/probabilistic_output.hpp"
#include "coupling/scene/scene.hpp"
#include "coupling/analyses/sph_stage.hpp"
#include "coupling/studies/study.hpp"
#include "coupling/output/run_files.hpp"
#include "coupling/output/tables.hpp"

namespace {

// A program built for a newer CPU (CMake option SPHSLOPE_ARCH, "native" by default) would die on its first unknown
// instruction with "Illegal instruction"; this says what happened and how to rebuild instead. It checks the
// instruction sets the compiler was allowed to use.
bool cpu_runs_this_build() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();
#if defined(__AVX512F__)
  if (!__builtin_cpu_supports("avx512f")) return false;
#endif
#if defined(__AVX2__)
  if (!__builtin_cpu_supports("avx2")) return false;
#endif
#if defined(__FMA__)
  if (!__builtin_cpu_supports("fma")) return false;
#endif
#if defined(__AVX__)
  if (!__builtin_cpu_supports("avx")) return false;
#endif
#if defined(__SSE4_2__)
  if (!__builtin_cpu_supports("sse4.2")) return false;
#endif
#endif
  return true;
}

// The strength-reduction factor of safety next to the limit-equilibrium ones, on stdout.
void print_srm(const coupling::StageRecord<coupling::SrmResult>& record) {
  const coupling::SrmResult* srm = record.result ? &*record.result : nullptr;
  if (!srm || !srm->bisection.bracketed) {
    const std::string error = !srm ? record.error : srm->bisection.error.empty() ? "" : "srm: " + srm->bisection.error;
    std::cout << "strength reduction (SPH): no factor of safety" << (error.empty() ? std::string() : " (" + error + ")")
              << "\n";
    return;
  }
  std::printf("strength reduction (SPH, dx = %g m): FS_SPH = %.3f in [%.3f, %.3f]\n", srm->particle_spacing_m,
              srm->bisection.factor_of_safety, srm->bisection.lo, srm->bisection.hi);
  for (const auto& [method, fs] : srm->lem_fs_by_method)
    std::printf("  limit equilibrium %-26s FS = %.3f\n", method.c_str(), fs);
  std::fflush(stdout);
  for (const std::string& warning : srm->warnings) std::cerr << "srm: warning: " << warning << "\n";
}

int print_outcome(const std::filesystem::path& scene_file, const coupling::WorkflowResult& result,
                  coupling::Mode mode) {
  using coupling::ExitStatus;
  if (result.status == ExitStatus::invalid_input) {
    for (const std::string& message : result.errors) {
      std::cerr << "error: " << scene_file.string() << ": " << message << "\n";
    }
    std::cerr << "sphslope: invalid input (" << result.errors.size() << " error"
              << (result.errors.size() == 1 ? "" : "s") << " in " << scene_file.string()
              << "); nothing was written\n";
    return static_cast<int>(ExitStatus::invalid_input);
  }
  if (mode == coupling::Mode::check) {
    std::cout << "ok: " << scene_file.string() << ": " << coupling::summarize(*result.scene) << "\n";
    for (const coupling::SectionLoad& load : coupling::loads_sph_leaves_out(*result.scene))
      std::cerr << "warning: " << scene_file.string() << ": " << load.path
                << " is left out of the SPH model (" << load.why
                << "): SPH, strength reduction and the comparison will analyse the slope without "
                << load.name << ", limit equilibrium with it\n";
    return 0;
  }
  if (const coupling::LemStageResult* lem = result.results.lem_result(); lem && result.scene) {
    std::cout << "limit equilibrium: " << result.scene->name << " (" << scene_file.string() << ")\n"
              << coupling::lem_table(lem->analysis, lem->search);
    if (lem->noncircular) std::cout << coupling::noncircular_table(*lem->noncircular);
    if (lem->critical_coefficient)
      std::cout << coupling::critical_coefficient_line(*lem->analysis.critical_coefficient_method,
                                                       *lem->critical_coefficient);
    if (lem->newmark)
      std::cout << coupling::newmark_line(*lem->analysis.acceleration_record, *lem->newmark,
                                          *lem->critical_coefficient->coefficient);
    if (!lem->surfaces.empty()) std::cout << coupling::given_surfaces_table(lem->surfaces);
    if (lem->probabilistic)
      std::cout << coupling::probabilistic_line(*lem->analysis.probabilistic, *lem->probabilistic) << "\n";
    if (lem->analysis.rapid_drawdown)
      std::cout << coupling::drawdown_lines(*lem->analysis.rapid_drawdown, lem->rapid_drawdown);
    if (lem->sensitivity) std::cout << coupling::sensitivity_table(*lem->analysis.sensitivity, *lem->sensitivity);
  }
  if (result.results.srm) print_srm(*result.results.srm);
  for (const std::string& message : result.errors) std::cerr << "error: " << message << "\n";
  for (const std::string& line : result.rejections) std::cerr << "not accepted: " << line << "\n";
  if (result.report_file) {
    const char* note = result.status == ExitStatus::ok             ? ""
                       : result.status == ExitStatus::not_accepted ? " (status: not accepted; comparison.acceptance)"
                                                                   : " (status: failed; the reasons are in the report)";
    std::cerr << "report: " << result.report_file->string() << note << "\n";
  }
  return static_cast<int>(result.status);
}

// The study's table on stdout: one row per spacing with the error of each quantity.
int print_study(const std::filesystem::path& scene_file, const std::filesystem::path& output_dir,
                const coupling::StudyResult& result) {
  using coupling::ExitStatus;
  if (result.status == ExitStatus::invalid_input) {
    for (const std::string& message : result.errors)
      std::cerr << "error: " << scene_file.string() << ": " << message << "\n";
    std::cerr << "sphslope: invalid input; nothing was run\n";
    return static_cast<int>(ExitStatus::invalid_input);
  }
  const auto& study = result.study;
  std::cout << "study: " << study["scene"]["name"].get<std::string>() << " (reference: "
            << study["reference_case"].get<std::string>() << ")\n";
  std::printf("%10s %10s %10s %10s", "dx (m)", "particles", "steps", "wall (s)");
  for (const auto& q : study["quantities"]) std::printf(" %18s", q["key"].get<std::string>().c_str());
  std::printf("\n");
  for (const auto& run : study["runs"]) {
    std::printf("%10.4g %10s %10s %10.1f", run["particle_spacing_m"].get<double>(),
                run.contains("soil_particles")                                ? run["soil_particles"].dump().c_str()
                : run.contains("particles") && run["particles"].is_number() ? run["particles"].dump().c_str()
                                                                              : "-",
                run.contains("steps") ? run["steps"].dump().c_str() : "-", run.value("wall_seconds", 0.0));
    for (std::size_t q = 0; q < study["quantities"].size(); ++q) {
      const auto& e = run["errors_vs_reference"][q];
      if (e.is_number())
        std::printf(" %17.3g%%", 100.0 * e.get<double>());
      else
        std::printf(" %18s", "-");
    }
    std::printf("\n");
  }
  std::printf("%43s", "observed order:");
  for (const auto& q : study["quantities"]) {
    if (q["observed_order"].is_number())
      std::printf(" %18.2f", q["observed_order"].get<double>());
    else
      std::printf(" %18s", "-");
  }
  std::printf("\n");
  if (study.contains("lem_search")) {
    std::printf("limit-equilibrium search against the finest (%s):\n",
                study["lem_search"]["reference"].get<std::string>().c_str());
    std::printf("%10s %8s %7s %10s %10s", "entry/exit", "slices", "refine", "trials", "time (s)");
    const auto& levels = study["lem_search"]["levels"];
    for (const auto& [method, fs] : levels[0]["factor_of_safety"].items()) std::printf(" %26s", (method + " FS").c_str());
    std::printf("\n");
    for (const auto& level : levels) {
      std::printf("%10d %8d %7s %10ld %10.3f", level["entry_exit_samples"].get<int>(), level["slices"].get<int>(),
                  level["refine"].get<bool>() ? "yes" : "no", level["trial_surfaces"].get<long>(),
                  level["seconds"].get<double>());
      for (const auto& [method, fs] : level["factor_of_safety"].items()) {
        const auto& error = level["relative_error"][method];
        if (!fs.is_number())
          std::printf(" %26s", "-");
        else if (error.is_number())
          std::printf(" %17.4f (%5.2f%%)", fs.get<double>(), 100.0 * error.get<double>());
        else
          std::printf(" %17.4f (  ref )", fs.get<double>());
      }
      std::printf("\n");
    }
  }
  std::fflush(stdout);
  for (const std::string& message : result.errors) std::cerr << "error: " << message << "\n";
  std::cerr << "study: " << (output_dir / "study.json").string() << ", "
            << (output_dir / "figures" / "error_vs_runtime.svg").string() << "\n";
  return static_cast<int>(result.status);
}

// sphslope batch: its options are read straight into `options` (the output folder gets its default after parsing).
CLI::App* add_batch_command(CLI::App& app, coupling::BatchOptions& options) {
  CLI::App* batch = app.add_subcommand(
      "batch", "Run a set of scenes (a folder of *.json or a manifest), one run folder per scene, resumable; writes "
               "DIR/summary.csv, DIR/summary.json and DIR/junit.xml. Exit status: 0 all ok, 3 some comparison not "
               "accepted, 1 some scene failed or invalid (or interrupted), 2 invalid batch input.");
  batch->add_option("INPUT", options.input, "A folder of scene files (*.json) or a manifest (one scene file per line; "
                                            "# comments; paths relative to the manifest)")
      ->required()
      ->type_name("FOLDER|FILE");
  batch->add_option("-o,--output", options.output_dir, "Output folder (default: runs/batch)")->type_name("DIR");
  batch->add_option("-j,--jobs", options.jobs, "Scenes run at once; the cores are shared out among them (default 1)")
      ->check(CLI::PositiveNumber);
  batch->add_option("--index", options.index, "Run only scene INDEX (0-based) of the list, e.g. a scheduler's array "
                                              "index ($SLURM_ARRAY_TASK_ID); gather the summary afterwards with "
                                              "--summary-only");
  batch->add_flag("--summary-only", options.summary_only, "Run nothing: write the summary of the runs already in DIR");
  return batch;
}

int run_batch_command(coupling::BatchOptions options) {
  if (options.output_dir.empty()) options.output_dir = "runs/batch";
  options.program = std::filesystem::read_symlink("/proc/self/exe");
  options.log = &std::cerr;
  try {
    return coupling::run_batch(options);
  } catch (const std::exception& error) {
    std::cerr << "sphslope: unexpected failure: " << error.what() << "\n";
    return static_cast<int>(coupling::ExitStatus::failed);
  }
}

// sphslope section ARGS...: runs sphslope-section ARGS... (beside this program), which links GDAL.
int run_section_program(int argc, char** argv) {
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe").parent_path() / "sphslope-section";
  std::vector<char*> arguments{const_cast<char*>(program.c_str())};
  for (int i = 2; i < argc; ++i) arguments.push_back(argv[i]);
  arguments.push_back(nullptr);
  ::execv(program.c_str(), arguments.data());
  std::cerr << "sphslope: cannot run " << program.string() << " (" << std::strerror(errno) << "); build it with "
            << "scripts/build\n";
  return static_cast<int>(coupling::ExitStatus::failed);
}

// Everything the command line can say; filled by CLI11, read by the run_* functions.
struct CommandLine {
  std::string scene_file;
  std::string output_dir;
  bool resume = false;               // run --resume
  std::string sample_part;           // lem, run --sample-part K/M
  std::vector<std::string> merge_samples;  // lem, run --merge-samples PATH...
  std::vector<double> spacings;      // study --spacings
  bool study_resume = false;         // study --resume
  bool no_lem_search = false;        // study --no-lem-search
  coupling::BatchOptions batch;
  CLI::App* check = nullptr;
  CLI::App* lem = nullptr;
  CLI::App* run = nullptr;
  CLI::App* study = nullptr;
  CLI::App* batch_command = nullptr;
};

void add_scene_commands(CLI::App& app, CommandLine& cli) {
  cli.check = app.add_subcommand("check", "Validate a scene file and explain every error.");
  // listed for --help; main() hands `sphslope section ...` to sphslope-section before parsing
  app.add_subcommand("section", "Cut a ground profile out of a terrain raster (GeoTIFF, .bil, ASCII grid, ...) along a "
                                "line, or take a drawn section's layers from DXF, into a scene (sphslope section "
                                "--help)");
  cli.check->add_option("SCENE", cli.scene_file, "Scene file (JSON, \"format\": \"sphslope-scene/1\")")
      ->required()
      ->type_name("FILE");

  cli.lem = app.add_subcommand(
      "lem", "Limit equilibrium only: critical circle and factor of safety per method, as a table on stdout.");
  cli.lem->add_option("SCENE", cli.scene_file, "Scene file with a \"section\"")->required()->type_name("FILE");
  cli.lem->add_option("-o,--output", cli.output_dir, "Also write DIR/report.json (default: print only, write nothing)")
      ->type_name("DIR");

  cli.run = app.add_subcommand("run", "Run every analysis the scene asks for and write DIR/report.json.");
  cli.run->add_option("SCENE", cli.scene_file, "Scene file")->required()->type_name("FILE");
  cli.run->add_option("-o,--output", cli.output_dir, "Output folder (default: runs/<scene file stem>)")->type_name("DIR");
  cli.run->add_flag("--resume", cli.resume,
                    "Continue an interrupted SPH run from DIR/checkpoint.bin (same scene, same DIR); the result is "
                    "the same as an uninterrupted run");
  for (CLI::App* command : {cli.lem, cli.run}) {
    command->add_option("--sample-part", cli.sample_part,
                        "Run only part K (from 0) of M of analyses.lem.probabilistic's samples, e.g. a scheduler's "
                        "array index ($SLURM_ARRAY_TASK_ID/M); merge the parts with --merge-samples")
        ->type_name("K/M");
    command->add_option("--merge-samples", cli.merge_samples,
                        "Analyse no sample: take every sample's result from the parts' run folders (or their "
                        "probabilistic_samples.csv); the result is that of one run")
        ->type_name("PATH...");
  }
}

// "K/M" with 0 <= K < M; nullopt when it is not.
std::optional<coupling::SamplePart> parse_sample_part(const std::string& text) {
  long k = -1, m = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%ld/%ld%c", &k, &m, &tail) != 2 || k < 0 || m < 1 || k >= m) return std::nullopt;
  return coupling::SamplePart{k, m};
}

void add_study_command(CLI::App& app, CommandLine& cli) {
  cli.study = app.add_subcommand(
      "study", "Error against run time: run the scene at several particle spacings and measure each monitored "
               "quantity against its reference (DIR/study.json, DIR/figures/error_vs_runtime.svg).");
  cli.study->add_option("SCENE", cli.scene_file, "Scene file with analyses.sph (a slope section, or one column body), analyses.mps (one granular column) or analyses.isph (the Martin & Moyce dam break, with its front_reference)")
      ->required()
      ->type_name("FILE");
  cli.study->add_option("--spacings", cli.spacings, "Particle spacings in metres, comma-separated, e.g. 0.4,0.2,0.1")
      ->required()
      ->delimiter(',')
      ->type_name("DX,...");
  cli.study->add_option("-o,--output", cli.output_dir, "Output folder (default: runs/<scene file stem>_study)")
      ->type_name("DIR");
  cli.study->add_flag("--resume", cli.study_resume,
                      "Reuse the spacings already finished in DIR and continue an interrupted one from its checkpoint");
  cli.study->add_flag("--no-lem-search", cli.no_lem_search,
                      "Slope sections: skip the study of the limit-equilibrium search");
}

int run_study_command(const CommandLine& cli) {
  coupling::StudyOptions study_options;
  study_options.spacings = cli.spacings;
  study_options.resume = cli.study_resume;
  study_options.lem_search = !cli.no_lem_search;
  study_options.log = &std::cerr;
  study_options.output_dir =
      cli.output_dir.empty()
          ? std::filesystem::path("runs") / (std::filesystem::path(cli.scene_file).stem().string() + "_study")
          : std::filesystem::path(cli.output_dir);
  try {
    return print_study(cli.scene_file, study_options.output_dir, coupling::run_study(cli.scene_file, study_options));
  } catch (const std::exception& error) {
    std::cerr << "sphslope: unexpected failure: " << error.what() << "\n";
    return static_cast<int>(coupling::ExitStatus::failed);
  }
}

// check, lem and run: the pipeline on one scene file.
int run_scene_command(const CommandLine& cli) {
  coupling::WorkflowOptions options;
  options.log = &std::cerr;
  if (!cli.sample_part.empty()) {
    options.sample_part = parse_sample_part(cli.sample_part);
    if (!options.sample_part || !cli.merge_samples.empty()) {
      std::cerr << "error: --sample-part: \"" << cli.sample_part
                << "\" is not K/M with 0 <= K < M (part K of M, from 0; not with --merge-samples)\n";
      return static_cast<int>(coupling::ExitStatus::invalid_input);
    }
  }
  for (const std::string& path : cli.merge_samples) options.merge_samples.emplace_back(path);
  if (cli.check->parsed()) {
    options.mode = coupling::Mode::check;
  } else if (cli.lem->parsed()) {
    options.mode = coupling::Mode::lem;
    if (!cli.output_dir.empty()) options.output_dir = cli.output_dir;
  } else {
    options.mode = coupling::Mode::run;
    options.resume = cli.resume;
    coupling::install_interrupt_handler();  // Ctrl-C: checkpoint, report "interrupted", exit 1; --resume continues
    options.output_dir = cli.output_dir.empty() ? coupling::default_output_dir(cli.scene_file)
                                                : std::filesystem::path(cli.output_dir);
  }
  try {
    const coupling::WorkflowResult result = coupling::run_scene_file(cli.scene_file, options);
    return print_outcome(cli.scene_file, result, options.mode);
  } catch (const std::exception& error) {
    std::cerr << "sphslope: unexpected failure: " << error.what() << "\n";
    return static_cast<int>(coupling::ExitStatus::failed);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (!cpu_runs_this_build()) {
    std::cerr << "sphslope: this program was built for a CPU with instructions this one lacks (CMake option "
                 "SPHSLOPE_ARCH, \"native\" by default, optimises for the build machine). Rebuild it here with "
                 "scripts/build, or for any x86-64 CPU with scripts/build -DSPHSLOPE_ARCH=x86-64.\n";
    return static_cast<int>(coupling::ExitStatus::failed);
  }
  if (argc >= 2 && std::string(argv[1]) == "section") return run_section_program(argc, argv);
  CLI::App app{"sphslope: geotechnical slope assessment (limit equilibrium and SPH) from a scene file.\n"
               "Exit status: 0 every requested analysis ran; 1 a run failed (report written with the reason);\n"
               "2 invalid input (nothing written; the message names the JSON path of the fault);\n"
               "3 every analysis ran but the comparison failed its acceptance criteria (report written).",
               "sphslope"};
  app.set_version_flag("--version", "sphslope " + std::string(coupling::program_version()));
  app.require_subcommand(1);
  CommandLine cli;
  add_scene_commands(app, cli);
  add_study_command(app, cli);
  cli.batch_command = add_batch_command(app, cli.batch);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);  // prints help, the version or the usage error
    return code == 0 ? 0 : static_cast<int>(coupling::ExitStatus::invalid_input);
  }
  if (cli.batch_command->parsed()) return run_batch_command(cli.batch);
  if (cli.study->parsed()) return run_study_command(cli);
  return run_scene_command(cli);
}
