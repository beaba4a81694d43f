// The one mesh type of holebench: an OpenMesh triangle mesh with double
// precision points and per-element holebench data.
//
// Per-element data lives in OpenMesh traits attributes rather than in named
// properties looked up by string: every element that any algorithm adds (an
// OpenMesh add_face, a CGAL Euler operation through CGAL's OpenMesh graph
// traits) is default-constructed, so it is automatically `Provenance::New`
// with no region; the data is copied with the mesh and read in O(1).
#pragma once

#include <array>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cstdint>

namespace holebench {

/// Where an element comes from: read from the input, or added by an algorithm.
enum class Provenance : std::uint8_t {
  New = 0,       ///< created after loading (a hole filler's patch); the default
  Original = 1,  ///< present in the mesh as it was read or generated
};

/// Region id of a face that belongs to no region (for example a new face).
inline constexpr int kNoRegion = -1;

struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;

  VertexAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::PrevHalfedge);

  VertexTraits {
   public:
    Provenance provenance = Provenance::New;
  };

  FaceTraits {
   public:
    int region = kNoRegion;  ///< CAD face (B-Rep face) this triangle belongs to
    Provenance provenance = Provenance::New;
  };
};

using Mesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;
using Point = Mesh::Point;
using VertexHandle = OpenMesh::VertexHandle;
using FaceHandle = OpenMesh::FaceHandle;
using HalfedgeHandle = OpenMesh::HalfedgeHandle;
using EdgeHandle = OpenMesh::SmartEdgeHandle;

inline int region(const Mesh& mesh, FaceHandle f) {
  return mesh.data(f).region;
}
inline void set_region(Mesh& mesh, FaceHandle f, int id) {
  mesh.data(f).region = id;
}
inline Provenance provenance(const Mesh& mesh, FaceHandle f) {
  return mesh.data(f).provenance;
}
inline Provenance provenance(const Mesh& mesh, VertexHandle v) {
  return mesh.data(v).provenance;
}
inline bool is_new(const Mesh& mesh, FaceHandle f) {
  return provenance(mesh, f) == Provenance::New;
}
inline bool is_new(const Mesh& mesh, VertexHandle v) {
  return provenance(mesh, v) == Provenance::New;
}

/// The vertex indices of a triangle in the face-vertex circulator's order (from the to-vertex
/// of the face's halfedge), read straight off the halfedges: faster than the circulator.
inline std::array<int, 3> triangle_vertex_indices(const Mesh& mesh, FaceHandle f) {
  HalfedgeHandle h = mesh.halfedge_handle(f);
  std::array<int, 3> ids{};
  for (int k = 0; k < 3; ++k, h = mesh.next_halfedge_handle(h))
    ids[k] = mesh.to_vertex_handle(h).idx();
  return ids;
}

/// Marks every vertex and face of `mesh` as original (done after reading or generating).
void mark_all_original(Mesh& mesh);

/// Number of faces whose provenance is `Provenance::New`.
std::size_t count_new_faces(const Mesh& mesh);

/// Number of regions: one more than the largest region id (0 if there is none).
int region_count(const Mesh& mesh);

}  // namespace holebench
