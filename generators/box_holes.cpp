#include "generators/box_holes.h"

#include "generators/box_solid.h"
#include "generators/hole_punch.h"

#include <fmt/format.h>

namespace holebench::generators {

const char* to_string(BoxHoleTarget target) {
  switch (target) {
    case BoxHoleTarget::FaceInterior:
      return "face_interior";
    case BoxHoleTarget::Edge:
      return "edge";
    case BoxHoleTarget::Corner:
      return "corner";
  }
  return "unknown";
}

Case make_box_hole_case(const BoxHoleOptions& options) {
  const BoxOptions box;
  const Point& s = box.size;
  Case result;
  result.family = "box";
  result.kind = to_string(options.target);
  result.id = fmt::format("box/{}", result.kind);
  result.complete = make_box(box);

  HoleTruth truth;
  truth.target = result.kind;
  HoleLabels labels;
  Point center;
  // Sizes as CASES.md defines them: the largest diameter (k = 1), the largest distance
  // to the missing edge (k = 2), the distance to the missing corner (k = 3). The ball
  // removes about a disc of `radius` around its centre on each face it touches.
  double hole_size = 0.0;
  switch (options.target) {
    case BoxHoleTarget::FaceInterior:
      // The centre of the +z face (region 5).
      center = Point(0.5 * s[0], 0.5 * s[1], s[2]);
      labels.k = 1;
      labels.regions = {5};
      hole_size = 2.0 * options.radius;
      break;
    case BoxHoleTarget::Edge: {
      // The middle of the convex edge between +y (region 3) and +z (region 5), along x.
      center = Point(0.5 * s[0], s[1], s[2]);
      labels.k = 2;
      labels.regions = {3, 5};
      labels.transitions = {Convexity::Convex, Convexity::Convex};
      truth.missing_edges.push_back({Point(center[0] - options.radius, s[1], s[2]),
                                     Point(center[0] + options.radius, s[1], s[2])});
      hole_size = options.radius;
      break;
    }
    case BoxHoleTarget::Corner: {
      // The corner (size) where +x, +y and +z meet; its three edges are convex.
      center = s;
      labels.k = 3;
      labels.regions = {1, 3, 5};
      labels.transitions = {Convexity::Convex, Convexity::Convex, Convexity::Convex};
      for (int axis = 0; axis < 3; ++axis) {
        Point end = s;
        end[axis] -= options.radius;
        truth.missing_edges.push_back({s, end});
      }
      truth.missing_corners.push_back(s);
      hole_size = options.radius;
      break;
    }
  }
  labels.orientation = Orientation::Inner;
  labels.size = hole_size;
  labels.structure_size = options.structure_size;
  labels.expected_decision =
      hole_size < options.structure_size ? Decision::CloseAutomatically : Decision::Guide;
  truth.labels = labels;

  PunchResult punched =
      punch_faces(result.complete, faces_in_ball(result.complete, center, options.radius));
  truth.removed_faces = std::move(punched.removed_faces);
  result.input = std::move(punched.holed);
  result.holes.push_back(std::move(truth));
  return result;
}

}  // namespace holebench::generators
