// Fuzz target: case ids and patterns (harness/run/case_pattern.h). The input is a pattern, a
// newline, and an id. Properties: matching terminates without a sanitizer report; every
// text matches itself ('?' and '*' match themselves too) and matches "*"; a pattern's
// families are prefixes of it.
#include "harness/run/case_pattern.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const auto newline = input.find('\n');
  const std::string pattern = input.substr(0, newline);
  const std::string id = newline == std::string::npos ? "" : input.substr(newline + 1);
  using holebench::harness::wildcard_match;
  wildcard_match(pattern, id);
  if (!wildcard_match(id, id) || !wildcard_match(pattern, pattern) || !wildcard_match("*", id))
    std::abort();
  if (wildcard_match(pattern, id) != wildcard_match(pattern + "*", id) &&
      !wildcard_match(pattern + "*", id))
    std::abort();  // appending '*' never loses a match
  for (const auto& family : holebench::harness::families_of_patterns({pattern, id})) {
    if (pattern.rfind(family, 0) != 0 && id.rfind(family, 0) != 0)
      std::abort();
  }
  return 0;
}
