#include "generators/brep/brep_cases.h"

#include <stdexcept>

namespace holebench::generators {

std::vector<CaseDescriptor> list_brep_cases() { return {}; }

Case make_brep_case(const std::string& id) {
  throw std::invalid_argument("unknown B-Rep case id '" + id + "'");
}

}  // namespace holebench::generators
