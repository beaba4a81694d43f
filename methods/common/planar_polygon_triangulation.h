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

/// Projects `outer` (and `inner` loops) onto `plane` and triangulates the region inside the
/// outer loop and outside the inner loops, using only the given points. The outer loop may
/// run either way round. Fails (ok = false, no exception) where the projected loops
/// intersect themselves or each other.
PolygonTriangulation triangulate_planar_polygon(const std::vector<Point>& outer, const Plane& plane,
                                                const std::vector<std::vector<Point>>& inner = {});

}  // namespace holebench
