// External methods holebench predefines: run by name (`--method NAME`, or a suite's
// "external_methods": [{"name": NAME}]), never as part of "every method" (each job starts a
// process).
#pragma once

#include "methods/external/external_method_spec.h"

#include <optional>
#include <string>
#include <vector>

namespace holebench {

/// Every predefined external method.
std::vector<ExternalMethodSpec> predefined_external_methods();

/// The predefined external method `name`, if there is one.
std::optional<ExternalMethodSpec> find_predefined_external_method(const std::string& name);

}  // namespace holebench
