// Patterns of case ids: '*' matches any run of characters (also '/'), '?' one. Pure string
// functions, apart from the catalog (harness/run/case_selection.h selects cases with them).
#pragma once

#include <string>
#include <vector>

namespace holebench::harness {

/// Whether `text` matches the wildcard `pattern` as a whole. Time O(|pattern| * |text|) at
/// worst, memory O(1).
bool wildcard_match(const std::string& pattern, const std::string& text);

/// The families (the id's first component) that `patterns` can match; empty when a pattern
/// starts with a wildcard (any family).
std::vector<std::string> families_of_patterns(const std::vector<std::string>& patterns);

}  // namespace holebench::harness
