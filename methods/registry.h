// Every method holebench can run, by id.
#pragma once

#include "methods/method.h"

#include <memory>
#include <string>
#include <vector>

namespace holebench {

/// One instance of each method with its default options, in a fixed order.
std::vector<std::unique_ptr<Method>> make_all_methods();

/// The named variants of the papers' methods, run by name only (`--method ID`, or a suite
/// that lists them), not in a run that names no method: each paper method with the project's
/// departures (brep_guidance_plus, slice_loft_plus, slice_direct_plus, crest_feature_plus) and
/// brep_guidance_segmented (segmenting even inputs that carry B-Rep faces).
std::vector<std::unique_ptr<Method>> make_named_variants();

/// The slice paper's Table 2 ablation: slice_loft and slice_direct with one departure each
/// (methods/slice_loft/slice_loft_variants.h), run by name only.
std::vector<std::unique_ptr<Method>> make_ablation_methods();

/// The named variants, then the ablation's methods.
std::vector<std::unique_ptr<Method>> make_methods_run_by_name();

/// The method `id` (of either list) with its options, or nullptr for an unknown id.
std::unique_ptr<Method> find_method(const std::string& id);

/// The method `id` (of either list) with its options; throws std::invalid_argument for an
/// unknown id.
std::unique_ptr<Method> make_method(const std::string& id);

}  // namespace holebench
