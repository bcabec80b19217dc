// Seconds of wall-clock time, for the stages a summary reports.
#pragma once

#include <chrono>

namespace offsetgen {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace offsetgen
