// Splitting text at a separator: "a/b//c" at '/' gives "a", "b", "", "c".
#pragma once

#include <string>
#include <vector>

namespace holebench {

/// The parts of `text` between the `separator`s, empty parts included; one part (the whole
/// text) where it has none.
inline std::vector<std::string> split_text(const std::string& text, char separator) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const auto at = text.find(separator, start);
    parts.push_back(text.substr(start, at - start));
    if (at == std::string::npos)
      return parts;
    start = at + 1;
  }
}

}  // namespace holebench
