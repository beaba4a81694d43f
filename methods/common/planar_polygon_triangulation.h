// Triangulating a planar polygon (possibly with holes) by a constrained Delaunay
// triangulation in its plane (CGAL), the step both the B-Rep closing and the crest-line
// filling need.
#pragma once

#include "core/mesh.h"
#include "core/plane_fit.h"

#include <array>
#include <string>
#include <vector>

namespace holebench {

struct PolygonTriangulation {
  /// Triangles as indices into the polygon's points (outer loop first, then the inner loops,
  /// in the order given), counter-clockwise about the plane's normal.
  std::vector<std::array<int, 3>> triangles;
  bool ok = false;
  std::string error;  ///< why it failed (self-intersecting projection, ...)
};

/// Why a 2D triangulation failed.
enum class TriangulationFailure {
  None,
  ShortLoop,         ///< a loop with fewer than three points
  SharedPoint,       ///< two loop points are the same 2D point
  SelfIntersection,  ///< loops intersect themselves or each other (what() in `detail`)
  ForeignPoint,      ///< the triangulation needed a point that is not an input point
  NoTriangle,        ///< nothing lies inside the outer loop
};

struct PolygonTriangulation2d {
  /// Counter-clockwise triangles; indices count the loops' points in order, then the
  /// interior points that were kept.
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> kept_interior;  ///< indices into `interior` of the points inserted
  TriangulationFailure failure = TriangulationFailure::None;
  std::string detail;  ///< CGAL's message for a self-intersection
  bool ok() const { return failure == TriangulationFailure::None; }
};

/// The constrained Delaunay triangulation (CGAL) of the region inside the first loop and
/// outside the others, with optional interior points; an interior point that coincides with
/// one already inserted is skipped. No exception.
PolygonTriangulation2d triangulate_polygon_2d(
    const std::vector<std::vector<std::array<double, 2>>>& loops,
    const std::vector<std::array<double, 2>>& interior = {});

/// Projects `outer` (and `inner` loops) onto `plane` and triangulates the region inside the
/// outer loop and outside the inner loops, using only the given points. The outer loop may
/// run either way round. Fails (ok = false, no exception) where the projected loops
/// intersect themselves or each other.
PolygonTriangulation triangulate_planar_polygon(const std::vector<Point>& outer, const Plane& plane,
                                                const std::vector<std::vector<Point>>& inner = {});

}  // namespace holebench
