// The normal cone of a surface at a point's nearest distance: the normals of every face of
// the surface within a tolerance of the point's nearest distance. On or next to a crease the
// faces on both sides are about equally near, so "the normal of the nearest face" flips
// between them with round-off or the order of a search; the smallest angle over the cone does
// not (docs/metrics.md, "Normal deviation").
#pragma once

#include "core/mesh.h"

#include <array>

namespace holebench {

namespace embree {
class TriangleScene;
}

struct NormalConeOptions {
  /// Faces within the nearest distance plus this (model units; the evaluation passes a
  /// fraction of the diagonal) belong to the cone.
  double tolerance = 1e-3;
};

/// The angles between a unit normal `n` at point `p` and the surface's normal cone at `p`.
struct NormalConeAngle {
  double smallest_deg = 0.0;  ///< min over the cone of the angle between n and the face's normal
  /// max over the cone of |n . m| (m the face's unit normal): the orientation-blind agreement
  /// the literature's normal consistency uses.
  double largest_abs_cosine = 0.0;
  double nearest_distance = 0.0;  ///< d(p, surface)
  int cone_faces = 0;             ///< faces in the cone (at least the nearest)
};

/// A face's term in the cone: the cosine of the unit normal `n` with triangle `t`'s unit
/// normal, clamped to [-1, 1].
double cone_cosine(const Point& n, const std::array<Point, 3>& t);

/// The cone's angles folded over its faces' cosines (maxima: in any order, the same).
struct NormalConeFold {
  double largest_cosine = -1.0;
  NormalConeAngle cone;  ///< largest_abs_cosine and cone_faces so far

  void add(double cosine);
  /// The angles of the faces added, at the nearest distance `nearest_distance`.
  NormalConeAngle finish(double nearest_distance) const;
};

/// The normal cone of the surface of `scene` at `p`, compared with the unit normal `n`.
NormalConeAngle normal_cone_angle(const embree::TriangleScene& scene, const Point& p,
                                  const Point& n, const NormalConeOptions& options = {});

/// The unit normal of a triangle (zero for a degenerate one).
Point triangle_unit_normal(const Point& a, const Point& b, const Point& c);

}  // namespace holebench
