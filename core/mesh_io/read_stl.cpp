// The STL reader (core/mesh_io.h), ASCII and binary; equal corners merged into one vertex.
#include "core/mesh_io/parsing.h"
#include "core/mesh_io/readers.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstring>
#include <map>

namespace holebench::mesh_io {

namespace {

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

}  // namespace

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

}  // namespace holebench::mesh_io
