#include "harness/results/run_context.h"

#include "harness/results/library_versions.h"
#include "holebench/version.h"

#include <unistd.h>

#include <chrono>
#include <ctime>

namespace holebench::harness {

RunContext current_context(const std::string& suite) {
  RunContext context;
  context.code_version = HOLEBENCH_GIT_DESCRIBE;
  context.build_type = HOLEBENCH_BUILD_TYPE;
  char host[256] = {0};
  if (gethostname(host, sizeof(host) - 1) == 0)
    context.host = host;
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char stamp[32];
  std::strftime(stamp, sizeof(stamp), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  context.created_utc = stamp;
  context.suite = suite;
  context.libraries = library_versions();
  return context;
}

}  // namespace holebench::harness
