#include "harness/results/library_versions.h"

#include "holebench/version.h"

#include <CGAL/version.h>
#include <OpenImageIO/oiioversion.h>  // macros only: the library is the image module's
#include <OpenMesh/Core/System/config.h>
#include <embree3/rtcore_config.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace holebench::harness {

std::vector<std::pair<std::string, std::string>> library_versions() {
  return {
      {"holebench", HOLEBENCH_VERSION},
      {"CGAL", CGAL_VERSION_STR},
      {"OpenMesh", fmt::format("{}.{}", OM_GET_VER, OM_GET_MAJ)},
      {"Embree", RTC_VERSION_STRING},
      {"OpenImageIO", OIIO_VERSION_STRING},
      {"fmt",
       fmt::format("{}.{}.{}", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100)},
      {"nlohmann_json", fmt::format("{}.{}.{}", NLOHMANN_JSON_VERSION_MAJOR,
                                    NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
      {"compiler", __VERSION__},
  };
}

}  // namespace holebench::harness
