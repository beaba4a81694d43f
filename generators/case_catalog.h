// The catalog of generated cases: every case has a stable id and is fully determined by
// its id and seed.
#pragma once

#include "core/case.h"

#include <cstdint>
#include <string>
#include <vector>

namespace holebench::generators {

struct CaseDescriptor {
  std::string id;           ///< stable id, e.g. "box/corner"
  std::string family;       ///< e.g. "box"
  std::string kind;         ///< e.g. "corner"
  std::string description;  ///< one line for `holebench list`
};

/// Every case the generators know, in a fixed order.
std::vector<CaseDescriptor> list_cases();

/// Generates the case `id`. Throws std::invalid_argument for an unknown id.
Case make_case(const std::string& id, std::uint64_t seed = 0);

}  // namespace holebench::generators
