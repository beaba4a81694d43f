#include "core/mesh_io/parsing.h"

#include "core/errors.h"

#include <fmt/format.h>

#include <charconv>
#include <system_error>

namespace holebench::mesh_io {

/// Throws InvalidInputError "<source>: <what>".
[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw InvalidInputError(fmt::format("{}: {}", source, what));
}

char to_lower(char c) {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (to_lower(a[i]) != to_lower(b[i]))
      return false;
  }
  return true;
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/// A token for an error message: quoted, shortened, non-printable bytes escaped.
std::string show(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += fmt::format("\\x{:02x}", c);
    }
  }
  if (token.size() > kMax)
    out += "...";
  return out + "'";
}

void split(std::string_view line, Tokens& tokens) {
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i]))
      ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i]))
      ++i;
    if (i > start)
      tokens.push_back(line.substr(start, i - start));
  }
}

std::string_view strip_comment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

/// Parses a whole token as a double ("nan" and "inf" included: build_mesh rejects them
/// with the vertex number). Returns an empty string or the reason it failed.
std::string parse_double(std::string_view s, double& out) {
  std::string_view digits = s;
  if (!digits.empty() && digits.front() == '+') {
    digits.remove_prefix(1);  // from_chars takes no '+'
    if (!digits.empty() && digits.front() == '-')
      digits = {};
  }
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, out);
  if (ec == std::errc::result_out_of_range) {
    return fmt::format("the number {} is out of the range of a double", show(s));
  }
  if (ec != std::errc() || ptr != end)
    return fmt::format("cannot parse {} as a number", show(s));
  return {};
}

/// Parses a whole token as a decimal integer; returns false on failure or overflow.
bool parse_int(std::string_view s, long long& out) {
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && s.front() == '-')
      return false;
  }
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, out);
  return !s.empty() && ec == std::errc() && ptr == end;
}

bool parse_uint64(std::string_view s, std::uint64_t& out) {
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, out);
  return !s.empty() && ec == std::errc() && ptr == end;
}

/// Text formats: a NUL byte means binary data (an image renamed .off, for example).
void check_text(const std::string& source, std::string_view text, std::string_view format) {
  const std::size_t nul = text.find('\0');
  if (nul != std::string_view::npos) {
    fail(source, fmt::format("byte {}: binary data (a NUL byte) in what should be a text {} "
                             "file; not an {} file",
                             nul, format, format));
  }
}

/// Appends a polygon as a fan of triangles (c0 c1 c2), (c0 c2 c3), ...
void add_fan(TriangleSoup& soup, const std::vector<int>& corners) {
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    soup.triangles.push_back({corners[0], corners[k], corners[k + 1]});
  }
}

std::uint64_t read_unsigned(const char* p, int size, bool big_endian) {
  std::uint64_t u = 0;
  for (int i = 0; i < size; ++i) {
    const int k = big_endian ? i : size - 1 - i;
    u = (u << 8) | static_cast<unsigned char>(p[k]);
  }
  return u;
}

}  // namespace holebench::mesh_io
