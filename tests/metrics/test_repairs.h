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

/// The input without one face at its first hole's boundary, every other face and vertex at
/// the input's index or (the faces after the dropped one) one index lower, in the input's
/// order, then every hole closed by a fan: a repair that keeps the input's faces in order but
/// not in place.
inline Mesh drop_in_order_and_fan(const Mesh& input) {
  const auto loop = find_boundary_loops(input).front();
  const int dropped =
      input.face_handle(input.opposite_halfedge_handle(loop.halfedges.front())).idx();
  Mesh kept;
  for (auto v : input.vertices())
    kept.data(kept.add_vertex(input.point(v))).provenance = input.data(v).provenance;
  for (auto f : input.faces()) {
    if (f.idx() == dropped)
      continue;
    std::vector<VertexHandle> corners;
    for (auto v : input.fv_range(f))
      corners.push_back(VertexHandle(v.idx()));
    const FaceHandle face = kept.add_face(corners);
    if (face.is_valid()) {
      kept.data(face).provenance = input.data(f).provenance;
      kept.data(face).region = input.data(f).region;
    }
  }
  return fan_closing(kept);
}

}  // namespace holebench::test
