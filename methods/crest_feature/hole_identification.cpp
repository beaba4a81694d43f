#include "methods/crest_feature/hole_identification.h"

#include "core/geometry.h"
#include "core/polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace holebench::crest_feature {

Point loop_face_normal_sum(const Mesh& mesh, const BoundaryLoop& loop) {
  Point n(0, 0, 0);
  for (auto h : loop.halfedges)
    n += face_normal(mesh, mesh.opposite_face_handle(h));
  return n;
}

bool is_island_of(const Mesh& mesh, const BoundaryLoop& inner, const BoundaryLoop& outer) {
  const Point n = loop_face_normal_sum(mesh, outer);
  if (!(n.norm() > 0.0) || inner.size() < 3 || outer.size() < 3)
    return false;
  if (OpenMesh::dot(loop_face_normal_sum(mesh, inner), n) <= 0.0)
    return false;
  const std::vector<Point> outer_points = loop_points(mesh, outer);
  const std::vector<Point> inner_points = loop_points(mesh, inner);
  const double outer_turn = OpenMesh::dot(newell_normal(outer_points), n);
  const double inner_turn = OpenMesh::dot(newell_normal(inner_points), n);
  // A hole's loop runs counter-clockwise about the normals of the faces around it, an
  // island's (and an open sheet's border) clockwise.
  if (!(outer_turn > 0.0 && inner_turn < 0.0))
    return false;
  const Point centroid = loop_centroid(mesh, outer);
  double diameter = 0.0;
  for (const Point& p : outer_points)
    diameter = std::max(diameter, 2.0 * (p - centroid).norm());
  const Point unit = n / n.norm();
  for (const Point& p : inner_points) {
    if (std::abs(OpenMesh::dot(p - centroid, unit)) > diameter ||
        !inside_projected_polygon(outer_points, n, p))
      return false;
  }
  return true;
}

std::vector<Hole> identify_holes(const Mesh& mesh, const HoleIdentificationOptions& options) {
  std::vector<BoundaryLoop> loops = find_boundary_loops(mesh);
  // owner[i]: the loop whose island loop i is, or -1 for a hole.
  std::vector<int> owner(loops.size(), -1);
  if (options.attach_islands) {
    std::vector<double> area(loops.size());
    for (std::size_t i = 0; i < loops.size(); ++i)
      area[i] = newell_normal(loop_points(mesh, loops[i])).norm();
    for (std::size_t i = 0; i < loops.size(); ++i) {
      double smallest = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < loops.size(); ++j) {
        if (j != i && area[j] < smallest && is_island_of(mesh, loops[i], loops[j])) {
          smallest = area[j];
          owner[i] = static_cast<int>(j);
        }
      }
    }
    // A loop that is itself an island cannot own one: such a pair stays two holes.
    for (std::size_t i = 0; i < loops.size(); ++i) {
      if (owner[i] >= 0 && owner[owner[i]] >= 0)
        owner[i] = -1;
    }
  }
  std::vector<Hole> holes;
  std::vector<int> hole_of(loops.size(), -1);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (owner[i] >= 0)
      continue;
    Hole hole;
    hole.vertices = loop_vertices(mesh, loops[i]);
    hole.centroid = loop_centroid(mesh, loops[i]);
    hole.average_edge_length = loop_length(mesh, loops[i]) / static_cast<double>(loops[i].size());
    for (auto v : hole.vertices)
      hole.radius = std::max(hole.radius, (mesh.point(v) - hole.centroid).norm());
    hole.loop = loops[i];
    hole_of[i] = static_cast<int>(holes.size());
    holes.push_back(std::move(hole));
  }
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (owner[i] >= 0)
      holes[hole_of[owner[i]]].islands.push_back(loop_vertices(mesh, loops[i]));
  }
  return holes;
}

}  // namespace holebench::crest_feature
