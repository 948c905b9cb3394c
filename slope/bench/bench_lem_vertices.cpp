// bench-lem-vertices: cost of the default critical-circle search (all seven methods, refinement on) against the
// number of ground-profile vertices, 10 to 100 000. The Griffiths & Lane (1999) slope (H = 10 m, 2:1, c' = 10 kPa,
// phi' = 20 deg) is written with more vertices two ways:
//   collinear  every segment split into collinear pieces: the same geometry, so the same factors of safety;
//   rough      the same, with 5 cm of deterministic pseudo-random relief on every inner vertex (a survey's noise).
// Each size runs in a child process, so the peak resident memory printed is that run's own (getrusage of the
// child). With --cli PATH the whole program (`PATH lem SCENE`: reading, checks, search, table) is timed the same
// way on a scene file written for each size. A benchmark program, not a test (docs/performance.md).
// Usage: bench-lem-vertices [--cli path/to/sphslope] [--max N]
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "slope/search.hpp"
#include "sphslope/units.hpp"

namespace {

using Clock = std::chrono::steady_clock;

std::vector<slope::Point> griffiths_lane_ground(std::size_t vertices, bool rough) {
  const std::vector<slope::Point> corners{{0, 20}, {20, 20}, {40, 10}, {60, 10}};
  const std::size_t per_segment = std::max<std::size_t>(1, (vertices - 1) / 3);
  std::vector<slope::Point> points;
  std::uint64_t state = 88172645463325252ULL;  // xorshift64: the same noise on every machine
  for (std::size_t s = 0; s + 1 < corners.size(); ++s) {
    for (std::size_t k = 0; k < per_segment; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(per_segment);
      slope::Point p{corners[s].x + t * (corners[s + 1].x - corners[s].x),
                     corners[s].y + t * (corners[s + 1].y - corners[s].y)};
      state ^= state << 13;
      state ^= state >> 7;
      state ^= state << 17;
      if (rough && !points.empty()) p.y += 0.05 * (static_cast<double>(state % 2001) / 1000.0 - 1.0);
      points.push_back(p);
    }
  }
  points.push_back(corners.back());
  return points;
}

slope::Section section_with(const std::vector<slope::Point>& ground) {
  slope::Section s;
  s.bottom_y = 0.0;
  s.materials.push_back({"soil", 20e3, 10e3, sphslope::radians(20.0)});
  s.profile_lines.push_back({0, ground});
  return s;
}

struct ChildRun {
  double wall_s = 0.0;
  double peak_MB = 0.0;
  int status = -1;
  std::string output;  // what the child wrote to its pipe
};

// Runs `work` in a child process; its standard output comes back through a pipe.
template <class Work>
ChildRun in_child(Work work) {
  int fds[2];
  std::fflush(stdout);  // nothing buffered may be written twice by the child
  if (pipe(fds) != 0) std::exit(1);
  const auto start = Clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    dup2(fds[1], STDOUT_FILENO);
    work();
    std::fflush(stdout);
    _exit(0);
  }
  close(fds[1]);
  ChildRun run;
  char buffer[4096];
  ssize_t got;
  while ((got = read(fds[0], buffer, sizeof buffer)) > 0) run.output.append(buffer, static_cast<std::size_t>(got));
  close(fds[0]);
  int status = 0;
  struct rusage usage {};
  wait4(pid, &status, 0, &usage);
  run.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  run.peak_MB = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return run;
}

void search_row(std::size_t vertices, bool rough) {
  const ChildRun run = in_child([&]() {
    const slope::Section section = section_with(griffiths_lane_ground(vertices, rough));
    const auto start = Clock::now();
    const slope::SearchResult result = slope::search_critical(section, slope::all_methods(), slope::SearchOptions{});
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    std::printf("%8.3f %10ld", seconds, result.trial_surfaces);
    for (const slope::CriticalSurface& c : result.methods)
      if (c.method == slope::Method::bishop || c.method == slope::Method::spencer)
        std::printf(" %8.4f", c.result.factor_of_safety.value_or(std::nan("")));
  });
  std::printf("%-9s %8zu  %s %9.3f %9.1f%s\n", rough ? "rough" : "collinear",
              section_with(griffiths_lane_ground(vertices, rough)).profile_lines.front().points.size(),
              run.output.c_str(), run.wall_s, run.peak_MB, run.status == 0 ? "" : "  (child failed)");
  std::fflush(stdout);
}

std::string write_scene(std::size_t vertices, bool rough) {
  const std::string path = "/tmp/bench-lem-vertices-" + std::to_string(getpid()) + ".json";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) std::exit(1);
  std::fprintf(f, "{\"format\": \"sphslope-scene/1\", \"name\": \"bench\", \"section\": {\"bottom_y_m\": 0,\n"
                  "\"materials\": [{\"name\": \"soil\", \"unit_weight_kN_m3\": 20, \"cohesion_kPa\": 10, "
                  "\"friction_angle_deg\": 20}],\n\"profile_lines\": [{\"material\": \"soil\", \"points_m\": [");
  const auto ground = griffiths_lane_ground(vertices, rough);
  for (std::size_t i = 0; i < ground.size(); ++i)
    std::fprintf(f, "%s[%.17g, %.17g]", i == 0 ? "" : ",", ground[i].x, ground[i].y);
  std::fprintf(f, "]}]},\n\"analyses\": {\"lem\": {}}}\n");
  std::fclose(f);
  return path;
}

void cli_row(const char* program, std::size_t vertices, bool rough) {
  const std::string scene = write_scene(vertices, rough);
  const ChildRun run = in_child([&]() {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    execl(program, program, "lem", scene.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  });
  std::printf("%-9s %8zu  whole program %9.3f s %9.1f MB%s\n", rough ? "rough" : "collinear",
              griffiths_lane_ground(vertices, rough).size(), run.wall_s, run.peak_MB,
              run.status == 0 ? "" : ("  (exit status " + std::to_string(run.status) + ")").c_str());
  std::fflush(stdout);
  std::remove(scene.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const char* cli = nullptr;
  std::size_t max_vertices = 100000;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--cli") == 0 && i + 1 < argc) cli = argv[++i];
    else if (std::strcmp(argv[i], "--max") == 0 && i + 1 < argc) max_vertices = std::strtoul(argv[++i], nullptr, 10);
    else {
      std::fprintf(stderr, "usage: bench-lem-vertices [--cli path/to/sphslope] [--max N]\n");
      return 2;
    }
  }
  const std::size_t sizes[] = {10, 100, 1000, 2000, 10000, 20000, 100000};
  std::printf("bench-lem-vertices: default search, all seven methods, Griffiths & Lane (1999) slope, one process per "
              "row\n");
  std::printf("%-9s %8s  %8s %10s %8s %8s %9s %9s\n", "profile", "vertices", "search_s", "FS_evals", "FS_bish",
              "FS_spen", "process_s", "peak_MB");
  for (bool rough : {false, true})
    for (std::size_t n : sizes)
      if (n <= max_vertices) search_row(n, rough);
  if (cli != nullptr)
    for (bool rough : {false, true})
      for (std::size_t n : sizes)
        if (n <= max_vertices) cli_row(cli, n, rough);
  return 0;
}
