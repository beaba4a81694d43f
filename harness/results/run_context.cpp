#include "harness/results/run_context.h"

#include "harness/outputs/render/image.h"
#include "holebench/version.h"

#include <CGAL/version.h>
#include <OpenMesh/Core/System/config.h>
#include <embree3/rtcore_config.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

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
  context.libraries = {
      {"holebench", HOLEBENCH_VERSION},
      {"CGAL", CGAL_VERSION_STR},
      {"OpenMesh", fmt::format("{}.{}", OM_GET_VER, OM_GET_MAJ)},
      {"Embree", RTC_VERSION_STRING},
      {"OpenImageIO", render::openimageio_version()},
      {"fmt",
       fmt::format("{}.{}.{}", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100)},
      {"nlohmann_json", fmt::format("{}.{}.{}", NLOHMANN_JSON_VERSION_MAJOR,
                                    NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
      {"compiler", __VERSION__},
  };
  return context;
}

}  // namespace holebench::harness
