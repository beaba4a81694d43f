// Repairs made in code for the evaluation's tests: what a method returns, without a method.
#pragma once

#include "core/boundary_loops.h"
#include "core/case.h"
#include "core/mesh.h"

#include <array>
#include <map>
#include <vector>

namespace holebench::test {

/// The input with every hole closed by a fan from its loop's first vertex (new faces added to
/// a copy of the input, after its faces).
inline Mesh fan_closing(const Mesh& input) {
  Mesh repaired = input;
  for (const auto& loop : find_boundary_loops(input)) {
    const auto v = loop_vertices(input, loop);
    for (std::size_t i = 1; i + 1 < v.size(); ++i)
      repaired.add_face(v[0], v[i], v[i + 1]);
  }
  return repaired;
}

/// The input with the complete model's removed faces appended as new faces (a vertex at a
/// point the input does not have is new): an exact closing that appends to the input, whose
/// new faces lie on the complete model.
inline Mesh exact_appended_closing(const Case& c) {
  Mesh repaired = c.input;
  std::map<std::array<double, 3>, VertexHandle> vertex_at;
  for (auto v : repaired.vertices()) {
    const Point& p = repaired.point(v);
    vertex_at.emplace(std::array<double, 3>{p[0], p[1], p[2]}, v);
  }
  for (const auto& hole : c.holes) {
    for (int f : hole.removed_faces) {
      std::vector<VertexHandle> corners;
      for (auto v : c.complete.fv_range(FaceHandle(f))) {
        const Point& p = c.complete.point(v);
        auto [it, added] =
            vertex_at.emplace(std::array<double, 3>{p[0], p[1], p[2]}, VertexHandle());
        if (added)
          it->second = repaired.add_vertex(p);
        corners.push_back(it->second);
      }
      const FaceHandle face = repaired.add_face(corners);
      if (face.is_valid())
        repaired.data(face).provenance = Provenance::New;
    }
  }
  return repaired;
}

}  // namespace holebench::test
