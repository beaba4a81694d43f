#include "core/geometry.h"

#include "core/portable_math.h"

#include <algorithm>
#include <cmath>

namespace holebench {

BoundingBox bounding_box(const Mesh& mesh) {
  BoundingBox box;
  bool first = true;
  for (auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    if (first) {
      box.min = box.max = p;
      first = false;
      continue;
    }
    box.min.minimize(p);
    box.max.maximize(p);
  }
  return box;
}

Point face_normal(const Mesh& mesh, FaceHandle f) {
  auto h = mesh.halfedge_handle(f);
  const Point& a = mesh.point(mesh.from_vertex_handle(h));
  const Point& b = mesh.point(mesh.to_vertex_handle(h));
  const Point& c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
  Point n = OpenMesh::cross(b - a, c - a);
  const double length = n.norm();
  return length > 0.0 ? n / length : n;
}

double face_area(const Mesh& mesh, FaceHandle f) {
  auto h = mesh.halfedge_handle(f);
  const Point& a = mesh.point(mesh.from_vertex_handle(h));
  const Point& b = mesh.point(mesh.to_vertex_handle(h));
  const Point& c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
  return 0.5 * OpenMesh::cross(b - a, c - a).norm();
}

std::vector<double> face_areas(const Mesh& mesh) {
  std::vector<double> areas(mesh.n_faces(), 0.0);
  for (auto f : mesh.faces())
    areas[f.idx()] = face_area(mesh, f);
  return areas;
}

Point face_centroid(const Mesh& mesh, FaceHandle f) {
  Point sum(0.0, 0.0, 0.0);
  for (auto v : mesh.fv_range(f))
    sum += mesh.point(v);
  return sum / 3.0;
}

std::array<Point, 3> face_corners(const Mesh& mesh, FaceHandle f) {
  std::array<Point, 3> corners;
  int k = 0;
  for (auto v : mesh.fv_range(f))
    corners[k++] = mesh.point(v);
  return corners;
}

double signed_dihedral_angle(const Mesh& mesh, EdgeHandle e) {
  if (mesh.is_boundary(e))
    return 0.0;
  const auto h0 = mesh.halfedge_handle(e, 0);
  const auto h1 = mesh.halfedge_handle(e, 1);
  const Point n0 = face_normal(mesh, mesh.face_handle(h0));
  const Point n1 = face_normal(mesh, mesh.face_handle(h1));
  const Point axis =
      mesh.point(mesh.to_vertex_handle(h0)) - mesh.point(mesh.from_vertex_handle(h0));
  const double axis_length = axis.norm();
  if (axis_length == 0.0)
    return 0.0;
  // The angle between the normals, signed by whether the faces fold away from each
  // other (convex) or towards each other (reflex) about the edge h0 runs along.
  const double sine = OpenMesh::dot(OpenMesh::cross(n0, n1), axis) / axis_length;
  const double cosine = std::clamp(OpenMesh::dot(n0, n1), -1.0, 1.0);
  return portable_atan2(sine, cosine);
}

}  // namespace holebench
