// Synthetic planar B-Rep cases: every k <= 3 combination of CASES.md and its variants.
#pragma once

#include "core/case.h"
#include "generators/case_catalog.h"

#include <string>
#include <vector>

namespace holebench::generators {

/// Every synthetic B-Rep case, ids "brep/...", in a fixed order.
std::vector<CaseDescriptor> list_brep_cases();

/// The clean case `id` (no noise; the catalog adds noise). Throws std::invalid_argument for
/// an unknown id.
Case make_brep_case(const std::string& id);

}  // namespace holebench::generators
