// libFuzzer target: the scene reader and every check that `sphslope check` performs, on arbitrary bytes.
// A finding is anything but "valid scene" or "SceneError with messages": a crash, a sanitizer report, an
// exception of another type (the program would exit 1 "unexpected failure" instead of 2), a hang or a blow-up of
// memory. Each finding is kept as a file in tests/coupling/bad_scenes/ with its test (tests/fuzz/README.md).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "coupling/scene/scene.hpp"
#include "coupling/output/run_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const coupling::Scene scene = coupling::parse_scene(text, "fuzz.json");
    coupling::WorkflowOptions options;
    options.mode = coupling::Mode::check;  // validation and the SPH size plan only: nothing is run or written
    const coupling::WorkflowResult result = coupling::run_scene(scene, options);
    if (result.status == coupling::ExitStatus::failed) std::abort();  // check never "fails a run"
    if (coupling::summarize(scene).empty()) std::abort();
  } catch (const coupling::SceneError& error) {
    if (error.messages().empty()) std::abort();  // an invalid scene always says what is wrong
  }
  return 0;
}
