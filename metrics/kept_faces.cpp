#include "metrics/kept_faces.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <unordered_map>

namespace holebench {
namespace {

using IndexTriple = std::array<int, 3>;

struct IndexTripleHash {
  std::size_t operator()(const IndexTriple& t) const {
    std::size_t h = 0;
    for (int i : t)
      h = h * 1000003u ^ std::hash<int>()(i);
    return h;
  }
};

IndexTriple index_triple(const Mesh& mesh, FaceHandle f) {
  IndexTriple t{-1, -1, -1};
  int k = 0;
  for (auto v : mesh.fv_range(f)) {
    if (k < 3)
      t[k] = v.idx();
    ++k;
  }
  return t;
}

}  // namespace

KeptFaces kept_faces(const Mesh& input, const Mesh& repaired) {
  KeptFaces kept;
  kept.repaired_face_of_input.assign(input.n_faces(), -1);
  kept.input_face_of_repaired.assign(repaired.n_faces(), -1);
  // Vertices of the repaired mesh at the input's index and, bit for bit, its point.
  const std::size_t common = std::min(input.n_vertices(), repaired.n_vertices());
  std::vector<char> same_vertex(common, 0);
  for (std::size_t i = 0; i < common; ++i) {
    const VertexHandle v(static_cast<int>(i));
    same_vertex[i] = !repaired.status(v).deleted() && repaired.point(v) == input.point(v);
  }
  const auto on_same_vertices = [&](const IndexTriple& t) {
    return std::all_of(t.begin(), t.end(), [&](int i) {
      return i >= 0 && static_cast<std::size_t>(i) < common && same_vertex[i];
    });
  };
  // Most repairs keep the input's faces at their indices: a repaired face is looked up at its
  // own index first, and in a table of the input's faces only when it is not there. The two
  // agree: the input has one face per triple (a mesh has one face per oriented corner), so
  // the table would name the same face.
  std::unordered_map<IndexTriple, int, IndexTripleHash> input_face_of;
  bool table_built = false;
  const auto input_face_with = [&](const IndexTriple& t, int index) {
    if (static_cast<std::size_t>(index) < input.n_faces() &&
        !input.status(input.face_handle(index)).deleted() &&
        index_triple(input, input.face_handle(index)) == t && on_same_vertices(t))
      return index;
    if (!table_built) {
      input_face_of.reserve(input.n_faces());
      for (auto f : input.faces()) {
        const IndexTriple triple = index_triple(input, f);
        if (on_same_vertices(triple))
          input_face_of.emplace(triple, f.idx());
      }
      table_built = true;
    }
    const auto it = input_face_of.find(t);
    return it == input_face_of.end() ? -1 : it->second;
  };
  int last_input_face = -1;
  for (auto f : repaired.faces()) {
    const int g = input_face_with(index_triple(repaired, f), f.idx());
    if (g < 0 || kept.repaired_face_of_input[g] >= 0)
      continue;
    kept.repaired_face_of_input[g] = f.idx();
    kept.input_face_of_repaired[f.idx()] = g;
    kept.order_kept = kept.order_kept && g > last_input_face;
    last_input_face = g;
  }
  return kept;
}

GrowingBox changed_faces_box(const Mesh& input, const Mesh& repaired, const KeptFaces& kept) {
  GrowingBox box;
  for (auto f : repaired.faces()) {
    if (kept.input_face_of_repaired[f.idx()] < 0) {
      for (auto v : repaired.fv_range(f))
        box.add(repaired.point(v));
    }
  }
  for (auto f : input.faces()) {
    if (kept.repaired_face_of_input[f.idx()] < 0) {
      for (auto v : input.fv_range(f))
        box.add(input.point(v));
    }
  }
  return box;
}

}  // namespace holebench
