// Every method holebench can run, by id.
#pragma once

#include "methods/method.h"

#include <memory>
#include <string>
#include <vector>

namespace holebench {

/// One instance of each method with its default options, in a fixed order.
std::vector<std::unique_ptr<Method>> make_all_methods();

/// Built-in variants run by name only (`--method ID`), not in a run that names no method:
/// brep_guidance_segmented (brep_guidance segmenting even inputs that carry B-Rep faces).
std::vector<std::unique_ptr<Method>> make_methods_run_by_name();

/// The method `id` (of either list) with its options, or nullptr for an unknown id.
std::unique_ptr<Method> find_method(const std::string& id);

/// The method `id` (of either list) with its options; throws std::invalid_argument for an
/// unknown id.
std::unique_ptr<Method> make_method(const std::string& id);

}  // namespace holebench
