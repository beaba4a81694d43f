// Closed polygons in 3D given by their points in order: Newell's normal, which side of a
// polygon a point lies on once both are projected along a direction, and a polygon's diameter.
#pragma once

#include "core/mesh.h"

#include <vector>

namespace holebench {

/// Newell's normal of a closed polygon: its vector area times two. Its direction is the one
/// about which the polygon runs counter-clockwise; zero for fewer than three points.
Point newell_normal(const std::vector<Point>& polygon);

/// Whether `p` lies inside `polygon` once both are projected on a plane normal to
/// `direction` (even-odd rule; a point on the boundary may count either way).
bool inside_projected_polygon(const std::vector<Point>& polygon, const Point& direction,
                              const Point& p);

/// The largest distance between two of the points (0 for fewer than two): a hole's size as
/// CASES.md defines it for k = 1.
double diameter(const std::vector<Point>& points);

}  // namespace holebench
