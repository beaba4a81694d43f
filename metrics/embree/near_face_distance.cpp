#include "metrics/embree/near_face_distance.h"

#include "core/distances.h"
#include "core/geometry.h"
#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace holebench::embree {

namespace {

// A margin far above the rounding of distances near p (about 1e-16 of the coordinates' and
// the distances' size), so that neither the stopping rule nor the check ever leaves out a
// triangle whose computed distance could be the smallest.
double margin_at(const Point& p, double distance) {
  return 1e-9 * (std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]) + distance);
}

}  // namespace

NearFaceDistance::NearFaceDistance(const Mesh& mesh, const TriangleScene& scene,
                                   const NearFaceDistanceOptions& options)
    : mesh_(mesh), scene_(scene), options_(options) {}

void NearFaceDistance::make(FaceHandle f, FaceCandidates& face) const {
  face.made = true;
  const std::array<Point, 3> corners = face_corners(mesh_, f);
  face.centre = (corners[0] + corners[1] + corners[2]) / 3.0;
  double face_radius = 0.0;
  for (const Point& c : corners)
    face_radius = std::max(face_radius, (c - face.centre).norm());
  // A point p of the face has d(p) <= d(g) + R, and its nearest triangle lies within
  // |p - g| + d(p) <= d(g) + 2 R of g.
  const double centre_distance = scene_.closest_point(face.centre).distance;
  if (!std::isfinite(centre_distance))
    return;
  face.radius = centre_distance + 2.0 * face_radius;
  // The candidates' corners lie within 3 R + d(g) of g: the scale of their rounding.
  face.margin = margin_at(face.centre, 3.0 * face.radius);
  face.radius += face.margin;
  const auto near = scene_.faces_within(face.centre, face.radius, options_.max_candidates);
  if (!near)
    return;
  face.candidates.reserve(near->size());
  for (int index : *near) {
    const auto& t = scene_.triangle_of_face(index);
    const Point q = closest_point_on_triangle(face.centre, t[0], t[1], t[2]);
    face.candidates.push_back({(q - face.centre).norm(), &t});
  }
  std::stable_sort(
      face.candidates.begin(), face.candidates.end(),
      [](const Candidate& a, const Candidate& b) { return a.from_centre < b.from_centre; });
  face.usable = !face.candidates.empty();
}

double NearFaceDistance::distance(FaceHandle f, const Point& p) {
  if (f.idx() < 0 || static_cast<std::size_t>(f.idx()) >= mesh_.n_faces())
    throw std::out_of_range("NearFaceDistance: face " + std::to_string(f.idx()) +
                            " is not a face of the mesh");
  FaceCandidates& face = faces_[f.idx()];
  if (!face.made)
    make(f, face);
  if (face.usable) {
    const double from_centre = (p - face.centre).norm();
    double best = std::numeric_limits<double>::infinity();
    for (const Candidate& candidate : face.candidates) {
      // dist(p, T) >= dist(g, T) - |p - g|: this one and every later one are farther.
      if (candidate.from_centre - from_centre > best + face.margin + margin_at(p, best))
        break;
      const auto& t = *candidate.triangle;
      best = std::min(best, (closest_point_on_triangle(p, t[0], t[1], t[2]) - p).norm());
    }
    // Every triangle within best of p (its nearest among them) is a candidate.
    if (from_centre + best + face.margin + margin_at(p, best) <= face.radius) {
      ++local_answers_;
      remember(p, best);
      return best;
    }
  }
  ++scene_answers_;
  // Bounded by the last point answered: the distance is 1-Lipschitz, and the points come
  // in scan order, so the last one is near; the bound lets the BVH skip far boxes.
  const double d = last_
                       ? scene_.closest_point(p, last_distance_ + (p - last_point_).norm()).distance
                       : scene_.closest_point(p).distance;
  remember(p, d);
  return d;
}

}  // namespace holebench::embree
