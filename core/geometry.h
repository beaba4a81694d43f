// Small geometry helpers over the core mesh.
#pragma once

#include "core/mesh.h"

#include <array>
#include <vector>

namespace holebench {

struct BoundingBox {
  Point min{0.0, 0.0, 0.0};
  Point max{0.0, 0.0, 0.0};

  double diagonal() const { return (max - min).norm(); }
  Point center() const { return (min + max) * 0.5; }
};

/// The axis-aligned bounding box of the mesh's vertices (zero box for an empty mesh).
BoundingBox bounding_box(const Mesh& mesh);

/// The length of the bounding-box diagonal: the unit of every reported distance.
inline double bounding_box_diagonal(const Mesh& mesh) {
  return bounding_box(mesh).diagonal();
}

/// Unit normal of a face computed from its points (not from a cached normal).
Point face_normal(const Mesh& mesh, FaceHandle f);

/// Area of a face.
double face_area(const Mesh& mesh, FaceHandle f);
/// face_area() of every face, by face index (zero for a deleted face).
std::vector<double> face_areas(const Mesh& mesh);

/// Centroid of a face.
Point face_centroid(const Mesh& mesh, FaceHandle f);

/// The three points of a face, in its vertex order.
std::array<Point, 3> face_corners(const Mesh& mesh, FaceHandle f);

/// Signed dihedral angle in radians across a non-boundary edge: 0 for coplanar faces,
/// positive where the edge is convex, negative where it is reflex (concave), for a
/// consistently oriented mesh with outward normals. 0 on a boundary edge.
double signed_dihedral_angle(const Mesh& mesh, EdgeHandle e);

}  // namespace holebench
