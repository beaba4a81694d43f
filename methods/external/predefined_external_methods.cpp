#include "methods/external/predefined_external_methods.h"

namespace holebench {

std::vector<ExternalMethodSpec> predefined_external_methods() {
  return {};
}

std::optional<ExternalMethodSpec> find_predefined_external_method(const std::string& name) {
  for (auto& spec : predefined_external_methods()) {
    if (spec.name == name)
      return spec;
  }
  return std::nullopt;
}

}  // namespace holebench
