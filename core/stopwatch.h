// Wall time of a stage or a phase: the one clock every module times itself with (the
// records' `stages_s`, `phases_s` and hole `seconds`).
#pragma once

#include <chrono>

namespace holebench {

using SteadyClock = std::chrono::steady_clock;

/// Seconds of wall time since `start` (a SteadyClock::now() taken earlier).
inline double seconds_since(SteadyClock::time_point start) {
  return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

}  // namespace holebench
