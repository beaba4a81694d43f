#include "metrics/embree/arrow_visibility.h"

#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace holebench::embree {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Whether each sample faces P and is not occluded by the holed model (independent of the
// viewing direction), and the unit vector from P to it.
struct SampleView {
  std::vector<char> candidate;
  std::vector<Point> from_camera;
};

SampleView view_from(const Point& position, const SurfaceSamples& missing,
                     const TriangleScene& holed_scene, double tolerance) {
  SampleView view;
  const std::size_t n = missing.points.size();
  view.candidate.assign(n, 0);
  view.from_camera.assign(n, Point(0, 0, 0));
  for (std::size_t i = 0; i < n; ++i) {
    const Point to_camera = position - missing.points[i];
    const double distance = to_camera.norm();
    if (!(distance > 2.0 * tolerance))
      continue;
    const Point u = to_camera / distance;
    view.from_camera[i] = -u;
    if (!(OpenMesh::dot(missing.normals[i], u) > 0.0))
      continue;
    view.candidate[i] =
        !holed_scene.occluded(missing.points[i], u, tolerance, distance - tolerance);
  }
  return view;
}

double fraction_in_cone(const SampleView& view, const SurfaceSamples& missing,
                        const Point& direction, double cos_half_angle, double total) {
  double seen = 0.0;
  for (std::size_t i = 0; i < view.candidate.size(); ++i) {
    if (view.candidate[i] && OpenMesh::dot(view.from_camera[i], direction) >= cos_half_angle)
      seen += missing.weights[i];
  }
  return total > 0.0 ? seen / total : 0.0;
}

// The samples seen from P (SampleView's candidates), in sample order: their unit vectors
// from P and their weights. fraction_in_cone over them adds the same weights in the same
// order as over every sample, without walking the unseen ones for each direction.
struct SeenSamples {
  std::vector<Point> from_camera;
  std::vector<double> weights;
};

SeenSamples seen_samples(const SampleView& view, const SurfaceSamples& missing) {
  SeenSamples seen;
  for (std::size_t i = 0; i < view.candidate.size(); ++i) {
    if (view.candidate[i]) {
      seen.from_camera.push_back(view.from_camera[i]);
      seen.weights.push_back(missing.weights[i]);
    }
  }
  return seen;
}

double fraction_in_cone(const SeenSamples& seen, const Point& direction, double cos_half_angle,
                        double total) {
  double sum = 0.0;
  for (std::size_t i = 0; i < seen.weights.size(); ++i) {
    if (OpenMesh::dot(seen.from_camera[i], direction) >= cos_half_angle)
      sum += seen.weights[i];
  }
  return total > 0.0 ? sum / total : 0.0;
}

double total_weight(const SurfaceSamples& missing) {
  double total = 0.0;
  for (double w : missing.weights)
    total += w;
  return total;
}

// Ray-triangle intersection (Moller-Trumbore), double precision; t or infinity.
double ray_triangle(const Point& o, const Point& d, const Point& a, const Point& b,
                    const Point& c) {
  const Point e1 = b - a, e2 = c - a;
  const Point p = OpenMesh::cross(d, e2);
  const double det = OpenMesh::dot(e1, p);
  if (std::abs(det) < 1e-300)
    return std::numeric_limits<double>::infinity();
  const double inv = 1.0 / det;
  const Point s = o - a;
  const double u = OpenMesh::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0)
    return std::numeric_limits<double>::infinity();
  const Point q = OpenMesh::cross(s, e1);
  const double v = OpenMesh::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0)
    return std::numeric_limits<double>::infinity();
  const double t = OpenMesh::dot(e2, q) * inv;
  return t > 0.0 ? t : std::numeric_limits<double>::infinity();
}

}  // namespace

SurfaceSamples sample_faces(const Mesh& mesh, const std::vector<int>& faces,
                            const ArrowVisibilityOptions& options) {
  SurfaceSamples samples;
  for (int index : faces) {
    const FaceHandle f = mesh.face_handle(index);
    std::array<Point, 3> t;
    int k = 0;
    for (auto v : mesh.fv_range(f))
      t[k++] = mesh.point(v);
    Point normal = OpenMesh::cross(t[1] - t[0], t[2] - t[0]);
    const double area = 0.5 * normal.norm();
    if (!(area > 0.0))
      continue;
    normal /= normal.norm();
    const double longest =
        std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
    const int m = std::clamp(static_cast<int>(std::ceil(longest / options.sample_spacing)), 1,
                             options.max_subdivision);
    // The m^2 sub-triangles of the regular split: centroids in barycentric coordinates.
    const double weight = area / (static_cast<double>(m) * m);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m - i; ++j) {
        // upward sub-triangle (i, j), (i+1, j), (i, j+1)
        const double a = (3.0 * i + 1.0) / (3.0 * m), b = (3.0 * j + 1.0) / (3.0 * m);
        samples.points.push_back(t[0] + (t[1] - t[0]) * a + (t[2] - t[0]) * b);
        if (i + j + 1 < m) {
          // downward sub-triangle (i+1, j), (i, j+1), (i+1, j+1)
          const double a2 = (3.0 * i + 2.0) / (3.0 * m), b2 = (3.0 * j + 2.0) / (3.0 * m);
          samples.points.push_back(t[0] + (t[1] - t[0]) * a2 + (t[2] - t[0]) * b2);
        }
      }
    }
    while (samples.normals.size() < samples.points.size()) {
      samples.normals.push_back(normal);
      samples.weights.push_back(weight);
      samples.faces.push_back(index);
    }
  }
  return samples;
}

bool is_inside(const Point& p, const TriangleScene& scene, double surface_tolerance) {
  static const std::array<Point, 3> directions = {Point(0.5773, 0.5774, 0.5775),
                                                  Point(-0.6123, 0.3251, -0.7206),
                                                  Point(0.2113, -0.9001, 0.3811)};
  int inside_votes = 0;
  for (const Point& d : directions) {
    int crossings = 0;
    double t_near = 0.0;
    for (int guard = 0; guard < 10000; ++guard) {
      const RayHit hit = scene.intersect(p, d, t_near);
      if (!hit.hit)
        break;
      ++crossings;
      t_near = hit.distance + surface_tolerance;
    }
    inside_votes += crossings % 2;
  }
  return inside_votes >= 2;
}

double visible_fraction(const Point& position, const Point& direction,
                        const SurfaceSamples& missing, const TriangleScene& holed_scene,
                        const ArrowVisibilityOptions& options) {
  const SampleView view = view_from(position, missing, holed_scene, options.surface_tolerance);
  const double cos_half = std::cos(0.5 * options.field_of_view_degrees * kPi / 180.0);
  return fraction_in_cone(view, missing, direction / direction.norm(), cos_half,
                          total_weight(missing));
}

ArrowQuality arrow_quality(const GuidanceArrow& arrow, const SurfaceSamples& missing,
                           const TriangleScene& complete_scene, const TriangleScene& holed_scene,
                           const ArrowVisibilityOptions& options) {
  ArrowQuality quality;
  const Point& p = arrow.position;
  const Point r = arrow.direction / arrow.direction.norm();
  const double tolerance = options.surface_tolerance;
  quality.position_outside = !is_inside(p, complete_scene, tolerance);

  // The shaft's end: where the ray meets the missing surface, else the projection of its
  // area centroid.
  double t_end = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < missing.points.size(); ++i) {
    if (i > 0 && missing.faces[i] == missing.faces[i - 1])
      continue;
    const auto& t = complete_scene.triangle_of_face(missing.faces[i]);
    t_end = std::min(t_end, ray_triangle(p, r, t[0], t[1], t[2]));
  }
  if (std::isinf(t_end)) {
    Point centroid(0, 0, 0);
    const double total = total_weight(missing);
    for (std::size_t i = 0; i < missing.points.size(); ++i)
      centroid += missing.points[i] * (missing.weights[i] / total);
    t_end = std::max(0.0, OpenMesh::dot(centroid - p, r));
  }
  quality.shaft_length = t_end;
  // The shaft ends on the model: Embree's single-precision ray parameter puts the hit there
  // up to about 1e-7 of the coordinates' size (a box's face 2 away was hit at 1.99999988,
  // which is float(2 - 1e-7)), so the end's margin holds that rounding as well.
  const double end_margin = tolerance + single_precision_pad(coordinate_sum(p), t_end);
  quality.shaft_free =
      t_end <= 2.0 * tolerance || !complete_scene.occluded(p, r, 0.0, t_end - end_margin);

  const SampleView view = view_from(p, missing, holed_scene, tolerance);
  const double cos_half = std::cos(0.5 * options.field_of_view_degrees * kPi / 180.0);
  const double total = total_weight(missing);
  const SeenSamples seen = seen_samples(view, missing);
  quality.visible_fraction = fraction_in_cone(seen, r, cos_half, total);

  // Candidates: r first, then a Fibonacci sphere.
  std::vector<Point> candidates = {r};
  const int n = std::max(1, options.search_directions);
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    candidates.emplace_back(radius * std::cos(golden * i), radius * std::sin(golden * i), z);
  }
  std::vector<double> fractions;
  fractions.reserve(candidates.size());
  double best = 0.0;
  for (const Point& u : candidates) {
    fractions.push_back(fraction_in_cone(seen, u, cos_half, total));
    best = std::max(best, fractions.back());
  }
  quality.best_visible_fraction = best;
  double nearest = 180.0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (fractions[i] < best)
      continue;
    const double c = std::clamp(OpenMesh::dot(candidates[i], r), -1.0, 1.0);
    nearest = std::min(nearest, std::acos(c) * 180.0 / kPi);
  }
  quality.direction_error_deg = nearest;
  return quality;
}

}  // namespace holebench::embree
