#include "methods/brep_guidance/guidance_arrow.h"

namespace holebench::brep_guidance {
namespace {

// Ps for k = 1, the mean of the transition vertices otherwise.
Point anchor(const Hole& hole) {
  if (hole.transitions.empty())
    return hole.centroid;
  Point sum(0, 0, 0);
  for (const auto& t : hole.transitions)
    sum += t.position;
  return sum / static_cast<double>(hole.transitions.size());
}

Point sum_of_normals(const BrepFaces& faces, const Hole& hole) {
  Point sum(0, 0, 0);
  for (int region : hole.faces)
    sum += faces.planes[region].plane.normal;
  return sum;
}

}  // namespace

GuidanceArrow inner_hole_arrow(const BrepFaces& faces, const Hole& hole, double d) {
  const Point sum = sum_of_normals(faces, hole);
  GuidanceArrow arrow;
  arrow.direction = -sum / sum.norm();
  arrow.position = anchor(hole) - arrow.direction * d;
  return arrow;
}

GuidanceArrow outer_hole_arrow(const BrepFaces& faces, const Hole& hole,
                               const std::vector<BoundaryKind>& boundary_kinds, double d) {
  Point weighted(0, 0, 0);
  for (int i = 0; i < hole.k(); ++i) {
    const double a = boundary_kinds[i] == BoundaryKind::Inner ? 1.0 : -1.0;
    weighted += faces.planes[hole.faces[i]].plane.normal * a;
  }
  GuidanceArrow arrow;
  arrow.direction = weighted / weighted.norm();
  arrow.position = anchor(hole) - arrow.direction * d;
  return arrow;
}

GuidanceArrow fan_arrow(const Mesh& mesh, const Hole& hole, double d) {
  // Without transition vertices (k = 1) the hole's own vertices span the fan.
  std::vector<Point> T;
  if (hole.transitions.size() >= 3) {
    for (const auto& t : hole.transitions)
      T.push_back(t.position);
  } else {
    for (auto h : hole.halfedges)
      T.push_back(mesh.point(mesh.from_vertex_handle(h)));
  }
  Point M(0, 0, 0);
  for (const Point& t : T)
    M += t;
  M /= static_cast<double>(T.size());
  Point sum(0, 0, 0);
  for (std::size_t i = 0; i < T.size(); ++i) {
    const Point v = T[(i + 1) % T.size()] - T[i];
    sum += OpenMesh::cross(M - T[i], v);  // Delta_i, weighted by the triangle's area
  }
  GuidanceArrow arrow;
  arrow.direction = -sum / sum.norm();
  arrow.position = M - arrow.direction * d;
  return arrow;
}

GuidanceArrow guidance_arrow(const Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                             const Classification& classification, double d) {
  const bool defined = sum_of_normals(faces, hole).norm() > 1e-9;
  if (hole.k() > 3 || !classification.orientation_known || !defined)
    return fan_arrow(mesh, hole, d);
  if (classification.orientation == Orientation::Inner)
    return inner_hole_arrow(faces, hole, d);
  Point weighted(0, 0, 0);
  for (int i = 0; i < hole.k(); ++i) {
    weighted += faces.planes[hole.faces[i]].plane.normal *
                (classification.boundary_kinds[i] == BoundaryKind::Inner ? 1.0 : -1.0);
  }
  if (weighted.norm() < 1e-9)
    return fan_arrow(mesh, hole, d);
  return outer_hole_arrow(faces, hole, classification.boundary_kinds, d);
}

}  // namespace holebench::brep_guidance
