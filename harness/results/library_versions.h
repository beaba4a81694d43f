// The versions of the libraries this build links, as a results file's context names them
// (harness/results/run_context.h) and as `holebench --version` could print them.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace holebench::harness {

/// Name and version of holebench and of each library it is built with, in a fixed order.
std::vector<std::pair<std::string, std::string>> library_versions();

}  // namespace holebench::harness
