// An axis-aligned box that grows to hold points and balls, starting empty, and the test of
// whether two boxes meet: the regions around a repair's new faces that the evaluation
// compares with what it knows of the input (validity.cpp, feature_recovery.cpp,
// mean_search.cpp, hausdorff_distance.cpp: surface_change.h).
#pragma once

#include "core/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace holebench {

struct GrowingBox {
  Point lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Point hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};

  void add(const Point& p) {
    lo.minimize(p);
    hi.maximize(p);
  }
  /// The box of the ball of `radius` about `center`.
  void add_ball(const Point& center, double radius) {
    add(center - Point(radius, radius, radius));
    add(center + Point(radius, radius, radius));
  }
  /// The distance between the boxes (0 where they meet): at most the distance between any
  /// point of one and any point of the other.
  double distance_to(const GrowingBox& other) const {
    double squared = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double gap = std::max({0.0, other.lo[i] - hi[i], lo[i] - other.hi[i]});
      squared += gap * gap;
    }
    return std::sqrt(squared);
  }
  /// The centre of the box, and the radius of a ball about it that holds the box: half its
  /// diagonal, padded by 1e-6 of itself so that rounding leaves no corner outside. A scene's
  /// faces_within(centre(), enclosing_radius()) holds every face with a point in the box.
  Point centre() const { return (lo + hi) * 0.5; }
  double enclosing_radius() const { return 0.5 * (hi - lo).norm() * (1.0 + 1e-6); }
  /// The largest absolute coordinate of the box: the scale of rounding near it.
  double magnitude() const {
    return std::max({std::abs(lo[0]), std::abs(lo[1]), std::abs(lo[2]), std::abs(hi[0]),
                     std::abs(hi[1]), std::abs(hi[2])});
  }
  /// Whether the boxes share a point (touching counts).
  bool meets(const GrowingBox& other) const {
    for (int i = 0; i < 3; ++i) {
      if (hi[i] < other.lo[i] || other.hi[i] < lo[i])
        return false;
    }
    return true;
  }
};

}  // namespace holebench
