#include "metrics/input_cone_answers.h"

#include "core/distances.h"
#include "core/portable_math.h"
#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace holebench {
namespace {

double face_distance(const Point& p, const std::array<Point, 3>& t) {
  // The expression TriangleScene's radius query compares with its radius.
  return (closest_point_on_triangle(p, t[0], t[1], t[2]) - p).norm();
}

double face_cosine(const Point& n, const std::array<Point, 3>& t) {
  return std::clamp(OpenMesh::dot(n, triangle_unit_normal(t[0], t[1], t[2])), -1.0, 1.0);
}

/// normal_cone_angle's fold over the cone's cosines.
struct ConeFold {
  double largest_cosine = -1.0;
  NormalConeAngle cone;
  void add(double cosine) {
    largest_cosine = std::max(largest_cosine, cosine);
    cone.largest_abs_cosine = std::max(cone.largest_abs_cosine, std::abs(cosine));
    ++cone.cone_faces;
  }
  NormalConeAngle finish(double nearest_distance) {
    cone.nearest_distance = nearest_distance;
    cone.smallest_deg = std::acos(largest_cosine) * 180.0 / kPi;
    return cone;
  }
};

/// The box of a scene's triangles: no triangle lies nearer a point than the box does.
struct TriangleBox {
  Point low = Point(1, 1, 1) * std::numeric_limits<double>::infinity();
  Point high = -Point(1, 1, 1) * std::numeric_limits<double>::infinity();

  explicit TriangleBox(const std::vector<std::array<Point, 3>>& triangles) {
    for (const auto& t : triangles) {
      for (const Point& c : t) {
        low.minimize(c);
        high.maximize(c);
      }
    }
  }
  /// Infinity for a box of no triangles.
  double distance(const Point& p) const {
    if (!(low[0] <= high[0]))
      return std::numeric_limits<double>::infinity();
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double out = std::max({0.0, low[k] - p[k], p[k] - high[k]});
      sum += out * out;
    }
    return std::sqrt(sum);
  }
};

}  // namespace

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
        nearest.face >= 0 ? face_cosine(normals_[i], input_scene.triangle_of_face(nearest.face))
                          : 0.0);
    for (int face : input_scene.faces_within(p, nearest.distance + options.tolerance)) {
      const auto& t = input_scene.triangle_of_face(face);
      near_.push_back({face_distance(p, t), face_cosine(normals_[i], t)});
    }
  }
  first_near_.push_back(near_.size());
}

SampledAnswers InputConeAnswers::with_patch(const embree::TriangleScene* patch) const {
  SampledAnswers out{points_, normals_, {}};
  out.cones.reserve(points_.size());
  const TriangleBox box(patch ? patch->triangles() : std::vector<std::array<Point, 3>>{});
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const Point& p = points_[i];
    const double input_radius = nearest_[i] + options_.tolerance;
    // The patch's box lies beyond the input's radius (with a margin far above the rounding of
    // the two distances): no patch face is nearer than the input or within the radius.
    const double margin = 1e-9 * (input_radius + std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]));
    const bool patch_near = patch && box.distance(p) <= input_radius + margin;
    embree::ClosestPoint from_patch;
    from_patch.distance = std::numeric_limits<double>::infinity();
    if (patch_near)
      from_patch = patch->closest_point(p);
    const double nearest = std::min(nearest_[i], from_patch.distance);
    const double radius = nearest + options_.tolerance;
    ConeFold fold;
    for (std::size_t k = first_near_[i]; k < first_near_[i + 1]; ++k) {
      if (near_[k].distance <= radius)
        fold.add(near_[k].cosine);
    }
    if (patch_near) {
      for (int face : patch->faces_within(p, radius))
        fold.add(face_cosine(normals_[i], patch->triangle_of_face(face)));
    }
    if (fold.cone.cone_faces == 0) {  // the nearest face belongs to the cone by definition
      const bool patch_wins = from_patch.face >= 0 && from_patch.distance < nearest_[i];
      fold.add(patch_wins ? face_cosine(normals_[i], patch->triangle_of_face(from_patch.face))
                          : nearest_cosine_[i]);
    }
    out.cones.push_back(fold.finish(nearest));
  }
  return out;
}

}  // namespace holebench
