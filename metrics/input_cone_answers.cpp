#include "metrics/input_cone_answers.h"

#include "core/distances.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/growing_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace holebench {
InputConeAnswers::InputConeAnswers(const AreaSamples& samples,
                                   const embree::TriangleScene& input_scene,
                                   const NormalConeOptions& options)
    : input_scene_(&input_scene),
      options_(options),
      points_(samples.points),
      normals_(samples.normals) {
  nearest_.reserve(points_.size());
  nearest_cosine_.reserve(points_.size());
  first_near_.reserve(points_.size() + 1);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    first_near_.push_back(near_.size());
    const Point& p = points_[i];
    const auto nearest = input_scene.closest_point(p);
    nearest_.push_back(nearest.distance);
    nearest_cosine_.push_back(
        nearest.face >= 0 ? cone_cosine(normals_[i], input_scene.triangle_of_face(nearest.face))
                          : 0.0);
    for (int face : input_scene.faces_within(p, nearest.distance + options.tolerance)) {
      const auto& t = input_scene.triangle_of_face(face);
      near_.push_back({point_triangle_distance(p, t), cone_cosine(normals_[i], t)});
    }
  }
  first_near_.push_back(near_.size());
}

SampledAnswers InputConeAnswers::with_patch(const embree::TriangleScene* patch) const {
  SampledAnswers out{points_, normals_, {}};
  out.cones.reserve(points_.size());
  // The patch's box: no patch face lies nearer a point than it does (infinitely far when
  // there is no patch).
  GrowingBox box;
  if (patch) {
    for (const auto& t : patch->triangles())
      for (const Point& c : t)
        box.add(c);
  }
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const Point& p = points_[i];
    const double input_radius = nearest_[i] + options_.tolerance;
    // The patch's box lies beyond the input's radius (with a margin far above the rounding of
    // the two distances): no patch face is nearer than the input or within the radius.
    const double margin = 1e-9 * (input_radius + std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]));
    GrowingBox at_p;
    at_p.add(p);
    const bool patch_near = patch && box.distance_to(at_p) <= input_radius + margin;
    embree::ClosestPoint from_patch;
    from_patch.distance = std::numeric_limits<double>::infinity();
    if (patch_near)
      from_patch = patch->closest_point(p);
    const double nearest = std::min(nearest_[i], from_patch.distance);
    const double radius = nearest + options_.tolerance;
    NormalConeFold fold;
    for (std::size_t k = first_near_[i]; k < first_near_[i + 1]; ++k) {
      if (near_[k].distance <= radius)
        fold.add(near_[k].cosine);
    }
    if (patch_near) {
      for (int face : patch->faces_within(p, radius))
        fold.add(cone_cosine(normals_[i], patch->triangle_of_face(face)));
    }
    if (fold.cone.cone_faces == 0) {  // the nearest face belongs to the cone by definition
      const bool patch_wins = from_patch.face >= 0 && from_patch.distance < nearest_[i];
      fold.add(patch_wins ? cone_cosine(normals_[i], patch->triangle_of_face(from_patch.face))
                          : nearest_cosine_[i]);
    }
    out.cones.push_back(fold.finish(nearest));
  }
  return out;
}

}  // namespace holebench
