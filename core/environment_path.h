// A folder a user may move with an environment variable (HOLEBENCH_CAD_DIR,
// HOLEBENCH_SUITES_DIR, HOLEBENCH_THREE_DIR): the variable's value where it is set and not
// empty, else the build's default.
#pragma once

#include <cstdlib>
#include <filesystem>

namespace holebench {

inline std::filesystem::path environment_path_or(const char* variable, const char* fallback) {
  if (const char* value = std::getenv(variable); value && *value)
    return value;
  return fallback;
}

}  // namespace holebench
