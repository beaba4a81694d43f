#include "harness/run/case_pattern.h"

#include <algorithm>

namespace holebench::harness {

bool wildcard_match(const std::string& pattern, const std::string& text) {
  // Iterative matching with one backtrack point for the last '*'.
  std::size_t p = 0, t = 0, star = std::string::npos, mark = 0;
  while (t < text.size()) {
    // A '*' is a wildcard even where the text holds a '*' too: tested before the literal.
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = t;
    } else if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++p;
      ++t;
    } else if (star != std::string::npos) {
      p = star + 1;
      t = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*')
    ++p;
  return p == pattern.size();
}

std::vector<std::string> families_of_patterns(const std::vector<std::string>& patterns) {
  std::vector<std::string> families;
  for (const auto& pattern : patterns) {
    const std::string family = pattern.substr(0, pattern.find('/'));
    if (family.find_first_of("*?") != std::string::npos)
      return {};
    if (std::find(families.begin(), families.end(), family) == families.end())
      families.push_back(family);
  }
  return families;
}

}  // namespace holebench::harness
