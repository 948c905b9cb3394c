// The durable writer (sph/atomic_file.hpp): every file the program writes goes through it, so a reader (or a
// resumed run) sees either the previous file or the complete new one, never a torn one.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <thread>

#include "sph/engine/atomic_file.hpp"

namespace test_atomic_file {

namespace fs = std::filesystem;

namespace {

fs::path fresh_folder(const std::string& tag) {
  const fs::path folder = fs::temp_directory_path() / ("sphslope-atomic-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Version k of a large file: 4 MiB of one repeated byte, so a torn mix of two versions (or a short file) shows.
constexpr std::size_t version_bytes = std::size_t{4} << 20;
std::string version(unsigned k) { return std::string(version_bytes, static_cast<char>('a' + k % 26)); }

bool is_a_complete_version(const std::string& text) {
  return text.size() == version_bytes && text.find_first_not_of(text.front()) == std::string::npos;
}

}  // namespace

TEST_CASE("the durable writer replaces the file and leaves no temporary behind", "[io]") {
  const fs::path folder = fresh_folder("replace");
  const fs::path file = folder / "report.json";
  sph::write_file_atomically(file, "first");
  sph::write_file_atomically(file, "second, longer content\n");
  CHECK(file_text(file) == "second, longer content\n");
  CHECK(std::distance(fs::directory_iterator(folder), fs::directory_iterator()) == 1);
  CHECK_THROWS_AS(sph::write_file_atomically(folder / "missing" / "x.json", "x"), std::system_error);
  fs::remove_all(folder);
}

TEST_CASE("a writer killed at any moment leaves the old file or the new one, never a torn one", "[io]") {
  // A child process rewrites one 4 MiB file as fast as it can, each version a different byte; it is killed with
  // SIGKILL (no chance to clean up) after delays spread over several write times. Whatever the moment, the file
  // must be one complete version. The child only writes files (no threads), so fork is safe here.
  const fs::path folder = fresh_folder("kill");
  const fs::path file = folder / "checkpoint.bin";
  sph::write_file_atomically(file, version(0));
  int replaced = 0;  // trials after which the file held a version the child wrote: the kills came mid-run
  for (int trial = 0; trial < 13; ++trial) {
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      for (unsigned k = 1;; ++k) sph::write_file_atomically(file, version(k));
    }
    if (trial < 12) {
      std::this_thread::sleep_for(std::chrono::microseconds(1500 * trial + 300));
    } else {
      // The last trial kills the writer only once it has replaced the file (at most 20 s): under the sanitizers on
      // a loaded machine a child can take longer to write its first version than every delay above (seen in CI).
      const std::string before = file_text(file);
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (file_text(file) == before && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    REQUIRE(WIFSIGNALED(status));
    INFO("trial " << trial);
    const std::string text = file_text(file);
    CHECK(is_a_complete_version(text));
    replaced += text != version(0);
  }
  CHECK(replaced > 0);
  // Stray temporaries of killed writers may remain; they never replace the file.
  fs::remove_all(folder);
}

}  // namespace test_atomic_file
