#include "metrics/surface_distance.h"

#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

namespace holebench {
namespace {

double triangle_area(const std::array<Point, 3>& c) {
  return 0.5 * OpenMesh::cross(c[1] - c[0], c[2] - c[0]).norm();
}

double segment_segment_distance(const Point& p1, const Point& q1, const Point& p2,
                                const Point& q2) {
  // Ericson, Real-Time Collision Detection, 5.1.9.
  using OpenMesh::dot;
  const Point d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0 && e <= 0.0)
    return r.norm();
  if (a <= 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e <= 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2);
      const double denominator = a * e - b * b;
      s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return ((p1 + d1 * s) - (p2 + d2 * t)).norm();
}

// Whether segment [p, q] meets triangle t (Moller-Trumbore with t in [0, 1]).
bool segment_meets_triangle(const Point& p, const Point& q, const std::array<Point, 3>& t) {
  const Point d = q - p;
  const Point e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Point h = OpenMesh::cross(d, e2);
  const double det = OpenMesh::dot(e1, h);
  if (det == 0.0)
    return false;  // parallel: coplanar contact is found by the edge distances
  const double inv = 1.0 / det;
  const Point s = p - t[0];
  const double u = OpenMesh::dot(s, h) * inv;
  if (u < 0.0 || u > 1.0)
    return false;
  const Point k = OpenMesh::cross(s, e1);
  const double v = OpenMesh::dot(d, k) * inv;
  if (v < 0.0 || u + v > 1.0)
    return false;
  const double param = OpenMesh::dot(e2, k) * inv;
  return param >= 0.0 && param <= 1.0;
}

// The distance between two triangles: 0 if they meet, else the smallest of the
// vertex-triangle and edge-edge distances.
double triangle_triangle_distance(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  for (int i = 0; i < 3; ++i) {
    if (segment_meets_triangle(a[i], a[(i + 1) % 3], b) ||
        segment_meets_triangle(b[i], b[(i + 1) % 3], a))
      return 0.0;
  }
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    best =
        std::min(best, (embree::closest_point_on_triangle(a[i], b[0], b[1], b[2]) - a[i]).norm());
    best =
        std::min(best, (embree::closest_point_on_triangle(b[i], a[0], a[1], a[2]) - b[i]).norm());
    for (int j = 0; j < 3; ++j)
      best = std::min(best, segment_segment_distance(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]));
  }
  return best;
}

struct Cell {
  std::array<Point, 3> corners;
  std::array<double, 3> corner_distance;
  double area = 0.0;
  double lo = 0.0;
  double hi = 0.0;
  double key = 0.0;       // area * w^2
  std::size_t order = 0;  // creation order: deterministic ties
};

struct CellOrder {
  bool operator()(const Cell& x, const Cell& y) const {
    if (x.key != y.key)
      return x.key < y.key;
    return x.order > y.order;
  }
};

class MeanSearch {
 public:
  MeanSearch(const embree::TriangleScene& scene, const MeanDistanceOptions& options)
      : scene_(scene), options_(options) {}

  DirectedMeanDistance run(const Mesh& a) {
    std::vector<double> vertex_distance(a.n_vertices(), 0.0);
    for (auto v : a.vertices())
      vertex_distance[v.idx()] = query(a.point(v)).distance;
    for (auto f : a.faces()) {
      Cell cell;
      int k = 0;
      for (auto v : f.vertices()) {
        cell.corners[k] = a.point(v);
        cell.corner_distance[k] = vertex_distance[v.idx()];
        ++k;
      }
      push(std::move(cell));
    }
    if (total_area_ <= 0.0)
      return result_;
    const double target = options_.error_bound * options_.error_bound * total_area_;
    while (!queue_.empty() && sum_key_ > target) {
      if (queue_.top().key <= 0.0)
        break;
      if (result_.queries >= options_.max_queries) {
        result_.converged = false;
        break;
      }
      Cell cell = queue_.top();
      queue_.pop();
      sum_key_ -= cell.key;
      split(cell);
    }
    // Final sums from the cells themselves (no drift from the running sum).
    double sum_mid = 0.0, sum_mid2 = 0.0, sum_w = 0.0, sum_w2 = 0.0;
    while (!queue_.empty()) {
      const Cell& cell = queue_.top();
      const double mid = 0.5 * (cell.hi + cell.lo);
      const double w = 0.5 * (cell.hi - cell.lo);
      sum_mid += cell.area * mid;
      sum_mid2 += cell.area * mid * mid;
      sum_w += cell.area * w;
      sum_w2 += cell.area * w * w;
      queue_.pop();
    }
    result_.area = total_area_;
    result_.mean = sum_mid / total_area_;
    result_.mean_error = sum_w / total_area_;
    result_.rms = std::sqrt(sum_mid2 / total_area_);
    result_.rms_error = std::sqrt(sum_w2 / total_area_);
    result_.converged = result_.converged && result_.rms_error <= options_.error_bound;
    return result_;
  }

 private:
  embree::ClosestPoint query(const Point& p) {
    ++result_.queries;
    return scene_.closest_point(p);
  }

  void push(Cell cell) {
    const auto& c = cell.corners;
    cell.area = triangle_area(c);
    if (!(cell.area > 0.0))
      return;  // a degenerate triangle has no area to integrate
    const Point centroid = (c[0] + c[1] + c[2]) / 3.0;
    const auto nearest = query(centroid);
    // Farthest any point of the cell is from a corner (its longest incident edge) or from
    // the centroid (its farthest corner).
    const std::array<double, 3> edge = {(c[1] - c[0]).norm(), (c[2] - c[1]).norm(),
                                        (c[0] - c[2]).norm()};
    const std::array<double, 3> corner_radius = {
        std::max(edge[0], edge[2]), std::max(edge[0], edge[1]), std::max(edge[1], edge[2])};
    double centroid_radius = 0.0;
    for (const Point& corner : c)
      centroid_radius = std::max(centroid_radius, (corner - centroid).norm());
    double lo = std::max(0.0, nearest.distance - centroid_radius);
    double hi = nearest.distance + centroid_radius;
    for (int i = 0; i < 3; ++i) {
      lo = std::max(lo, cell.corner_distance[i] - corner_radius[i]);
      hi = std::min(hi, cell.corner_distance[i] + corner_radius[i]);
    }
    const auto& t = scene_.triangle_of_face(nearest.face);
    double bound_single = 0.0;
    for (const Point& corner : c) {
      const Point q = embree::closest_point_on_triangle(corner, t[0], t[1], t[2]);
      bound_single = std::max(bound_single, (q - corner).norm());
    }
    hi = std::min(hi, bound_single);
    // The exact minimum over the cell: its distance to the triangles of B that can hold
    // the closest point of some point of the cell (within hi + centroid_radius of the
    // centroid). Only where the cheap bound leaves a gap that matters: a cell with
    // w <= bound / 4 already contributes at most a sixteenth of the allowed error.
    if (0.5 * (hi - lo) > 0.25 * options_.error_bound) {
      double minimum = std::numeric_limits<double>::infinity();
      for (int face : scene_.faces_within(centroid, hi + centroid_radius))
        minimum = std::min(minimum, triangle_triangle_distance(c, scene_.triangle_of_face(face)));
      if (std::isfinite(minimum))
        lo = std::max(lo, minimum);
    }
    hi = std::max(lo, hi);
    cell.lo = lo;
    cell.hi = hi;
    const double w = 0.5 * (hi - lo);
    cell.key = cell.area * w * w;
    cell.order = next_order_++;
    if (!splitting_)
      total_area_ += cell.area;
    sum_key_ += cell.key;
    queue_.push(std::move(cell));
  }

  void split(const Cell& cell) {
    splitting_ = true;
    const auto& c = cell.corners;
    const std::array<Point, 3> mid = {(c[0] + c[1]) * 0.5, (c[1] + c[2]) * 0.5,
                                      (c[2] + c[0]) * 0.5};
    std::array<double, 3> md;
    for (int i = 0; i < 3; ++i)
      md[i] = query(mid[i]).distance;
    const auto& d = cell.corner_distance;
    push({{c[0], mid[0], mid[2]}, {d[0], md[0], md[2]}});
    push({{mid[0], c[1], mid[1]}, {md[0], d[1], md[1]}});
    push({{mid[2], mid[1], c[2]}, {md[2], md[1], d[2]}});
    push({{mid[0], mid[1], mid[2]}, {md[0], md[1], md[2]}});
  }

  const embree::TriangleScene& scene_;
  const MeanDistanceOptions& options_;
  DirectedMeanDistance result_;
  std::priority_queue<Cell, std::vector<Cell>, CellOrder> queue_;
  std::size_t next_order_ = 0;
  double total_area_ = 0.0;
  double sum_key_ = 0.0;
  bool splitting_ = false;
};

}  // namespace

DirectedMeanDistance directed_mean_distance(const Mesh& a, const embree::TriangleScene& b_scene,
                                            const MeanDistanceOptions& options) {
  return MeanSearch(b_scene, options).run(a);
}

SurfaceDistance surface_distance(const Mesh& a, const embree::TriangleScene& a_scene, const Mesh& b,
                                 const embree::TriangleScene& b_scene,
                                 const SurfaceDistanceOptions& options) {
  SurfaceDistance result;
  result.hausdorff.a_to_b = directed_hausdorff(a, b_scene, options.hausdorff);
  result.hausdorff.b_to_a = directed_hausdorff(b, a_scene, options.hausdorff);
  result.a_to_b = directed_mean_distance(a, b_scene, options.mean);
  result.b_to_a = directed_mean_distance(b, a_scene, options.mean);
  return result;
}

}  // namespace holebench
