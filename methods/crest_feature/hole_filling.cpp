// The crest_feature method's CGAL translation unit for the optional refinement and fairing.
#include "methods/crest_feature/hole_filling.h"

#include "core/geometry.h"
#include "core/plane_fit.h"
#include "core/polygon.h"
#include "methods/common/planar_polygon_triangulation.h"

// CGAL's graph traits for OpenMesh must come before any CGAL algorithm header.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/refine.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <set>

namespace holebench::crest_feature {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

// SubHoleFilling::fallback names, from the nearest to the paper's step to the furthest.
constexpr const char* kNewellProjection = "sub_hole_newell_projection";
constexpr const char* kLeastSquaresProjection = "sub_hole_least_squares_projection";
constexpr const char* kPolylineTriangulation = "sub_hole_cgal_triangulate_hole_polyline";

// A node's position: a mesh vertex's, or one of `new_points` (new_point_node numbering).
Point node_point(const Mesh& mesh, const std::vector<Point>& new_points, Node node) {
  return node >= 0 ? mesh.point(mesh.vertex_handle(node)) : new_points[new_point_index(node)];
}

std::vector<Point> node_points(const Mesh& mesh, const std::vector<Point>& new_points,
                               const std::vector<Node>& nodes) {
  std::vector<Point> points;
  for (Node node : nodes)
    points.push_back(node_point(mesh, new_points, node));
  return points;
}

}  // namespace

Point projection_normal(const Mesh& mesh, const std::vector<Node>& sub_hole) {
  Point n(0, 0, 0);
  for (std::size_t i = 0; i < sub_hole.size(); ++i) {
    const Node a = sub_hole[i], b = sub_hole[(i + 1) % sub_hole.size()];
    if (a < 0 || b < 0)
      continue;
    const auto h = mesh.find_halfedge(mesh.vertex_handle(a), mesh.vertex_handle(b));
    if (!h.is_valid() || !mesh.is_boundary(h))
      continue;
    n += face_normal(mesh, mesh.opposite_face_handle(h));
  }
  return n;
}

std::string sub_hole_fallback(const std::vector<SubHoleFilling>& sub_holes) {
  for (const char* name : {kPolylineTriangulation, kLeastSquaresProjection, kNewellProjection}) {
    for (const auto& s : sub_holes) {
      if (s.ok && s.fallback == name)
        return name;
    }
  }
  return "";
}

std::vector<int> place_islands(const Mesh& mesh, const HolePartition& partition) {
  std::vector<int> placed(partition.islands.size(), -1);
  for (std::size_t k = 0; k < partition.islands.size(); ++k) {
    const std::vector<Point> island = node_points(mesh, partition.new_points, partition.islands[k]);
    for (std::size_t i = 0; i < partition.sub_holes.size() && placed[k] < 0; ++i) {
      const std::vector<Point> boundary =
          node_points(mesh, partition.new_points, partition.sub_holes[i]);
      Point normal = projection_normal(mesh, partition.sub_holes[i]);
      if (normal.norm() < 1e-12)
        normal = newell_normal(boundary);
      const bool inside = std::all_of(island.begin(), island.end(), [&](const Point& p) {
        return inside_projected_polygon(boundary, normal, p);
      });
      if (inside)
        placed[k] = static_cast<int>(i);
    }
  }
  return placed;
}

std::size_t split_chords_the_mesh_has(const Mesh& mesh, std::vector<std::array<Node, 3>>& triangles,
                                      std::vector<Point>& new_points) {
  auto point = [&](Node node) { return node_point(mesh, new_points, node); };
  // The halfedge a -> b of a triangle can be stitched only where the mesh has no such edge
  // or has it as a boundary halfedge (an edge of the hole's own loop).
  auto taken = [&](Node a, Node b) {
    if (a < 0 || b < 0)
      return false;
    const auto h = mesh.find_halfedge(mesh.vertex_handle(a), mesh.vertex_handle(b));
    return h.is_valid() && !mesh.is_boundary(h);
  };
  std::size_t splits = 0;
  // Each split removes one taken chord and adds none (the new edges end at the new point).
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Node a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      if (!taken(a, b))
        continue;
      const Node m = new_point_node(static_cast<int>(new_points.size()));
      new_points.push_back((point(a) + point(b)) * 0.5);
      ++splits;
      // Every triangle on the chord {a, b} (this one and its neighbour across it) becomes two.
      const std::size_t count = triangles.size();
      for (std::size_t u = 0; u < count; ++u) {
        for (int j = 0; j < 3; ++j) {
          const Node p = triangles[u][j], q = triangles[u][(j + 1) % 3],
                     r = triangles[u][(j + 2) % 3];
          if ((p == a && q == b) || (p == b && q == a)) {
            triangles[u] = {p, m, r};
            triangles.push_back({m, q, r});
            break;
          }
        }
      }
      k = -1;  // the triangle changed: look at its edges again
    }
  }
  return splits;
}

namespace {

// The CDT of a loop (and inner loops) projected on the plane with `normal` through the loop's
// centroid; indices count the loop's nodes, then the inner loops'.
PolygonTriangulation projected_triangulation(const Mesh& mesh, const std::vector<Point>& new_points,
                                             const std::vector<Node>& loop,
                                             const std::vector<std::vector<Node>>& inner,
                                             const Point& normal) {
  PolygonTriangulation triangulation;
  if (normal.norm() < 1e-12) {
    triangulation.error = "no projection direction";
    return triangulation;
  }
  const std::vector<Point> points = node_points(mesh, new_points, loop);
  std::vector<std::vector<Point>> inner_points;
  for (const auto& island : inner)
    inner_points.push_back(node_points(mesh, new_points, island));
  Plane plane;
  for (const Point& p : points)
    plane.point += p;
  plane.point /= static_cast<double>(points.size());
  plane.normal = normal / normal.norm();
  return triangulate_planar_polygon(points, plane, inner_points);
}

// Equation 6: the normals of the triangles along the loop and along the inner loops.
PolygonTriangulation equation_6(const Mesh& mesh, const std::vector<Point>& new_points,
                                const std::vector<Node>& loop,
                                const std::vector<std::vector<Node>>& inner) {
  Point normal = projection_normal(mesh, loop);
  for (const auto& island : inner)
    normal += projection_normal(mesh, island);
  return projected_triangulation(mesh, new_points, loop, inner, normal);
}

// Orient a triangulation like the mesh (the triangle on the loop's first edge (0, 1) must run
// 0 -> 1) and keep its triangles as nodes.
void keep_oriented(const std::vector<Node>& nodes, const PolygonTriangulation& triangulation,
                   std::vector<std::array<Node, 3>>& triangles) {
  bool flip = false;
  for (const auto& t : triangulation.triangles) {
    for (int k = 0; k < 3; ++k) {
      if (t[k] == 0 && t[(k + 1) % 3] == 1)
        flip = false;
      if (t[k] == 1 && t[(k + 1) % 3] == 0)
        flip = true;
    }
  }
  for (const auto& t : triangulation.triangles) {
    std::array<Node, 3> tri{nodes[t[0]], nodes[t[1]], nodes[t[2]]};
    if (flip)
      std::swap(tri[1], tri[2]);
    triangles.push_back(tri);
  }
}

// Every projection intersects itself: a minimum-weight triangulation of the 3D boundary
// polygon (Barequet-Sharir / Liepa, CGAL), recorded as a departure. False where CGAL finds
// none.
bool triangulate_3d_polygon(const std::vector<Point>& points, PolygonTriangulation& triangulation) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_3> polyline;
  for (const Point& p : points)
    polyline.emplace_back(p[0], p[1], p[2]);
  std::vector<CGAL::Triple<int, int, int>> patch;
  // Without CGAL's 3D Delaunay restriction: on regular boundaries it depends on memory
  // addresses, and the same job would give different patches (docs/methods.md).
  PMP::triangulate_hole_polyline(polyline, std::back_inserter(patch),
                                 CGAL::parameters::use_delaunay_triangulation(false));
  if (patch.empty())
    return false;
  triangulation.triangles.clear();
  for (const auto& t : patch)
    triangulation.triangles.push_back({t.first, t.second, t.third});
  triangulation.ok = true;
  return true;
}

// One sub-hole (`loop` with the islands placed in it) triangulated, its triangles added to
// `triangles`: by equation 6 (the paper's step), else equation 6 on planar pieces, else the
// fallbacks, each named. `new_points` grows by the chords' points.
SubHoleFilling fill_sub_hole(const Mesh& mesh, std::vector<Point>& new_points,
                             const std::vector<Node>& loop,
                             const std::vector<std::vector<Node>>& islands,
                             const HoleFillingOptions& options,
                             std::vector<std::array<Node, 3>>& triangles) {
  SubHoleFilling filling;
  // The triangulation's indices count the loop's nodes, then the islands'.
  std::vector<Node> nodes = loop;
  for (const auto& island : islands)
    nodes.insert(nodes.end(), island.begin(), island.end());

  // Equation 6 (the paper's step).
  PolygonTriangulation triangulation = equation_6(mesh, new_points, loop, islands);
  if (triangulation.ok) {
    filling.ok = true;
    filling.plane = "equation 6";
    keep_oriented(nodes, triangulation, triangles);
    return filling;
  }
  filling.error = "equation 6: " + triangulation.error;

  // Where its projection intersects itself: the sub-hole cut into more planar pieces, each
  // projected by equation 6 (planarity_split.h).
  if (islands.empty()) {
    const PlanaritySplit split = split_for_equation_6(
        loop, new_points, [&](Node node) { return node_point(mesh, new_points, node); },
        [&](const std::vector<Node>& piece) { return equation_6(mesh, new_points, piece, {}); },
        options.planarity_split);
    if (split.ok) {
      filling.ok = true;
      filling.plane = "equation 6";
      filling.chords = split.chords;
      for (const auto& piece : split.pieces)
        keep_oriented(piece.nodes, piece.triangulation, triangles);
      return filling;
    }
  }

  // Not in the paper: Newell's normal (the maximum area vector of the polygon itself), then
  // the least-squares plane, then a 3D triangulation; each named as the fallback.
  const std::vector<Point> points = node_points(mesh, new_points, loop);
  std::vector<std::pair<std::string, Point>> normals{{"newell", newell_normal(points)}};
  const PlaneFit fit = fit_plane(points);
  if (fit.valid)
    normals.push_back({"least squares", fit.plane.normal});
  for (const auto& [name, normal] : normals) {
    triangulation = projected_triangulation(mesh, new_points, loop, islands, normal);
    if (triangulation.ok) {
      filling.plane = name;
      filling.fallback = name == "newell" ? kNewellProjection : kLeastSquaresProjection;
      break;
    }
  }
  if (!triangulation.ok && options.polyline_fallback && islands.empty() &&
      triangulate_3d_polygon(points, triangulation)) {
    filling.plane = "none (3D minimum-weight triangulation)";
    filling.fallback = kPolylineTriangulation;
  }
  filling.ok = triangulation.ok;
  if (triangulation.ok)
    keep_oriented(nodes, triangulation, triangles);
  return filling;
}

// Stitch: new vertices for the new points the sub-holes use, then the faces; refined and
// faired where the options ask. The mesh is changed only where every triangle was stitched.
void stitch(Mesh& mesh, const std::vector<std::array<Node, 3>>& triangles,
            const std::vector<Point>& new_points, const HoleFillingOptions& options,
            HoleFillingResult& result) {
  Mesh patched = mesh;
  std::map<Node, VertexHandle> handles;
  auto handle = [&](Node node) {
    if (node >= 0)
      return patched.vertex_handle(node);
    auto it = handles.find(node);
    if (it == handles.end()) {
      it = handles.emplace(node, patched.add_vertex(new_points[new_point_index(node)])).first;
      ++result.new_vertices;
    }
    return it->second;
  };
  std::vector<FaceHandle> new_faces;
  for (const auto& t : triangles) {
    const FaceHandle f = patched.add_face(handle(t[0]), handle(t[1]), handle(t[2]));
    if (!f.is_valid()) {
      result.error = "a patch triangle could not be stitched (non-manifold)";
      result.new_vertices = 0;
      return;
    }
    new_faces.push_back(f);
  }
  if (options.refine_and_fair) {
    std::vector<FaceHandle> refined_faces;
    std::vector<VertexHandle> refined_vertices;
    PMP::refine(patched, new_faces, std::back_inserter(refined_faces),
                std::back_inserter(refined_vertices),
                CGAL::parameters::density_control_factor(options.density_control_factor));
    if (!refined_vertices.empty())
      PMP::fair(patched, refined_vertices);
    result.new_vertices += refined_vertices.size();
  }
  result.new_faces = count_new_faces(patched) - count_new_faces(mesh);
  result.closed = true;
  mesh = std::move(patched);
}

}  // namespace

HoleFillingResult fill_hole(Mesh& mesh, const HolePartition& partition,
                            const HoleFillingOptions& options) {
  HoleFillingResult result;
  const std::vector<int> placed = place_islands(mesh, partition);
  if (std::find(placed.begin(), placed.end(), -1) != placed.end()) {
    result.error = "an island lies inside no sub-hole";
    return result;
  }
  std::vector<Point> new_points = partition.new_points;  // grows by the chords' points
  std::vector<std::array<Node, 3>> triangles;
  for (std::size_t i = 0; i < partition.sub_holes.size(); ++i) {
    std::vector<std::vector<Node>> islands;
    for (std::size_t k = 0; k < placed.size(); ++k) {
      if (placed[k] == static_cast<int>(i))
        islands.push_back(partition.islands[k]);
    }
    result.sub_holes.push_back(
        fill_sub_hole(mesh, new_points, partition.sub_holes[i], islands, options, triangles));
  }
  const bool all = std::all_of(result.sub_holes.begin(), result.sub_holes.end(),
                               [](const SubHoleFilling& s) { return s.ok; });
  if (!all) {
    result.error = "a sub-hole could not be triangulated";
    return result;
  }
  if (options.split_taken_chords)
    result.split_chords = split_chords_the_mesh_has(mesh, triangles, new_points);
  stitch(mesh, triangles, new_points, options, result);
  return result;
}

std::size_t fill_hole_without_features(Mesh& mesh, HalfedgeHandle border) {
  std::vector<FaceHandle> faces;
  PMP::triangulate_hole(mesh, border, std::back_inserter(faces),
                        CGAL::parameters::use_delaunay_triangulation(false));
  return faces.size();
}

}  // namespace holebench::crest_feature
