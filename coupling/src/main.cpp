// sphslope: the command-line program. Parses the command line and prints; the work is in workflow.cpp.
//
//   sphslope check SCENE            validate a scene file, explain every error
//   sphslope lem SCENE [-o DIR]     limit equilibrium only; table on stdout, DIR/report.json with -o
//   sphslope run SCENE [-o DIR]     every analysis of the scene; report in DIR (default runs/<scene stem>)
//
// Exit status: 0 every requested analysis ran; 1 a run failed (report written with the reason); 2 invalid input
// (nothing written; the message names the JSON path of the fault). Errors go to stderr.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <string>

#include "coupling/report.hpp"
#include "coupling/scene.hpp"
#include "coupling/sph_workflow.hpp"
#include "coupling/workflow.hpp"

namespace {

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
    return 0;
  }
  if (result.lem && result.scene) {
    const coupling::LemAnalysis analysis =
        result.scene->analyses.lem ? *result.scene->analyses.lem : coupling::default_lem_analysis();
    std::cout << "limit equilibrium: " << result.scene->name << " (" << scene_file.string() << ")\n"
              << coupling::lem_table(analysis, *result.lem);
  }
  for (const std::string& message : result.errors) std::cerr << "error: " << message << "\n";
  if (result.report_file) {
    std::cerr << "report: " << result.report_file->string()
              << (result.status == ExitStatus::ok ? "" : " (status: failed; the reasons are in the report)") << "\n";
  }
  return static_cast<int>(result.status);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sphslope: geotechnical slope assessment (limit equilibrium and SPH) from a scene file.\n"
               "Exit status: 0 every requested analysis ran; 1 a run failed (report written with the reason);\n"
               "2 invalid input (nothing written; the message names the JSON path of the fault).",
               "sphslope"};
  app.set_version_flag("--version", "sphslope " + std::string(coupling::program_version()));
  app.require_subcommand(1);

  std::string scene_file;
  std::string output_dir;

  CLI::App* check = app.add_subcommand("check", "Validate a scene file and explain every error.");
  check->add_option("SCENE", scene_file, "Scene file (JSON, \"format\": \"sphslope-scene/1\")")
      ->required()
      ->type_name("FILE");

  CLI::App* lem = app.add_subcommand(
      "lem", "Limit equilibrium only: critical circle and factor of safety per method, as a table on stdout.");
  lem->add_option("SCENE", scene_file, "Scene file with a \"section\"")->required()->type_name("FILE");
  lem->add_option("-o,--output", output_dir, "Also write DIR/report.json (default: print only, write nothing)")
      ->type_name("DIR");

  CLI::App* run = app.add_subcommand("run", "Run every analysis the scene asks for and write DIR/report.json.");
  run->add_option("SCENE", scene_file, "Scene file")->required()->type_name("FILE");
  run->add_option("-o,--output", output_dir, "Output folder (default: runs/<scene file stem>)")->type_name("DIR");
  bool resume = false;
  run->add_flag("--resume", resume,
                "Continue an interrupted SPH run from DIR/checkpoint.bin (same scene, same DIR); the result is the "
                "same as an uninterrupted run");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);  // prints help, the version or the usage error
    return code == 0 ? 0 : static_cast<int>(coupling::ExitStatus::invalid_input);
  }

  coupling::WorkflowOptions options;
  options.log = &std::cerr;
  if (check->parsed()) {
    options.mode = coupling::Mode::check;
  } else if (lem->parsed()) {
    options.mode = coupling::Mode::lem;
    if (!output_dir.empty()) options.output_dir = output_dir;
  } else {
    options.mode = coupling::Mode::run;
    options.resume = resume;
    coupling::install_interrupt_handler();  // Ctrl-C: checkpoint, report "interrupted", exit 1; --resume continues
    options.output_dir = output_dir.empty() ? coupling::default_output_dir(scene_file)
                                            : std::filesystem::path(output_dir);
  }

  try {
    const coupling::WorkflowResult result = coupling::run_scene_file(scene_file, options);
    return print_outcome(scene_file, result, options.mode);
  } catch (const std::exception& error) {
    std::cerr << "sphslope: unexpected failure: " << error.what() << "\n";
    return static_cast<int>(coupling::ExitStatus::failed);
  }
}
