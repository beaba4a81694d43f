// The normal cones at fixed points (the complete model's literature samples) against a case's
// input, kept so that each repair that appends to the input answers them at the cost of its
// patch.
//
// normal_cone_angle() against a surface S asks for p's nearest distance d to S and the faces of
// S within d + tolerance. Where S is the input I plus a patch P (a scene made of I's scene and
// P's: TriangleScene's base and added parts), d = min(d_I, d_P), and the faces within d +
// tolerance are I's within it and P's within it. So each point keeps d_I and every face of I
// within d_I + tolerance (its distance and its cosine with the point's normal): a job asks P
// alone where P can come that near (its bounding box within d_I + tolerance of the point),
// keeps the faces of I within the new radius, and takes the largest cosines over both; the
// other points keep their answer. The answers are normal_cone_angle()'s against a scene of the
// whole repair, bit for bit (the same distances of the same triangles, and maxima that do not
// depend on the order).
#pragma once

#include "core/mesh.h"
#include "metrics/literature_metrics.h"
#include "metrics/normal_cone.h"

#include <cstddef>
#include <vector>

namespace holebench {

namespace embree {
class TriangleScene;
}

class InputConeAnswers {
 public:
  /// The cones at `samples` (points with unit normals) against `input_scene`.
  InputConeAnswers(const AreaSamples& samples, const embree::TriangleScene& input_scene,
                   const NormalConeOptions& options);

  const embree::TriangleScene& input_scene() const { return *input_scene_; }
  const std::vector<Point>& points() const { return points_; }
  const std::vector<Point>& normals() const { return normals_; }

  /// The answers at the points against the input plus `patch` (a scene of the faces a
  /// repair adds to the input; nullptr: none), as SampledAnswers for sampled_agreement().
  SampledAnswers with_patch(const embree::TriangleScene* patch) const;

 private:
  struct NearFace {
    double distance = 0.0;  ///< from the point
    double cosine = 0.0;    ///< of the point's normal with the face's, clamped to [-1, 1]
  };
  const embree::TriangleScene* input_scene_;
  NormalConeOptions options_;
  std::vector<Point> points_, normals_;
  std::vector<double> nearest_;          ///< d_I per point
  std::vector<double> nearest_cosine_;   ///< the nearest face's cosine per point
  std::vector<std::size_t> first_near_;  ///< per point, its first entry in near_ (and one more)
  std::vector<NearFace> near_;           ///< faces of I within d_I + tolerance, point by point
};

}  // namespace holebench
