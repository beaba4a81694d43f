// What the mesh readers share (core/mesh_io/read_*.cpp): errors that name the file, tokens,
// numbers and lines of text, integers of binary data. Internal to core's mesh I/O.
#pragma once

#include "core/mesh_io.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace holebench::mesh_io {

using Tokens = std::vector<std::string_view>;

/// Throws InvalidInputError "<source>: <what>".
[[noreturn]] void fail(const std::string& source, const std::string& what);

char to_lower(char c);

bool iequals(std::string_view a, std::string_view b);

bool is_space(char c);

/// A token for an error message: quoted, shortened, non-printable bytes escaped.
std::string show(std::string_view token);

void split(std::string_view line, Tokens& tokens);

std::string_view strip_comment(std::string_view line);

/// Parses a whole token as a double ("nan" and "inf" included: build_mesh rejects them
/// with the vertex number). Returns an empty string or the reason it failed.
std::string parse_double(std::string_view s, double& out);

/// Parses a whole token as a decimal integer; returns false on failure or overflow.
bool parse_int(std::string_view s, long long& out);

bool parse_uint64(std::string_view s, std::uint64_t& out);

/// Text formats: a NUL byte means binary data (an image renamed .off, for example).
void check_text(const std::string& source, std::string_view text, std::string_view format);

/// Appends a polygon as a fan of triangles (c0 c1 c2), (c0 c2 c3), ...
void add_fan(TriangleSoup& soup, const std::vector<int>& corners);

/// An unsigned integer of `size` bytes of binary data, little or big endian.
std::uint64_t read_unsigned(const char* p, int size, bool big_endian);

/// Lines of a text, without their terminators ("\n" or "\r\n"), numbered from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  bool next(std::string_view& line) {
    if (pos_ >= text_.size())
      return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos)
      end = text_.size();
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    pos_ = end + 1;
    ++line_;
    return true;
  }

  /// Next line with at least one token (after removing '#' comments if asked).
  bool next_tokens(Tokens& tokens, bool strip_comments) {
    std::string_view line;
    while (next(line)) {
      split(strip_comments ? strip_comment(line) : line, tokens);
      if (!tokens.empty())
        return true;
    }
    return false;
  }

  std::size_t line() const { return line_; }  ///< number of the last line returned
  std::size_t position() const { return std::min(pos_, text_.size()); }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

}  // namespace holebench::mesh_io
