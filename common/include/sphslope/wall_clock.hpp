#pragma once
// The wall clock of progress lines, timings and benchmarks: one steady clock and one way to read it.
#include <chrono>

namespace sphslope {

using WallClock = std::chrono::steady_clock;

// Wall-clock seconds since `start`.
inline double seconds_since(WallClock::time_point start) {
  return std::chrono::duration<double>(WallClock::now() - start).count();
}

}  // namespace sphslope
