// Every method holebench can run, by id.
#pragma once

#include "methods/method.h"

#include <memory>
#include <string>
#include <vector>

namespace holebench {

/// One instance of each method with its default options, in a fixed order.
std::vector<std::unique_ptr<Method>> make_all_methods();

/// The method `id` with default options; throws std::invalid_argument for an unknown id.
std::unique_ptr<Method> make_method(const std::string& id);

}  // namespace holebench
