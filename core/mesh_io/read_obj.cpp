// The OBJ reader (core/mesh_io.h): v and f lines, errors naming the line.
#include "core/mesh_io/parsing.h"
#include "core/mesh_io/readers.h"

#include <fmt/format.h>

namespace holebench::mesh_io {

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

}  // namespace holebench::mesh_io
