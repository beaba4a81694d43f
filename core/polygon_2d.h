// Closed polygons in the plane, given by their points in order: which side of one a point lies
// on, how far a point is from one, and a polygon's signed area. The 2D counterparts of
// core/polygon.h, for methods that work in a projection or a parameter domain.
#pragma once

#include <vector>

namespace holebench {

struct Point2d {
  double x = 0.0, y = 0.0;
};

/// Whether `p` lies inside `polygon` (even-odd rule; a point on the boundary may count either
/// way).
bool inside_polygon_2d(const std::vector<Point2d>& polygon, Point2d p);

/// The distance from `p` to the nearest point of the polygon's edges (the closing edge from
/// the last point to the first included).
double distance_to_polygon_2d(const std::vector<Point2d>& polygon, Point2d p);

/// The signed area: positive when the polygon runs counter-clockwise.
double signed_area_2d(const std::vector<Point2d>& polygon);

}  // namespace holebench
