// The OFF reader (core/mesh_io.h): vertices and polygons, errors naming the line.
#include "core/mesh_io/parsing.h"
#include "core/mesh_io/readers.h"

#include <fmt/format.h>

namespace holebench::mesh_io {

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

}  // namespace holebench::mesh_io
