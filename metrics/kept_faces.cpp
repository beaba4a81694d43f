#include "metrics/kept_faces.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <numeric>
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
  return triangle_vertex_indices(mesh, f);
}

// Whether `repaired` holds every face of `input` at its index with the same vertex indices
// in the same order, read from the connectivity arrays in index order: each input face's
// halfedge, and each input halfedge inside a face with its face, next halfedge and target
// vertex, are the repair's. Then walking a face's halfedges from its halfedge visits the same
// vertices in both meshes. A repair made by adding faces to a copy of the input passes
// (adding a face changes only boundary halfedges, which lie in no face); false says only that
// this check does not show it (a repair may keep the faces with other halfedges).
bool input_faces_in_place(const Mesh& input, const Mesh& repaired) {
  if (repaired.n_faces() < input.n_faces() || repaired.n_halfedges() < input.n_halfedges())
    return false;
  for (std::size_t f = 0; f < input.n_faces(); ++f) {
    const FaceHandle face(static_cast<int>(f));
    if (input.status(face).deleted() || repaired.status(face).deleted() ||
        input.halfedge_handle(face) != repaired.halfedge_handle(face))
      return false;
  }
  for (std::size_t h = 0; h < input.n_halfedges(); ++h) {
    const HalfedgeHandle half(static_cast<int>(h));
    const FaceHandle face = input.face_handle(half);
    if (!face.is_valid())
      continue;
    if (repaired.face_handle(half) != face ||
        repaired.next_halfedge_handle(half) != input.next_halfedge_handle(half) ||
        repaired.to_vertex_handle(half) != input.to_vertex_handle(half))
      return false;
  }
  return true;
}

}  // namespace

KeptFaces kept_faces(const Mesh& input, const Mesh& repaired) {
  KeptFaces kept;
  // Vertices of the repaired mesh at the input's index and, bit for bit, its point.
  const std::size_t common = std::min(input.n_vertices(), repaired.n_vertices());
  const auto same_vertex_at = [&](std::size_t i) {
    const VertexHandle v(static_cast<int>(i));
    return !repaired.status(v).deleted() && repaired.point(v) == input.point(v);
  };
  bool all_same = common == input.n_vertices();
  for (std::size_t i = 0; i < common && all_same; ++i)
    all_same = same_vertex_at(i);
  kept.input_vertices_kept = all_same;
  // A repair that adds faces to a copy of the input keeps each input face at its index with
  // the same halfedges: shown in one pass over the arrays, without walking any face.
  if (kept.input_vertices_kept && input_faces_in_place(input, repaired)) {
    kept.repaired_face_of_input.resize(input.n_faces());
    std::iota(kept.repaired_face_of_input.begin(), kept.repaired_face_of_input.end(), 0);
    kept.input_face_of_repaired.assign(repaired.n_faces(), -1);
    std::iota(kept.input_face_of_repaired.begin(),
              kept.input_face_of_repaired.begin() + static_cast<std::ptrdiff_t>(input.n_faces()),
              0);
    kept.input_faces_in_place = true;
    for (std::size_t f = input.n_faces(); f < repaired.n_faces(); ++f)
      kept.repaired_faces_not_kept.push_back(static_cast<int>(f));
    return kept;
  }
  kept.repaired_face_of_input.assign(input.n_faces(), -1);
  kept.input_face_of_repaired.assign(repaired.n_faces(), -1);
  std::vector<char> same_vertex(common, 0);
  for (std::size_t i = 0; i < common; ++i)
    same_vertex[i] = same_vertex_at(i);
  const auto on_same_vertices = [&](const IndexTriple& t) {
    return std::all_of(t.begin(), t.end(), [&](int i) {
      return i >= 0 && static_cast<std::size_t>(i) < common && same_vertex[i];
    });
  };
  // Most repairs keep the input's faces at their indices: each repaired face is looked up
  // at its own index first. Only where input faces are left unmatched is a table of those
  // built for the rest (a mesh has one face per oriented corner, so a triple names at most one
  // face of each mesh: the order of the lookups changes no match). A repair that keeps every
  // input face at its index costs one pass, whatever its new faces.
  std::vector<int> unmatched_lookups;  // repaired faces not kept at their own index
  std::size_t matched = 0;
  for (auto f : repaired.faces()) {
    const int index = f.idx();
    if (static_cast<std::size_t>(index) < input.n_faces()) {
      const FaceHandle g = input.face_handle(index);
      const IndexTriple t = index_triple(repaired, f);
      if (!input.status(g).deleted() && index_triple(input, g) == t && on_same_vertices(t)) {
        kept.repaired_face_of_input[index] = index;
        kept.input_face_of_repaired[index] = index;
        ++matched;
        continue;
      }
    }
    unmatched_lookups.push_back(index);
  }
  kept.input_faces_in_place = matched == input.n_faces();
  if (matched < input.n_faces() && !unmatched_lookups.empty()) {
    std::unordered_map<IndexTriple, int, IndexTripleHash> input_face_of;
    for (auto f : input.faces()) {
      if (kept.repaired_face_of_input[f.idx()] >= 0)
        continue;
      const IndexTriple triple = index_triple(input, f);
      if (on_same_vertices(triple))
        input_face_of.emplace(triple, f.idx());
    }
    for (int index : unmatched_lookups) {
      const auto it = input_face_of.find(index_triple(repaired, repaired.face_handle(index)));
      if (it == input_face_of.end() || kept.repaired_face_of_input[it->second] >= 0)
        continue;
      kept.repaired_face_of_input[it->second] = index;
      kept.input_face_of_repaired[index] = it->second;
    }
  }
  int last_input_face = -1;
  for (std::size_t f = 0; f < kept.input_face_of_repaired.size(); ++f) {
    const int g = kept.input_face_of_repaired[f];
    if (g < 0) {
      kept.repaired_faces_not_kept.push_back(static_cast<int>(f));
      continue;
    }
    kept.order_kept = kept.order_kept && g > last_input_face;
    last_input_face = g;
  }
  for (std::size_t f = 0; f < kept.repaired_face_of_input.size(); ++f) {
    if (kept.repaired_face_of_input[f] < 0)
      kept.input_faces_not_kept.push_back(static_cast<int>(f));
  }
  return kept;
}

namespace {

// The points of `faces` of `mesh` (deleted ones left out) into `box`.
void add_faces_to_box(const Mesh& mesh, const std::vector<int>& faces, GrowingBox& box) {
  for (int f : faces) {
    const FaceHandle face(f);
    if (mesh.status(face).deleted())
      continue;
    for (auto v : mesh.fv_range(face))
      box.add(mesh.point(v));
  }
}

}  // namespace

GrowingBox changed_faces_box(const Mesh& input, const Mesh& repaired, const KeptFaces& kept) {
  GrowingBox box;
  add_faces_to_box(repaired, kept.repaired_faces_not_kept, box);
  add_faces_to_box(input, kept.input_faces_not_kept, box);
  return box;
}

}  // namespace holebench
