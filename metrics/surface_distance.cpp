#include "metrics/surface_distance.h"

#include "metrics/embree/triangle_scene.h"
#include "metrics/shared_faces.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

// A (sub)triangle of A with bounds on the mean of d(x, B) and of d(x, B)^2 over it.
struct Cell {
  std::array<Point, 3> corners;
  std::array<double, 3> corner_distance;
  std::array<int, 3> corner_face = {-1, -1, -1};  // faces of B nearest to the corners
  double area = 0.0;
  double mean_lo = 0.0, mean_hi = 0.0;      // bounds of the cell's mean of d
  double square_lo = 0.0, square_hi = 0.0;  // bounds of the cell's mean of d^2
  double key = 0.0;                         // its share of the errors: split the largest
  std::size_t order = 0;                    // creation order: deterministic ties
};

struct CellOrder {
  bool operator()(const Cell& x, const Cell& y) const {
    if (x.key != y.key)
      return x.key < y.key;
    return x.order > y.order;
  }
};

// The errors of the estimates from the sums of area-weighted bound widths.
struct Estimate {
  double mean = 0.0, mean_error = 0.0, rms = 0.0, rms_error = 0.0;
};

Estimate estimate(double area, double sum_mean, double sum_mean_width, double sum_square,
                  double sum_square_width) {
  Estimate e;
  e.mean = sum_mean / area;
  e.mean_error = 0.5 * sum_mean_width / area;
  // The mean square lies in [q - w, q + w]; the RMS in the square roots of that interval.
  const double q = sum_square / area, w = 0.5 * sum_square_width / area;
  const double hi = std::sqrt(std::max(0.0, q + w)), lo = std::sqrt(std::max(0.0, q - w));
  e.rms = 0.5 * (hi + lo);
  e.rms_error = 0.5 * (hi - lo);
  return e;
}

class MeanSearch {
 public:
  MeanSearch(const embree::TriangleScene& scene, const MeanDistanceOptions& options)
      : scene_(scene), options_(options) {}

  DirectedMeanDistance run(const Mesh& a, const KnownDistances& known) {
    VertexDistances computed;
    const VertexDistances* vertices = known.vertices;
    if (!vertices) {
      computed = vertex_distances(a, scene_, known.b_face_of_a);
      vertices = &computed;
      result_.queries += computed.queries;
    }
    std::vector<Cell> initial;
    initial.reserve(a.n_faces());
    for (auto f : a.faces()) {
      Cell cell;
      int k = 0;
      for (auto v : f.vertices()) {
        cell.corners[k] = a.point(v);
        cell.corner_distance[k] = vertices->distance[v.idx()];
        cell.corner_face[k] = vertices->nearest_face[v.idx()];
        ++k;
      }
      cell.area = triangle_area(cell.corners);
      if (!(cell.area > 0.0))
        continue;  // a degenerate triangle has no area to integrate
      total_area_ += cell.area;
      if (known.b_face_of_a && (*known.b_face_of_a)[f.idx()] >= 0)
        continue;  // lies on B: contributes zero, exactly
      initial.push_back(std::move(cell));
    }
    // The first cells' bounds in parallel (one query each, no shared state); queued below
    // in face order, so the result does not depend on the number of threads.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, initial.size(), 256),
                      [&](const auto& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i)
                          bound(initial[i]);
                      });
    if (total_area_ <= 0.0)
      return result_;
    // The RMS error is about the mean-square error / (2 RMS): the scale that weighs the
    // cells' mean-square widths against their mean widths when choosing what to split.
    double sum_square = 0.0;
    for (const Cell& cell : initial)
      sum_square += cell.area * 0.5 * (cell.square_lo + cell.square_hi);
    rms_scale_ = std::max(options_.error_bound, std::sqrt(sum_square / total_area_));
    // Queued all at once (one heap build, no copies): the same queue as pushing them in
    // face order, since the order is total.
    for (Cell& cell : initial)
      prepare(cell);
    queue_ = Queue(CellOrder{}, std::move(initial));
    while (!queue_.empty() && !within_bound()) {
      if (result_.queries >= options_.max_queries) {
        result_.converged = false;
        break;
      }
      Cell cell = queue_.top();
      queue_.pop();
      remove_sums(cell);
      split(cell);
    }
    // Final sums from the cells themselves (no drift from the running sums).
    sum_mean_ = sum_mean_width_ = sum_square_ = sum_square_width_ = 0.0;
    while (!queue_.empty()) {
      add_sums(queue_.top(), 1.0);
      queue_.pop();
    }
    const Estimate e =
        estimate(total_area_, sum_mean_, sum_mean_width_, sum_square_, sum_square_width_);
    result_.area = total_area_;
    result_.mean = e.mean;
    result_.mean_error = e.mean_error;
    result_.rms = e.rms;
    result_.rms_error = e.rms_error;
    result_.converged = result_.converged && e.mean_error <= options_.error_bound &&
                        e.rms_error <= options_.error_bound;
    return result_;
  }

 private:
  embree::ClosestPoint query(const Point& p, double bound) {
    ++result_.queries;
    return scene_.closest_point(p, bound);
  }

  bool within_bound() const {
    const Estimate e =
        estimate(total_area_, sum_mean_, sum_mean_width_, sum_square_, sum_square_width_);
    return e.mean_error <= options_.error_bound && e.rms_error <= options_.error_bound;
  }

  void add_sums(const Cell& cell, double sign) {
    sum_mean_ += sign * cell.area * 0.5 * (cell.mean_lo + cell.mean_hi);
    sum_mean_width_ += sign * cell.area * (cell.mean_hi - cell.mean_lo);
    sum_square_ += sign * cell.area * 0.5 * (cell.square_lo + cell.square_hi);
    sum_square_width_ += sign * cell.area * (cell.square_hi - cell.square_lo);
  }
  void remove_sums(const Cell& cell) { add_sums(cell, -1.0); }

  // Counts the cell's query of bound(), gives it its key and creation order and adds it to
  // the running sums.
  void prepare(Cell& cell) {
    ++result_.queries;  // the one closest-point query of bound()
    cell.key = cell.area * ((cell.mean_hi - cell.mean_lo) +
                            (cell.square_hi - cell.square_lo) / (2.0 * rms_scale_));
    cell.order = next_order_++;
    add_sums(cell, 1.0);
  }

  void enqueue(Cell cell) {
    prepare(cell);
    queue_.push(std::move(cell));
  }

  // The distance to one triangle of B at the cell's corners.
  std::array<double, 3> corner_distances_to(const std::array<Point, 3>& c, int face) const {
    const auto& t = scene_.triangle_of_face(face);
    std::array<double, 3> f;
    for (int i = 0; i < 3; ++i)
      f[i] = (embree::closest_point_on_triangle(c[i], t[0], t[1], t[2]) - c[i]).norm();
    return f;
  }

  // Bounds of d over the cell, pointwise (first order) and of its mean and mean square
  // (second order).
  void bound(Cell& cell) const {
    const auto& c = cell.corners;
    const auto& d = cell.corner_distance;
    const Point centroid = (c[0] + c[1] + c[2]) / 3.0;
    // Farthest any point of the cell is from a corner (its longest incident edge) or from
    // the centroid (its farthest corner).
    const std::array<double, 3> edge = {(c[1] - c[0]).norm(), (c[2] - c[1]).norm(),
                                        (c[0] - c[2]).norm()};
    const std::array<double, 3> corner_radius = {
        std::max(edge[0], edge[2]), std::max(edge[0], edge[1]), std::max(edge[1], edge[2])};
    double centroid_radius = 0.0;
    for (const Point& corner : c)
      centroid_radius = std::max(centroid_radius, (corner - centroid).norm());
    const auto nearest = scene_.closest_point(
        centroid, std::min({d[0] + (centroid - c[0]).norm(), d[1] + (centroid - c[1]).norm(),
                            d[2] + (centroid - c[2]).norm()}));

    // First order, pointwise: 1-Lipschitz from the centroid and the corners.
    double lo = std::max(0.0, nearest.distance - centroid_radius);
    double hi = nearest.distance + centroid_radius;
    for (int i = 0; i < 3; ++i) {
      lo = std::max(lo, d[i] - corner_radius[i]);
      hi = std::min(hi, d[i] + corner_radius[i]);
    }
    // The distance f_T to a single triangle T of B is convex and d <= f_T: max f_T over
    // the cell is at a corner, and the cell's mean of f_T (of f_T^2, also convex) is at
    // most the mean of its corner values. T: the triangles nearest to centroid and corners.
    double mean_hi = std::numeric_limits<double>::infinity();
    double square_hi = std::numeric_limits<double>::infinity();
    for (int face : {nearest.face, cell.corner_face[0], cell.corner_face[1], cell.corner_face[2]}) {
      if (face < 0)
        continue;
      const auto f = corner_distances_to(c, face);
      hi = std::min(hi, std::max({f[0], f[1], f[2]}));
      mean_hi = std::min(mean_hi, (f[0] + f[1] + f[2]) / 3.0);
      square_hi = std::min(square_hi, (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]) / 3.0);
    }
    // The exact minimum over the cell where the cell may touch B (there the distance has
    // a kink that no smooth bound follows): its distance to the triangles of B within
    // a + centroid_radius of the centroid, a = the smallest distance sampled on the cell
    // (the minimum is at most a, so farther triangles cannot hold it). Only where it can
    // matter: the gap w > bound / 4 and the minimum able to raise lo by more than that.
    const double sampled = std::min({d[0], d[1], d[2], nearest.distance});
    const double useful = 0.25 * options_.error_bound;
    if (0.5 * (hi - lo) > useful && sampled - lo > useful && lo < centroid_radius) {
      double minimum = sampled;
      for (int face : scene_.faces_within(centroid, sampled + centroid_radius))
        minimum = std::min(minimum, triangle_triangle_distance(c, scene_.triangle_of_face(face)));
      lo = std::max(lo, minimum);
    }
    hi = std::max(lo, hi);
    // Second order (semiconcavity): |x|^2 - d(x)^2 = max over y of B of (2 x.y - |y|^2) is
    // convex, so with barycentric weights l_i of x,
    //   d(x)^2 >= sum l_i d_i^2 - sum l_i |c_i - x|^2,
    // whose mean over the cell is mean(d_i^2) - V with V = sum |c_i - g|^2 / 4 (the
    // triangle's second moment about its centroid g). And sqrt(a - b) >= sqrt(a) - b /
    // sqrt(a) with sqrt(sum l_i d_i^2) >= sum l_i d_i >= min d_i gives
    //   mean of d >= mean(d_i) - V / min(d_i).
    double v = 0.0;
    for (const Point& corner : c)
      v += (corner - centroid).sqrnorm();
    v *= 0.25;
    const double square_lo = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / 3.0 - v;
    const double d_min = std::min({d[0], d[1], d[2]});
    const double mean_lo = d_min > 0.0 ? (d[0] + d[1] + d[2]) / 3.0 - v / d_min
                                       : -std::numeric_limits<double>::infinity();
    cell.mean_lo = std::max(lo, mean_lo);
    cell.mean_hi = std::min(hi, mean_hi);
    cell.square_lo = std::max(lo * lo, square_lo);
    cell.square_hi = std::min(hi * hi, square_hi);
    // Rounding may cross the bounds by an ulp: then they meet.
    if (cell.mean_lo > cell.mean_hi)
      cell.mean_lo = cell.mean_hi = 0.5 * (cell.mean_lo + cell.mean_hi);
    if (cell.square_lo > cell.square_hi)
      cell.square_lo = cell.square_hi = 0.5 * (cell.square_lo + cell.square_hi);
  }

  void split(const Cell& cell) {
    const auto& c = cell.corners;
    const auto& d = cell.corner_distance;
    const auto& f = cell.corner_face;
    const std::array<Point, 3> mid = {(c[0] + c[1]) * 0.5, (c[1] + c[2]) * 0.5,
                                      (c[2] + c[0]) * 0.5};
    std::array<double, 3> md;
    std::array<int, 3> mf;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const auto closest = query(mid[i], std::min(d[i], d[j]) + 0.5 * edge_length(c[i], c[j]));
      md[i] = closest.distance;
      mf[i] = closest.face;
    }
    const std::array<Cell, 4> children = {
        Cell{{c[0], mid[0], mid[2]}, {d[0], md[0], md[2]}, {f[0], mf[0], mf[2]}},
        Cell{{mid[0], c[1], mid[1]}, {md[0], d[1], md[1]}, {mf[0], f[1], mf[1]}},
        Cell{{mid[2], mid[1], c[2]}, {md[2], md[1], d[2]}, {mf[2], mf[1], f[2]}},
        Cell{{mid[0], mid[1], mid[2]}, {md[0], md[1], md[2]}, {mf[0], mf[1], mf[2]}}};
    for (Cell child : children) {
      child.area = triangle_area(child.corners);
      if (!(child.area > 0.0))
        continue;
      bound(child);
      enqueue(std::move(child));
    }
  }

  static double edge_length(const Point& p, const Point& q) { return (q - p).norm(); }

  const embree::TriangleScene& scene_;
  const MeanDistanceOptions& options_;
  DirectedMeanDistance result_;
  using Queue = std::priority_queue<Cell, std::vector<Cell>, CellOrder>;
  Queue queue_;
  std::size_t next_order_ = 0;
  double total_area_ = 0.0;
  double rms_scale_ = 0.0;
  double sum_mean_ = 0.0, sum_mean_width_ = 0.0, sum_square_ = 0.0, sum_square_width_ = 0.0;
};

}  // namespace

DirectedMeanDistance directed_mean_distance(const Mesh& a, const embree::TriangleScene& b_scene,
                                            const MeanDistanceOptions& options,
                                            const KnownDistances& known) {
  return MeanSearch(b_scene, options).run(a, known);
}

SurfaceDistance surface_distance(const Mesh& a, const embree::TriangleScene& a_scene, const Mesh& b,
                                 const embree::TriangleScene& b_scene,
                                 const SurfaceDistanceOptions& options) {
  // One first pass per direction, shared by the Hausdorff and the mean searches; faces the
  // two meshes share exactly are skipped by both.
  const SharedFaces shared = shared_faces(a, b);
  const VertexDistances a_vertices = vertex_distances(a, b_scene, &shared.b_face_of_a);
  const VertexDistances b_vertices = vertex_distances(b, a_scene, &shared.a_face_of_b);
  const KnownDistances a_known{&a_vertices, &shared.b_face_of_a};
  const KnownDistances b_known{&b_vertices, &shared.a_face_of_b};
  SurfaceDistance result;
  result.hausdorff.a_to_b = directed_hausdorff(a, b_scene, options.hausdorff, a_known);
  result.hausdorff.b_to_a = directed_hausdorff(b, a_scene, options.hausdorff, b_known);
  result.a_to_b = directed_mean_distance(a, b_scene, options.mean, a_known);
  result.b_to_a = directed_mean_distance(b, a_scene, options.mean, b_known);
  // The shared first pass counts once, with the Hausdorff search.
  result.hausdorff.a_to_b.queries += a_vertices.queries;
  result.hausdorff.b_to_a.queries += b_vertices.queries;
  return result;
}

}  // namespace holebench
