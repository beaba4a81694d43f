// Mesh file reading and writing with holebench's own parsers, so that every error names
// the file and the place (line for text, byte offset for binary data).
#include "core/mesh_io.h"

#include "core/errors.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace holebench {
namespace {

namespace fs = std::filesystem;
using Tokens = std::vector<std::string_view>;

// ------------------------------------------------------------------ small helpers

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

/// Appends a polygon as a fan of triangles (c0 c1 c2), (c0 c2 c3), ...
void add_fan(TriangleSoup& soup, const std::vector<int>& corners) {
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    soup.triangles.push_back({corners[0], corners[k], corners[k + 1]});
  }
}

// ------------------------------------------------------------------ OFF

TriangleSoup read_off(const std::string& src, std::string_view text) {
  check_text(src, text, "OFF");
  LineReader lines(text);
  Tokens tok;
  if (!lines.next_tokens(tok, true)) {
    fail(src, "the file has only blank lines and comments; not an OFF mesh");
  }
  std::size_t first = 0;  // index of the vertex count on the counts line
  const std::string_view head = tok[0];
  if (head.size() >= 3 && head.substr(head.size() - 3) == "OFF") {
    const std::string_view prefix = head.substr(0, head.size() - 3);
    if (prefix.find_first_not_of("STCN") != std::string_view::npos) {
      fail(src, fmt::format("line {}: unsupported OFF variant {} (holebench reads OFF, COFF, "
                            "NOFF and STOFF with 3D vertices)",
                            lines.line(), show(head)));
    }
    if (tok.size() > 1 && tok[1] == "BINARY") {
      fail(src, fmt::format("line {}: binary OFF is not supported", lines.line()));
    }
    first = 1;  // "OFF <vertices> <faces> <edges>" on one line
    if (tok.size() == 1) {
      if (!lines.next_tokens(tok, true)) {
        fail(src, fmt::format("line {}: truncated: the file ends after the OFF header, before "
                              "the vertex and face counts",
                              lines.line()));
      }
      first = 0;
    }
  } else {
    long long ignored = 0;
    if (!parse_int(head, ignored)) {
      fail(src, fmt::format("line {}: expected the 'OFF' header or the vertex and face counts, "
                            "found {}; not an OFF file",
                            lines.line(), show(head)));
    }
  }
  long long nv = 0;
  long long nf = 0;
  if (tok.size() < first + 2 || !parse_int(tok[first], nv) || !parse_int(tok[first + 1], nf) ||
      nv < 0 || nf < 0) {
    fail(src, fmt::format("line {}: expected the vertex and face counts ('<vertices> <faces> "
                          "<edges>'), found {}",
                          lines.line(), show(tok[std::min(first, tok.size() - 1)])));
  }

  TriangleSoup soup;
  for (long long i = 0; i < nv; ++i) {
    if (!lines.next_tokens(tok, true)) {
      fail(src, fmt::format("line {}: truncated: the file ends after {} of {} vertices",
                            lines.line(), i, nv));
    }
    if (tok.size() < 3) {
      fail(src, fmt::format("line {}: expected 3 coordinates for vertex {}, found {} value{}",
                            lines.line(), i, tok.size(), tok.size() == 1 ? "" : "s"));
    }
    Point p;
    for (int c = 0; c < 3; ++c) {
      const std::string error = parse_double(tok[c], p[c]);
      if (!error.empty()) {
        fail(src,
             fmt::format("line {}: {} (coordinate {} of vertex {})", lines.line(), error, c, i));
      }
    }
    soup.points.push_back(p);
  }

  std::vector<int> corners;
  for (long long j = 0; j < nf; ++j) {
    if (!lines.next_tokens(tok, true)) {
      fail(src, fmt::format("line {}: truncated: the file ends after {} of {} faces", lines.line(),
                            j, nf));
    }
    long long n = 0;
    if (!parse_int(tok[0], n)) {
      fail(src, fmt::format("line {}: expected the number of vertices of face {}, found {}",
                            lines.line(), j, show(tok[0])));
    }
    if (n < 3) {
      fail(src, fmt::format("line {}: face {} has {} vertices; a face needs at least 3",
                            lines.line(), j, n));
    }
    if (static_cast<long long>(tok.size()) - 1 < n) {
      fail(src, fmt::format("line {}: face {} declares {} vertices but lists {} indices",
                            lines.line(), j, n, tok.size() - 1));
    }
    corners.clear();
    for (long long k = 1; k <= n; ++k) {
      long long index = 0;
      if (!parse_int(tok[k], index)) {
        fail(src, fmt::format("line {}: cannot parse {} as a vertex index (face {})", lines.line(),
                              show(tok[k]), j));
      }
      if (index < 0 || index >= nv) {
        fail(src, fmt::format("line {}: face {} references vertex {}, but there are {} vertices "
                              "(indices start at 0)",
                              lines.line(), j, index, nv));
      }
      corners.push_back(static_cast<int>(index));
    }
    add_fan(soup, corners);  // anything after the indices (a colour) is ignored
  }
  return soup;
}

// ------------------------------------------------------------------ OBJ

TriangleSoup read_obj(const std::string& src, std::string_view text) {
  check_text(src, text, "OBJ");
  LineReader lines(text);
  Tokens tok;
  TriangleSoup soup;
  std::vector<int> corners;
  // Positive indices may refer to vertices defined later; checked at the end.
  std::vector<std::pair<std::size_t, long long>> forward;  // (line, 1-based index)
  bool any_face = false;
  while (lines.next_tokens(tok, true)) {
    const std::string_view keyword = tok[0];
    if (keyword == "v") {
      if (tok.size() < 4) {
        fail(src, fmt::format("line {}: expected 3 coordinates after 'v', found {}", lines.line(),
                              tok.size() - 1));
      }
      Point p;
      for (int c = 0; c < 3; ++c) {
        const std::string error = parse_double(tok[c + 1], p[c]);
        if (!error.empty()) {
          fail(src, fmt::format("line {}: {} (coordinate {} of vertex {})", lines.line(), error, c,
                                soup.points.size()));
        }
      }
      soup.points.push_back(p);  // an optional w (or colour) is ignored
    } else if (keyword == "f") {
      any_face = true;
      if (tok.size() < 4) {
        fail(src, fmt::format("line {}: a face needs at least 3 vertices, found {}", lines.line(),
                              tok.size() - 1));
      }
      corners.clear();
      const auto defined = static_cast<long long>(soup.points.size());
      for (std::size_t k = 1; k < tok.size(); ++k) {
        const std::string_view vertex = tok[k].substr(0, tok[k].find('/'));
        long long index = 0;
        if (!parse_int(vertex, index)) {
          fail(src, fmt::format("line {}: cannot parse face vertex {} (expected i, i/j, i//k or "
                                "i/j/k)",
                                lines.line(), show(tok[k])));
        }
        if (index == 0) {
          fail(src, fmt::format("line {}: face vertex {} has index 0; OBJ indices start at 1",
                                lines.line(), show(tok[k])));
        }
        if (index < 0) {
          if (-index > defined) {
            fail(src, fmt::format("line {}: relative index {} references a vertex before the "
                                  "first ({} vertices are defined so far)",
                                  lines.line(), index, defined));
          }
          index = defined + index + 1;
        } else if (index > defined) {
          if (index > std::numeric_limits<int>::max()) {
            fail(src, fmt::format("line {}: face references vertex {}, more than holebench "
                                  "supports",
                                  lines.line(), index));
          }
          if (forward.empty() || forward.back().second < index) {
            forward.emplace_back(lines.line(), index);
          }
        }
        corners.push_back(static_cast<int>(index - 1));
      }
      add_fan(soup, corners);
    }
    // vt, vn, vp, g, o, s, usemtl, mtllib, l, p and the rest are ignored.
  }
  if (soup.points.empty() && !any_face) {
    fail(src, "no vertex ('v') or face ('f') statements; not an OBJ mesh");
  }
  const auto total = static_cast<long long>(soup.points.size());
  for (const auto& [line, index] : forward) {
    if (index > total) {
      fail(src, fmt::format("line {}: face references vertex {}, but the file has {} vertices",
                            line, index, total));
    }
  }
  return soup;
}

// ------------------------------------------------------------------ STL

/// Merges STL corners with identical coordinates into one vertex.
class VertexMerger {
 public:
  explicit VertexMerger(TriangleSoup& soup) : soup_(soup) {}
  int add(const Point& p) {
    const auto [it, inserted] =
        index_.emplace(std::array<double, 3>{p[0], p[1], p[2]}, static_cast<int>(index_.size()));
    if (inserted)
      soup_.points.push_back(p);
    return it->second;
  }

 private:
  TriangleSoup& soup_;
  std::map<std::array<double, 3>, int> index_;
};

bool finite(const Point& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

/// Whitespace-separated tokens of a whole text, with the line of each.
class Tokenizer {
 public:
  explicit Tokenizer(std::string_view text) : text_(text) {}

  bool next(std::string_view& token) {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n')
        ++line_;
      ++pos_;
    }
    if (pos_ >= text_.size())
      return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_]))
      ++pos_;
    token = text_.substr(start, pos_ - start);
    token_line_ = line_;
    return true;
  }
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n')
      ++pos_;
  }
  std::size_t token_line() const { return token_line_; }  ///< line of the last token

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t token_line_ = 1;
};

TriangleSoup read_stl_ascii(const std::string& src, std::string_view text) {
  Tokenizer tz(text);
  std::string_view tok;
  TriangleSoup soup;
  VertexMerger merger(soup);
  std::size_t facet = 0;

  auto next = [&](std::string_view expected) {
    if (!tz.next(tok)) {
      fail(src, fmt::format("line {}: truncated: the file ends inside facet {} (expected {})",
                            tz.token_line(), facet, expected));
    }
  };
  auto expect = [&](std::string_view word) {
    next(fmt::format("'{}'", word));
    if (!iequals(tok, word)) {
      fail(src, fmt::format("line {}: expected '{}' in facet {}, found {}", tz.token_line(), word,
                            facet, show(tok)));
    }
  };
  auto number = [&](std::string_view what) {
    next(fmt::format("a number ({})", what));
    double value = 0;
    const std::string error = parse_double(tok, value);
    if (!error.empty()) {
      fail(src, fmt::format("line {}: {} ({} of facet {})", tz.token_line(), error, what, facet));
    }
    return value;
  };

  tz.next(tok);  // "solid"; the caller checked it
  tz.skip_line();
  std::vector<int> corners;
  for (;;) {
    if (!tz.next(tok)) {
      fail(src, fmt::format("line {}: truncated: the file ends after {} facets, before "
                            "'endsolid'",
                            tz.token_line(), facet));
    }
    if (iequals(tok, "endsolid")) {
      tz.skip_line();
      if (!tz.next(tok))
        break;
      if (iequals(tok, "solid")) {  // several solids in one file
        tz.skip_line();
        continue;
      }
      fail(src, fmt::format("line {}: unexpected {} after 'endsolid'", tz.token_line(), show(tok)));
    }
    if (!iequals(tok, "facet")) {
      fail(src, fmt::format("line {}: expected 'facet' or 'endsolid', found {}", tz.token_line(),
                            show(tok)));
    }
    expect("normal");
    for (int c = 0; c < 3; ++c)
      number("normal");
    expect("outer");
    expect("loop");
    corners.clear();
    for (;;) {
      next("'vertex' or 'endloop'");
      if (iequals(tok, "endloop"))
        break;
      if (!iequals(tok, "vertex")) {
        fail(src, fmt::format("line {}: expected 'vertex' or 'endloop' in facet {}, found {}",
                              tz.token_line(), facet, show(tok)));
      }
      Point p;
      for (int c = 0; c < 3; ++c)
        p[c] = number("vertex coordinate");
      if (!finite(p)) {
        fail(src, fmt::format("line {}: non-finite vertex coordinate ({}, {}, {}) in facet {}",
                              tz.token_line(), p[0], p[1], p[2], facet));
      }
      corners.push_back(merger.add(p));
    }
    if (corners.size() < 3) {
      fail(src, fmt::format("line {}: facet {} has {} vertices; a facet needs 3", tz.token_line(),
                            facet, corners.size()));
    }
    expect("endfacet");
    add_fan(soup, corners);
    ++facet;
  }
  return soup;
}

std::uint64_t read_unsigned(const char* p, int size, bool big_endian) {
  std::uint64_t u = 0;
  for (int i = 0; i < size; ++i) {
    const int k = big_endian ? i : size - 1 - i;
    u = (u << 8) | static_cast<unsigned char>(p[k]);
  }
  return u;
}

float read_float_le(const char* p) {
  const auto bits = static_cast<std::uint32_t>(read_unsigned(p, 4, false));
  float f = 0;
  std::memcpy(&f, &bits, 4);
  return f;
}

TriangleSoup read_stl_binary(const std::string& src, std::string_view data, std::uint32_t count) {
  TriangleSoup soup;
  VertexMerger merger(soup);
  soup.triangles.reserve(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const std::size_t base = 84 + 50 * static_cast<std::size_t>(t);
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const std::size_t offset = base + 12 + 12 * k;  // after the normal
      const Point p(read_float_le(data.data() + offset), read_float_le(data.data() + offset + 4),
                    read_float_le(data.data() + offset + 8));
      if (!finite(p)) {
        fail(src, fmt::format("byte {}: triangle {} has a non-finite vertex coordinate ({}, {}, "
                              "{})",
                              offset, t, p[0], p[1], p[2]));
      }
      tri[k] = merger.add(p);
    }
    soup.triangles.push_back(tri);
  }
  return soup;
}

bool starts_with_solid(std::string_view data) {
  std::size_t i = 0;
  while (i < data.size() && is_space(data[i]))
    ++i;
  if (data.size() - i < 5 || !iequals(data.substr(i, 5), "solid"))
    return false;
  return data.size() == i + 5 || is_space(data[i + 5]);
}

TriangleSoup read_stl(const std::string& src, std::string_view data) {
  std::uint32_t count = 0;
  std::uint64_t expected = 0;
  if (data.size() >= 84) {
    count = static_cast<std::uint32_t>(read_unsigned(data.data() + 80, 4, false));
    expected = 84 + 50 * static_cast<std::uint64_t>(count);
    // Binary files may start with "solid" too: the size decides.
    if (data.size() == expected)
      return read_stl_binary(src, data, count);
  }
  if (starts_with_solid(data) && data.find('\0') == std::string_view::npos) {
    return read_stl_ascii(src, data);
  }
  if (data.size() < 84) {
    fail(src, fmt::format("byte {}: truncated: the file ends inside the 84-byte header of a "
                          "binary STL, and it is not an ASCII STL (which starts with 'solid')",
                          data.size()));
  }
  if (data.size() < expected) {
    fail(src, fmt::format("byte {}: truncated or not an STL file: the binary STL header "
                          "declares {} triangles "
                          "({} bytes), but the file ends after {} of them",
                          data.size(), count, expected, (data.size() - 84) / 50));
  }
  fail(src, fmt::format("byte {}: the binary STL header declares {} triangles ({} bytes), but "
                        "the file has {} bytes; not an STL file",
                        expected, count, expected, data.size()));
}

// ------------------------------------------------------------------ PLY

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool ply_type(std::string_view name, PlyType& type) {
  static const std::pair<std::string_view, PlyType> kNames[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [n, t] : kNames) {
    if (n == name) {
      type = t;
      return true;
    }
  }
  return false;
}

int ply_size(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 1;
}

bool ply_integral(PlyType t) {
  return t != PlyType::Float32 && t != PlyType::Float64;
}

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
  PlyType type = PlyType::Float32;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::size_t line = 0;  ///< header line that declares it
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;
};

PlyHeader read_ply_header(const std::string& src, LineReader& lines) {
  std::string_view line;
  Tokens tok;
  lines.next(line);
  split(line, tok);
  if (tok.size() != 1 || tok[0] != "ply") {
    fail(src, "not a PLY file: it does not start with the line 'ply'");
  }
  PlyHeader header;
  bool has_format = false;
  bool ended = false;
  while (lines.next(line)) {
    split(line, tok);
    if (tok.empty())
      continue;
    const std::string_view keyword = tok[0];
    if (keyword == "end_header") {
      ended = true;
      break;
    }
    if (keyword == "comment" || keyword == "obj_info")
      continue;
    if (keyword == "format") {
      if (tok.size() < 2)
        fail(src, fmt::format("line {}: 'format' without a value", lines.line()));
      if (tok[1] == "ascii") {
        header.format = PlyFormat::Ascii;
      } else if (tok[1] == "binary_little_endian") {
        header.format = PlyFormat::BinaryLittleEndian;
      } else if (tok[1] == "binary_big_endian") {
        header.format = PlyFormat::BinaryBigEndian;
      } else {
        fail(src, fmt::format("line {}: unknown PLY format {} (expected ascii, "
                              "binary_little_endian or binary_big_endian)",
                              lines.line(), show(tok[1])));
      }
      has_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      if (tok.size() != 3 || !parse_uint64(tok[2], element.count)) {
        fail(src, fmt::format("line {}: expected 'element <name> <count>'", lines.line()));
      }
      element.name = std::string(tok[1]);
      element.line = lines.line();
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) {
        fail(src, fmt::format("line {}: 'property' before any 'element'", lines.line()));
      }
      PlyProperty property;
      std::string_view type_name;
      if (tok.size() >= 2 && tok[1] == "list") {
        if (tok.size() != 5) {
          fail(src, fmt::format("line {}: expected 'property list <count type> <index type> "
                                "<name>'",
                                lines.line()));
        }
        property.is_list = true;
        if (!ply_type(tok[2], property.count_type)) {
          fail(src, fmt::format("line {}: unknown property type {}", lines.line(), show(tok[2])));
        }
        if (!ply_integral(property.count_type)) {
          fail(src, fmt::format("line {}: the count type of a list must be an integer type, "
                                "found {}",
                                lines.line(), show(tok[2])));
        }
        type_name = tok[3];
        property.name = std::string(tok[4]);
      } else {
        if (tok.size() != 3) {
          fail(src, fmt::format("line {}: expected 'property <type> <name>'", lines.line()));
        }
        type_name = tok[1];
        property.name = std::string(tok[2]);
      }
      if (!ply_type(type_name, property.type)) {
        fail(src, fmt::format("line {}: unknown property type {}", lines.line(), show(type_name)));
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {
      fail(src, fmt::format("line {}: unexpected PLY header line starting with {}", lines.line(),
                            show(keyword)));
    }
  }
  if (!ended) {
    fail(src,
         fmt::format("line {}: truncated: the PLY header has no 'end_header' line", lines.line()));
  }
  if (!has_format)
    fail(src, "the PLY header has no 'format' line");
  header.data_offset = lines.position();
  return header;
}

/// Where the data of interest sits in a PLY header's elements.
struct PlyLayout {
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  std::array<std::size_t, 3> xyz{};      ///< property indices in the vertex element
  std::size_t indices = 0;               ///< list property index in the face element
  std::size_t region = std::size_t(-1);  ///< "region" property index, or -1
};

PlyLayout ply_layout(const std::string& src, const PlyHeader& header) {
  PlyLayout layout;
  for (const PlyElement& element : header.elements) {
    if (element.name != "vertex" && element.name != "face")
      continue;
    const PlyElement*& slot = element.name == "vertex" ? layout.vertex : layout.face;
    if (slot != nullptr) {
      fail(src, fmt::format("line {}: a second '{}' element", element.line, element.name));
    }
    slot = &element;
  }
  if (layout.vertex == nullptr)
    fail(src, "the PLY header declares no 'vertex' element");
  const char* axes[] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) {
    const auto& props = layout.vertex->properties;
    const auto it = std::find_if(props.begin(), props.end(), [&](const PlyProperty& p) {
      return !p.is_list && p.name == axes[c];
    });
    if (it == props.end()) {
      fail(src, fmt::format("line {}: the 'vertex' element has no '{}' property",
                            layout.vertex->line, axes[c]));
    }
    layout.xyz[c] = static_cast<std::size_t>(it - props.begin());
  }
  if (layout.face != nullptr) {
    const auto& props = layout.face->properties;
    const auto it = std::find_if(props.begin(), props.end(), [](const PlyProperty& p) {
      return p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
    });
    if (it == props.end()) {
      fail(src, fmt::format("line {}: the 'face' element has no 'vertex_indices' list property",
                            layout.face->line));
    }
    if (!ply_integral(it->type)) {
      fail(src, fmt::format("line {}: the vertex indices of the 'face' element must have an "
                            "integer type",
                            layout.face->line));
    }
    layout.indices = static_cast<std::size_t>(it - props.begin());
    for (std::size_t k = 0; k < props.size(); ++k) {
      if (!props[k].is_list && props[k].name == "region")
        layout.region = k;
    }
  }
  return layout;
}

/// PLY values from ASCII lines, one element per line.
class PlyAsciiSource {
 public:
  PlyAsciiSource(const std::string& src, LineReader& lines) : src_(src), lines_(lines) {}

  void begin_element(const PlyElement& element) { element_ = &element; }
  void begin_item(std::uint64_t index) {
    index_ = index;
    if (!lines_.next_tokens(tokens_, false)) {
      fail(src_, fmt::format("line {}: truncated: the file ends after {} of {} '{}' elements",
                             lines_.line(), index, element_->count, element_->name));
    }
    next_ = 0;
  }
  double value(PlyType type) {
    need(1);
    const std::string_view tok = tokens_[next_++];
    if (ply_integral(type)) {
      long long v = 0;
      if (!parse_int(tok, v)) {
        fail(src_, fmt::format("{}: cannot parse {} as an integer ('{}' element {})", where(),
                               show(tok), element_->name, index_));
      }
      return static_cast<double>(v);
    }
    double v = 0;
    const std::string error = parse_double(tok, v);
    if (!error.empty()) {
      fail(src_, fmt::format("{}: {} ('{}' element {})", where(), error, element_->name, index_));
    }
    return v;
  }
  void require(std::uint64_t n, PlyType) { need(n); }
  void need(std::uint64_t n) {
    if (n > tokens_.size() - next_) {
      fail(src_, fmt::format("{}: '{}' element {} has too few values for the properties the "
                             "header declares",
                             where(), element_->name, index_));
    }
  }
  void skip_list(std::uint64_t n, PlyType) {
    need(n);
    next_ += static_cast<std::size_t>(n);
  }
  void end_item() {
    if (next_ < tokens_.size()) {
      fail(src_, fmt::format("{}: '{}' element {} has {} values, more than the {} the header "
                             "declares",
                             where(), element_->name, index_, tokens_.size(), next_));
    }
  }
  std::string where() const { return fmt::format("line {}", lines_.line()); }

 private:
  const std::string& src_;
  LineReader& lines_;
  const PlyElement* element_ = nullptr;
  std::uint64_t index_ = 0;
  Tokens tokens_;
  std::size_t next_ = 0;
};

/// PLY values from binary data of either byte order.
class PlyBinarySource {
 public:
  PlyBinarySource(const std::string& src, std::string_view data, std::size_t offset,
                  bool big_endian)
      : src_(src), data_(data), pos_(offset), big_endian_(big_endian) {}

  void begin_element(const PlyElement& element) {
    element_ = &element;
    std::uint64_t stride = 0;
    for (const PlyProperty& p : element.properties) {
      if (p.is_list)
        return;  // variable size: checked value by value
      stride += static_cast<std::uint64_t>(ply_size(p.type));
    }
    const std::uint64_t left = data_.size() - pos_;
    if (stride > 0 && element.count > left / stride) {
      fail(src_, fmt::format("byte {}: truncated: the file ends after {} of {} '{}' elements "
                             "({} bytes each)",
                             data_.size(), left / stride, element.count, element.name, stride));
    }
  }
  void begin_item(std::uint64_t index) { index_ = index; }
  double value(PlyType type) {
    const int size = ply_size(type);
    require_bytes(static_cast<std::uint64_t>(size));
    at_ = pos_;
    const std::uint64_t u = read_unsigned(data_.data() + pos_, size, big_endian_);
    pos_ += static_cast<std::size_t>(size);
    switch (type) {
      case PlyType::Int8:
        return static_cast<std::int8_t>(static_cast<std::uint8_t>(u));
      case PlyType::UInt8:
        return static_cast<std::uint8_t>(u);
      case PlyType::Int16:
        return static_cast<std::int16_t>(static_cast<std::uint16_t>(u));
      case PlyType::UInt16:
        return static_cast<std::uint16_t>(u);
      case PlyType::Int32:
        return static_cast<std::int32_t>(static_cast<std::uint32_t>(u));
      case PlyType::UInt32:
        return static_cast<std::uint32_t>(u);
      case PlyType::Float32: {
        const auto bits = static_cast<std::uint32_t>(u);
        float f = 0;
        std::memcpy(&f, &bits, 4);
        return f;
      }
      case PlyType::Float64: {
        double d = 0;
        std::memcpy(&d, &u, 8);
        return d;
      }
    }
    return 0;
  }
  void require(std::uint64_t n, PlyType type) {
    const auto size = static_cast<std::uint64_t>(ply_size(type));
    if (n > (data_.size() - pos_) / size)
      truncated();
  }
  void skip_list(std::uint64_t n, PlyType type) {
    require(n, type);
    pos_ += static_cast<std::size_t>(n * static_cast<std::uint64_t>(ply_size(type)));
  }
  void end_item() {}
  std::string where() const { return fmt::format("byte {}", at_); }

 private:
  void require_bytes(std::uint64_t n) {
    if (n > data_.size() - pos_)
      truncated();
  }
  [[noreturn]] void truncated() const {
    fail(src_, fmt::format("byte {}: truncated: the file ends inside '{}' element {} of {}",
                           data_.size(), element_->name, index_, element_->count));
  }

  const std::string& src_;
  std::string_view data_;
  std::size_t pos_;
  std::size_t at_ = 0;  ///< offset of the last value read
  bool big_endian_;
  const PlyElement* element_ = nullptr;
  std::uint64_t index_ = 0;
};

template <class Source>
void read_ply_body(const std::string& src, Source& source, const PlyHeader& header,
                   const PlyLayout& layout, TriangleSoup& soup) {
  const long long vertex_count = static_cast<long long>(
      std::min<std::uint64_t>(layout.vertex->count, std::numeric_limits<long long>::max()));
  std::vector<int> corners;
  for (const PlyElement& element : header.elements) {
    if (element.properties.empty())
      continue;  // nothing stored per element
    source.begin_element(element);
    const bool is_vertex = &element == layout.vertex;
    const bool is_face = &element == layout.face;
    for (std::uint64_t i = 0; i < element.count; ++i) {
      source.begin_item(i);
      Point p(0, 0, 0);
      int region = kNoRegion;
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& property = element.properties[k];
        if (!property.is_list) {
          const double v = source.value(property.type);
          if (is_vertex) {
            for (int c = 0; c < 3; ++c) {
              if (layout.xyz[c] == k)
                p[c] = v;
            }
          } else if (is_face && k == layout.region) {
            if (!(v == std::floor(v) && v >= std::numeric_limits<int>::min() &&
                  v <= std::numeric_limits<int>::max())) {
              fail(src,
                   fmt::format("{}: region {} of face {} is not an int", source.where(), v, i));
            }
            region = static_cast<int>(v);
          }
          continue;
        }
        const double count = source.value(property.count_type);
        if (count < 0) {
          fail(src, fmt::format("{}: negative list length {} in '{}' element {}", source.where(),
                                count, element.name, i));
        }
        const auto n = static_cast<std::uint64_t>(count);
        if (!is_face || k != layout.indices) {
          source.skip_list(n, property.type);
          continue;
        }
        if (n < 3) {
          fail(src, fmt::format("{}: face {} has {} vertices; a face needs at least 3",
                                source.where(), i, n));
        }
        source.require(n, property.type);
        corners.clear();
        for (std::uint64_t j = 0; j < n; ++j) {
          const double v = source.value(property.type);
          if (v < 0 || v >= static_cast<double>(vertex_count)) {
            fail(src, fmt::format("{}: face {} references vertex {}, but there are {} vertices",
                                  source.where(), i, v, vertex_count));
          }
          corners.push_back(static_cast<int>(v));
        }
      }
      source.end_item();
      if (is_vertex)
        soup.points.push_back(p);
      if (is_face) {
        add_fan(soup, corners);
        if (layout.region != std::size_t(-1))
          soup.regions.resize(soup.triangles.size(), region);
      }
    }
  }
}

TriangleSoup read_ply(const std::string& src, std::string_view data) {
  LineReader lines(data);
  const PlyHeader header = read_ply_header(src, lines);
  const PlyLayout layout = ply_layout(src, header);
  TriangleSoup soup;
  if (header.format == PlyFormat::Ascii) {
    check_text(src, data, "ASCII PLY");
    PlyAsciiSource source(src, lines);
    read_ply_body(src, source, header, layout, soup);
  } else {
    PlyBinarySource source(src, data, header.data_offset,
                           header.format == PlyFormat::BinaryBigEndian);
    read_ply_body(src, source, header, layout, soup);
  }
  return soup;
}

// ------------------------------------------------------------------ reading files

void check_readable(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status))
    fail(path.string(), "the file does not exist");
  if (fs::is_directory(status))
    fail(path.string(), "is a directory, not a mesh file");
}

std::string read_file(const fs::path& path) {
  const std::string src = path.string();
  std::FILE* file = std::fopen(src.c_str(), "rb");
  if (file == nullptr)
    fail(src, fmt::format("cannot open the file: {}", std::strerror(errno)));
  std::string content;
  std::array<char, 1 << 16> chunk{};
  for (;;) {
    const std::size_t n = std::fread(chunk.data(), 1, chunk.size(), file);
    content.append(chunk.data(), n);
    if (n < chunk.size())
      break;
  }
  const bool error = std::ferror(file) != 0;
  std::fclose(file);
  if (error)
    fail(src, "cannot read the file (I/O error)");
  return content;
}

// ------------------------------------------------------------------ writing

/// A file written through a buffer; every failure throws std::runtime_error naming it.
class OutputFile {
 public:
  explicit OutputFile(const fs::path& path) : name_(path.string()) {
    file_ = std::fopen(name_.c_str(), "wb");
    if (file_ == nullptr) {
      throw std::runtime_error(
          fmt::format("{}: cannot open for writing: {}", name_, std::strerror(errno)));
    }
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile() {
    if (file_ != nullptr)
      std::fclose(file_);
  }

  template <typename... Args>
  void print(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(fmt::appender(buffer_), format, std::forward<Args>(args)...);
    if (buffer_.size() > (1 << 20))
      flush();
  }
  void bytes(const void* data, std::size_t n) {
    const char* p = static_cast<const char*>(data);
    buffer_.append(p, p + n);
    if (buffer_.size() > (1 << 20))
      flush();
  }
  void little_endian(std::uint64_t value, int size) {
    char b[8];
    for (int i = 0; i < size; ++i)
      b[i] = static_cast<char>((value >> (8 * i)) & 0xff);
    bytes(b, static_cast<std::size_t>(size));
  }
  void f32(float f) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    little_endian(bits, 4);
  }
  void f64(double d) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &d, 8);
    little_endian(bits, 8);
  }
  void close() {
    flush();
    const int rc = std::fclose(file_);
    file_ = nullptr;
    if (rc != 0)
      write_failed();
  }

 private:
  void flush() {
    if (buffer_.size() > 0 &&
        std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
      write_failed();
    }
    buffer_.clear();
  }
  [[noreturn]] void write_failed() const {
    throw std::runtime_error(fmt::format("{}: cannot write: {}", name_, std::strerror(errno)));
  }

  std::string name_;
  std::FILE* file_ = nullptr;
  fmt::memory_buffer buffer_;
};

Point unit_normal(const TriangleSoup& soup, const std::array<int, 3>& tri) {
  const Point& a = soup.points[tri[0]];
  Point n = OpenMesh::cross(soup.points[tri[1]] - a, soup.points[tri[2]] - a);
  const double length = n.norm();
  return length > 0 ? n / length : Point(0, 0, 0);
}

void write_off(const TriangleSoup& soup, OutputFile& out) {
  out.print("OFF\n{} {} 0\n", soup.points.size(), soup.triangles.size());
  for (const Point& p : soup.points)
    out.print("{:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
  for (const auto& t : soup.triangles)
    out.print("3 {} {} {}\n", t[0], t[1], t[2]);
}

void write_obj(const TriangleSoup& soup, OutputFile& out) {
  out.print("# written by holebench\n");
  for (const Point& p : soup.points)
    out.print("v {:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
  for (const auto& t : soup.triangles)
    out.print("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
}

void write_stl_ascii(const TriangleSoup& soup, OutputFile& out) {
  out.print("solid holebench\n");
  for (const auto& t : soup.triangles) {
    const Point n = unit_normal(soup, t);
    out.print("  facet normal {:.9g} {:.9g} {:.9g}\n    outer loop\n", n[0], n[1], n[2]);
    for (int k = 0; k < 3; ++k) {
      const Point& p = soup.points[t[k]];
      out.print("      vertex {:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
    }
    out.print("    endloop\n  endfacet\n");
  }
  out.print("endsolid holebench\n");
}

void write_stl_binary(const std::filesystem::path& path, const TriangleSoup& soup,
                      OutputFile& out) {
  if (soup.triangles.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::runtime_error(fmt::format("{}: {} triangles do not fit in a binary STL",
                                         path.string(), soup.triangles.size()));
  }
  std::array<char, 80> header{};  // must not start with "solid"
  const std::string_view title = "binary STL written by holebench";
  std::copy(title.begin(), title.end(), header.begin());
  out.bytes(header.data(), header.size());
  out.little_endian(soup.triangles.size(), 4);
  for (const auto& t : soup.triangles) {
    const Point n = unit_normal(soup, t);
    for (int c = 0; c < 3; ++c)
      out.f32(static_cast<float>(n[c]));
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c)
        out.f32(static_cast<float>(soup.points[t[k]][c]));
    }
    out.little_endian(0, 2);  // attribute byte count
  }
}

void write_ply(const TriangleSoup& soup, OutputFile& out, bool binary, bool regions) {
  out.print("ply\nformat {} 1.0\ncomment written by holebench\n",
            binary ? "binary_little_endian" : "ascii");
  out.print("element vertex {}\nproperty double x\nproperty double y\nproperty double z\n",
            soup.points.size());
  out.print("element face {}\nproperty list uchar int vertex_indices\n", soup.triangles.size());
  if (regions)
    out.print("property int region\n");
  out.print("end_header\n");
  const auto region_of = [&](std::size_t j) {
    return soup.regions.empty() ? kNoRegion : soup.regions[j];
  };
  for (const Point& p : soup.points) {
    if (binary) {
      for (int c = 0; c < 3; ++c)
        out.f64(p[c]);
    } else {
      out.print("{:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
    }
  }
  for (std::size_t j = 0; j < soup.triangles.size(); ++j) {
    const auto& t = soup.triangles[j];
    if (binary) {
      out.little_endian(3, 1);
      for (int k = 0; k < 3; ++k)
        out.little_endian(static_cast<std::uint32_t>(t[k]), 4);
      if (regions)
        out.little_endian(static_cast<std::uint32_t>(region_of(j)), 4);
    } else if (regions) {
      out.print("3 {} {} {} {}\n", t[0], t[1], t[2], region_of(j));
    } else {
      out.print("3 {} {} {}\n", t[0], t[1], t[2]);
    }
  }
}

}  // namespace

MeshFormat format_from_extension(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (iequals(extension, ".off"))
    return MeshFormat::Off;
  if (iequals(extension, ".obj"))
    return MeshFormat::Obj;
  if (iequals(extension, ".stl"))
    return MeshFormat::StlBinary;
  if (iequals(extension, ".ply"))
    return MeshFormat::PlyBinary;
  fail(path.string(),
       fmt::format("unknown mesh file extension {} (expected .off, .obj, .stl or .ply)",
                   extension.empty() ? std::string("(none)") : show(extension)));
}

TriangleSoup read_soup(const std::filesystem::path& path) {
  const std::string src = path.string();
  check_readable(path);
  const MeshFormat format = format_from_extension(path);
  const std::string content = read_file(path);
  if (content.empty())
    fail(src, "the file is empty");
  switch (format) {
    case MeshFormat::Off:
      return read_off(src, content);
    case MeshFormat::Obj:
      return read_obj(src, content);
    case MeshFormat::StlAscii:
    case MeshFormat::StlBinary:
      return read_stl(src, content);
    case MeshFormat::PlyAscii:
    case MeshFormat::PlyBinary:
      return read_ply(src, content);
  }
  fail(src, "unknown mesh format");
}

Mesh read_mesh(const std::filesystem::path& path) {
  return build_mesh(read_soup(path), BuildOptions{path.string()});
}

void write_mesh(const Mesh& mesh, const std::filesystem::path& path, const WriteOptions& options) {
  MeshFormat format = format_from_extension(path);
  if (!options.binary && format == MeshFormat::StlBinary)
    format = MeshFormat::StlAscii;
  if (!options.binary && format == MeshFormat::PlyBinary)
    format = MeshFormat::PlyAscii;
  const TriangleSoup soup = to_soup(mesh);
  OutputFile out(path);
  switch (format) {
    case MeshFormat::Off:
      write_off(soup, out);
      break;
    case MeshFormat::Obj:
      write_obj(soup, out);
      break;
    case MeshFormat::StlAscii:
      write_stl_ascii(soup, out);
      break;
    case MeshFormat::StlBinary:
      write_stl_binary(path, soup, out);
      break;
    case MeshFormat::PlyAscii:
      write_ply(soup, out, false, options.write_regions);
      break;
    case MeshFormat::PlyBinary:
      write_ply(soup, out, true, options.write_regions);
      break;
  }
  out.close();
}

}  // namespace holebench
