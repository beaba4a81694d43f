// The last trimming domain of slice_loft: the boundary of a portion developed onto a disc.
// Section 4.1.1 of the slice paper develops every contour onto a reference circle whose
// perimeter is the contour's length; here the same development serves the trimming where
// the boundary's pre-image folds both in the portion's plane and on the lofted surface (a
// hole wrapped around a corner, a noisy boundary running along the slicing direction). A
// disc is convex, so the boundary never crosses itself there and the constrained
// triangulation always exists; a point of the disc is taken to the surface through the
// mean value coordinates (Floater 2003) of the boundary's own surface parameters, so every
// new vertex lies on the lofted surface and the boundary vertices stay where they are.
#pragma once

#include "core/mesh.h"

#include <array>
#include <vector>

namespace holebench::slice_loft {

struct DevelopedDisc {
  /// The loop's points on the circle of perimeter = the loop's length, counter-clockwise,
  /// each at the arc length of the loop up to it.
  std::vector<std::array<double, 2>> points;
  double radius = 0.0;
  /// How much farther apart interior points go on the disc than on the surface: the square
  /// root of the disc's area over the loop's vector area, in [1, 5] (a long thin portion
  /// develops onto a disc far larger than itself).
  double spacing_scale = 1.0;
};

DevelopedDisc develop_onto_disc(const std::vector<Point>& loop);

/// The mean value coordinates of `x` with respect to the polygon (Floater 2003): positive
/// inside a convex polygon, summing to 1, reproducing linear functions.
std::vector<double> mean_value_coordinates(const std::vector<std::array<double, 2>>& polygon,
                                           std::array<double, 2> x);

}  // namespace holebench::slice_loft
