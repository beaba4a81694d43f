// The crest_feature method's CGAL translation unit for the optional refinement and fairing.
#include "methods/crest_feature/hole_filling.h"

#include "core/geometry.h"
#include "core/plane_fit.h"
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

Point node_point(const Mesh& mesh, const HolePartition& partition, Node node) {
  return node >= 0 ? mesh.point(mesh.vertex_handle(node))
                   : partition.new_points[new_point_index(node)];
}

// Newell's normal of a closed polygon.
Point newell_normal(const std::vector<Point>& points) {
  Point n(0, 0, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    const Point& q = points[(i + 1) % points.size()];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
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

HoleFillingResult fill_hole(Mesh& mesh, const HolePartition& partition,
                            const HoleFillingOptions& options) {
  HoleFillingResult result;
  std::vector<std::array<Node, 3>> triangles;
  for (const auto& sub_hole : partition.sub_holes) {
    SubHoleFilling filling;
    std::vector<Point> points;
    for (Node node : sub_hole)
      points.push_back(node_point(mesh, partition, node));
    Point centroid(0, 0, 0);
    for (const Point& p : points)
      centroid += p;
    centroid /= static_cast<double>(points.size());
    // Equation 6 first; where its projection intersects itself, Newell's normal (the
    // maximum area vector of the polygon itself), then the least-squares plane.
    struct Candidate {
      std::string name;
      std::string fallback;
      Point normal;
    };
    std::vector<Candidate> normals{{"equation 6", "", projection_normal(mesh, sub_hole)},
                                   {"newell", kNewellProjection, newell_normal(points)}};
    const PlaneFit fit = fit_plane(points);
    if (fit.valid)
      normals.push_back({"least squares", kLeastSquaresProjection, fit.plane.normal});
    PolygonTriangulation triangulation;
    for (const auto& [name, fallback, normal] : normals) {
      if (normal.norm() < 1e-12)
        continue;
      Plane plane;
      plane.point = centroid;
      plane.normal = normal / normal.norm();
      triangulation = triangulate_planar_polygon(points, plane);
      if (triangulation.ok) {
        filling.plane = name;
        filling.fallback = fallback;
        break;
      }
      if (filling.error.empty())
        filling.error = name + ": " + triangulation.error;
    }
    if (!triangulation.ok && options.polyline_fallback) {
      // Every projection intersects itself: a minimum-weight triangulation of the 3D
      // boundary polygon (Barequet-Sharir / Liepa, CGAL), recorded as a departure.
      using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
      std::vector<Kernel::Point_3> polyline;
      for (const Point& p : points)
        polyline.emplace_back(p[0], p[1], p[2]);
      std::vector<CGAL::Triple<int, int, int>> patch;
      // Without CGAL's 3D Delaunay restriction: on regular boundaries it depends on memory
      // addresses, and the same job would give different patches (docs/methods.md).
      PMP::triangulate_hole_polyline(polyline, std::back_inserter(patch),
                                     CGAL::parameters::use_delaunay_triangulation(false));
      if (!patch.empty()) {
        triangulation.triangles.clear();
        for (const auto& t : patch)
          triangulation.triangles.push_back({t.first, t.second, t.third});
        triangulation.ok = true;
        filling.plane = "none (3D minimum-weight triangulation)";
        filling.fallback = kPolylineTriangulation;
      }
    }
    filling.ok = triangulation.ok;
    if (triangulation.ok) {
      // Orient the patch like the mesh: the triangle on the sub-hole's first edge (0, 1)
      // must run 0 -> 1.
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
        std::array<Node, 3> tri{sub_hole[t[0]], sub_hole[t[1]], sub_hole[t[2]]};
        if (flip)
          std::swap(tri[1], tri[2]);
        triangles.push_back(tri);
      }
    }
    result.sub_holes.push_back(filling);
  }
  const bool all = std::all_of(result.sub_holes.begin(), result.sub_holes.end(),
                               [](const SubHoleFilling& s) { return s.ok; });
  if (!all) {
    result.error = "a sub-hole could not be triangulated";
    return result;
  }

  // Stitch: new vertices for the new points the sub-holes use, then the faces.
  Mesh patched = mesh;
  std::map<Node, VertexHandle> handles;
  auto handle = [&](Node node) {
    if (node >= 0)
      return patched.vertex_handle(node);
    auto it = handles.find(node);
    if (it == handles.end()) {
      it = handles.emplace(node, patched.add_vertex(partition.new_points[new_point_index(node)]))
               .first;
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
      return result;
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
  return result;
}

std::size_t fill_hole_without_features(Mesh& mesh, HalfedgeHandle border) {
  std::vector<FaceHandle> faces;
  PMP::triangulate_hole(mesh, border, std::back_inserter(faces),
                        CGAL::parameters::use_delaunay_triangulation(false));
  return faces.size();
}

}  // namespace holebench::crest_feature
