#include "metrics/face_subset.h"

#include <algorithm>
#include <unordered_map>

namespace holebench {

std::vector<int> removed_faces(const Case& c) {
  std::vector<int> removed;
  for (const auto& hole : c.holes)
    removed.insert(removed.end(), hole.removed_faces.begin(), hole.removed_faces.end());
  std::sort(removed.begin(), removed.end());
  removed.erase(std::unique(removed.begin(), removed.end()), removed.end());
  return removed;
}

Mesh face_subset(const Mesh& mesh, const std::vector<int>& faces) {
  Mesh out;
  std::unordered_map<int, VertexHandle> copy_of;
  auto copy_vertex = [&](VertexHandle v) {
    auto [it, inserted] = copy_of.try_emplace(v.idx());
    if (inserted) {
      it->second = out.add_vertex(mesh.point(v));
      out.data(it->second).provenance = provenance(mesh, v);
    }
    return it->second;
  };
  for (int index : faces) {
    const FaceHandle f = mesh.face_handle(index);
    std::vector<VertexHandle> corners;
    std::vector<VertexHandle> originals;
    for (auto v : mesh.fv_range(f)) {
      originals.push_back(v);
      corners.push_back(copy_vertex(v));
    }
    FaceHandle added = out.add_face(corners);
    if (!added.is_valid()) {
      // Non-manifold in isolation: give the triangle vertices of its own.
      std::vector<VertexHandle> own;
      for (auto v : originals) {
        own.push_back(out.add_vertex(mesh.point(v)));
        out.data(own.back()).provenance = provenance(mesh, v);
      }
      added = out.add_face(own);
    }
    out.data(added).region = region(mesh, f);
    out.data(added).provenance = provenance(mesh, f);
  }
  return out;
}

std::vector<int> new_face_indices(const Mesh& mesh) {
  std::vector<int> faces;
  const std::size_t count = mesh.n_faces();
  for (std::size_t i = 0; i < count; ++i) {
    const FaceHandle f(static_cast<int>(i));
    if (is_new(mesh, f) && !mesh.status(f).deleted())
      faces.push_back(f.idx());
  }
  return faces;
}

const std::vector<int>& new_face_indices(const Mesh& mesh, const std::vector<int>* known,
                                         std::vector<int>& found) {
  if (known)
    return *known;
  found = new_face_indices(mesh);
  return found;
}

std::vector<int> new_vertex_indices(const Mesh& mesh) {
  std::vector<int> vertices;
  const std::size_t count = mesh.n_vertices();
  for (std::size_t i = 0; i < count; ++i) {
    const VertexHandle v(static_cast<int>(i));
    if (is_new(mesh, v) && !mesh.status(v).deleted())
      vertices.push_back(v.idx());
  }
  return vertices;
}

}  // namespace holebench
