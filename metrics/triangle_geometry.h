// Geometry of a triangle given by its three corners, shared by the distance searches
// (hausdorff_distance.cpp, mean_search.cpp): its area, plane and box, the distances from its
// corners to another triangle, and whether two triangles meet and how far apart they are.
#pragma once

#include "core/mesh.h"
#include "core/plane_fit.h"
#include "metrics/growing_box.h"

#include <array>

namespace holebench {

double triangle_area(const std::array<Point, 3>& c);

/// The plane of a triangle (unit normal, a corner as its point); false for a degenerate one.
bool plane_of(const std::array<Point, 3>& t, Plane& plane);

GrowingBox box_of(const std::array<Point, 3>& t);

/// The distance from each corner of `corners` to triangle `t`.
std::array<double, 3> corner_distances_to_triangle(const std::array<Point, 3>& corners,
                                                   const std::array<Point, 3>& t);

/// Whether segment [p, q] meets triangle t (Moller-Trumbore with t in [0, 1]).
bool segment_meets_triangle(const Point& p, const Point& q, const std::array<Point, 3>& t);

/// Whether an edge of either triangle meets the other (then they meet).
bool edges_meet_triangles(const std::array<Point, 3>& a, const std::array<Point, 3>& b);

/// The distance between two triangles: 0 if they meet, else the smallest of the
/// vertex-triangle and edge-edge distances.
double triangle_triangle_distance(const std::array<Point, 3>& a, const std::array<Point, 3>& b);

}  // namespace holebench
