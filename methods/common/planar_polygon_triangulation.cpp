// The methods' CGAL translation unit for 2D constrained Delaunay triangulations.
#include "methods/common/planar_polygon_triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_2.h>

#include <cmath>
#include <list>
#include <map>

namespace holebench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int nesting = -1;  // -1: not yet visited; odd: inside the polygon
};
using VertexBase = CGAL::Triangulation_vertex_base_2<Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// No intersection tag: intersecting constraints throw, and the caller reports a failure.
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;

// Marks faces by nesting level (CGAL's polygon_triangulation example): crossing a constraint
// increases the level; odd levels are inside.
void mark_nesting(Cdt& cdt) {
  std::list<Cdt::Edge> border;
  auto flood = [&](Cdt::Face_handle start, int level) {
    if (start->info().nesting != -1)
      return;
    std::list<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      auto f = queue.front();
      queue.pop_front();
      if (f->info().nesting != -1)
        continue;
      f->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        Cdt::Edge e(f, i);
        auto n = f->neighbor(i);
        if (n->info().nesting != -1)
          continue;
        if (cdt.is_constrained(e)) {
          border.push_back(e);
        } else {
          queue.push_back(n);
        }
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    const Cdt::Edge e = border.front();
    border.pop_front();
    auto n = e.first->neighbor(e.second);
    if (n->info().nesting == -1)
      flood(n, e.first->info().nesting + 1);
  }
}

}  // namespace

PolygonTriangulation2d triangulate_polygon_2d(
    const std::vector<std::vector<std::array<double, 2>>>& loops,
    const std::vector<std::array<double, 2>>& interior) {
  PolygonTriangulation2d result;
  auto fail = [&](TriangulationFailure failure) {
    result.failure = failure;
    result.triangles.clear();
    result.kept_interior.clear();
    return result;
  };
  try {
    Cdt cdt;
    // Input points are numbered in a map (a vertex's info is not initialised by CGAL).
    std::map<Cdt::Vertex_handle, int> number;
    int index = 0;
    for (const auto& loop : loops) {
      if (loop.size() < 3)
        return fail(TriangulationFailure::ShortLoop);
      std::vector<Cdt::Vertex_handle> handles;
      for (const auto& p : loop) {
        auto h = cdt.insert(Kernel::Point_2(p[0], p[1]));
        if (!number.emplace(h, index).second)
          return fail(TriangulationFailure::SharedPoint);
        handles.push_back(h);
        ++index;
      }
      for (std::size_t i = 0; i < handles.size(); ++i) {
        cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
      }
    }
    for (std::size_t i = 0; i < interior.size(); ++i) {
      auto h = cdt.insert(Kernel::Point_2(interior[i][0], interior[i][1]));
      if (!number.emplace(h, index).second)
        continue;
      result.kept_interior.push_back(static_cast<int>(i));
      ++index;
    }
    mark_nesting(cdt);
    for (auto f : cdt.finite_face_handles()) {
      if (f->info().nesting % 2 != 1)
        continue;
      std::array<int, 3> tri{};
      for (int i = 0; i < 3; ++i) {
        const auto it = number.find(f->vertex(i));
        if (it == number.end())
          return fail(TriangulationFailure::ForeignPoint);
        tri[i] = it->second;
      }
      result.triangles.push_back(tri);  // CGAL faces are counter-clockwise
    }
  } catch (const std::exception& e) {
    result.detail = e.what();
    return fail(TriangulationFailure::SelfIntersection);
  }
  if (result.triangles.empty())
    return fail(TriangulationFailure::NoTriangle);
  return result;
}

PolygonTriangulation triangulate_planar_polygon(const std::vector<Point>& outer, const Plane& plane,
                                                const std::vector<std::vector<Point>>& inner) {
  PolygonTriangulation result;
  // An orthonormal frame (u, v) of the plane with u x v = normal.
  const Point n = plane.normal / plane.normal.norm();
  const Point helper = std::abs(n[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0);
  Point u = OpenMesh::cross(n, helper);
  u /= u.norm();
  const Point v = OpenMesh::cross(n, u);

  std::vector<std::vector<std::array<double, 2>>> loops;
  auto project = [&](const std::vector<Point>& loop) {
    std::vector<std::array<double, 2>> projected;
    for (const Point& p : loop) {
      const Point d = p - plane.point;
      projected.push_back({OpenMesh::dot(d, u), OpenMesh::dot(d, v)});
    }
    loops.push_back(std::move(projected));
  };
  project(outer);
  for (const auto& loop : inner)
    project(loop);
  const PolygonTriangulation2d planar = triangulate_polygon_2d(loops);
  switch (planar.failure) {
    case TriangulationFailure::None:
      result.triangles = planar.triangles;  // counter-clockwise in (u, v): about the normal
      result.ok = true;
      break;
    case TriangulationFailure::ShortLoop:
      result.error = "a loop with fewer than three points";
      break;
    case TriangulationFailure::SharedPoint:
      // Two input points project onto one: the projection is not a simple polygon.
      result.error = "two points of the polygon project onto the same point";
      break;
    case TriangulationFailure::SelfIntersection:
      result.error = "the projected polygon intersects itself (" + planar.detail + ")";
      break;
    case TriangulationFailure::ForeignPoint:
      result.error = "the triangulation needed a point that is not on the polygon";
      break;
    case TriangulationFailure::NoTriangle:
      result.error = "no triangle inside the polygon";
      break;
  }
  return result;
}

}  // namespace holebench
