// An axis-aligned box that grows to hold points and balls, starting empty, and the test of
// whether two boxes meet: the regions around a repair's new faces that the evaluation
// compares with what it knows of the input (validity.cpp, surface_distance.cpp).
#pragma once

#include "core/mesh.h"

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
