#include "metrics/surface_distance.h"

#include "core/distances.h"
#include "core/plane_fit.h"
#include "metrics/cell_queue.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/shared_faces.h"
#include "metrics/triangle_cell.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

namespace holebench {
namespace {

// The most triangles of B the mean search weighs for one cell's exact minimum (bound()).
constexpr std::size_t kMaxExactMinimumFaces = 256;

double triangle_area(const std::array<Point, 3>& c) {
  return 0.5 * OpenMesh::cross(c[1] - c[0], c[2] - c[0]).norm();
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

// Whether an edge of either triangle meets the other (then they meet).
bool edges_meet_triangles(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  for (int i = 0; i < 3; ++i) {
    if (segment_meets_triangle(a[i], a[(i + 1) % 3], b) ||
        segment_meets_triangle(b[i], b[(i + 1) % 3], a))
      return true;
  }
  return false;
}

// The distance between two triangles: 0 if they meet, else the smallest of the
// vertex-triangle and edge-edge distances.
double triangle_triangle_distance(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  if (edges_meet_triangles(a, b))
    return 0.0;
  // The smallest square, then one square root: the root is monotone and correctly rounded,
  // so this is the smallest of the distances, bit for bit.
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    best = std::min(best, (closest_point_on_triangle(a[i], b[0], b[1], b[2]) - a[i]).sqrnorm());
    best = std::min(best, (closest_point_on_triangle(b[i], a[0], a[1], a[2]) - b[i]).sqrnorm());
    for (int j = 0; j < 3; ++j)
      best = std::min(best,
                      segment_segment_squared_distance(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]));
  }
  return std::sqrt(best);
}

GrowingBox box_of(const std::array<Point, 3>& t) {
  GrowingBox box;
  for (const Point& p : t)
    box.add(p);
  return box;
}

// For a unit direction n, the affine l(x) = n.x - max over T's corners of n.v is at most
// dist(x, T): T lies in the half-space n.y <= max n.v.
struct HalfSpaceBound {
  Point normal;
  double offset = 0.0;
  double operator()(const Point& x) const { return OpenMesh::dot(normal, x) - offset; }
};
HalfSpaceBound half_space_bound(const Point& normal, const std::array<Point, 3>& t) {
  double offset = -std::numeric_limits<double>::infinity();
  for (const Point& v : t)
    offset = std::max(offset, OpenMesh::dot(normal, v));
  return {normal, offset};
}

// The mean over a triangle of a linear function with corner values v, and of its square.
double linear_mean(const std::array<double, 3>& v) {
  return (v[0] + v[1] + v[2]) / 3.0;
}
double linear_square_mean(const std::array<double, 3>& v) {
  return (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[0] * v[1] + v[1] * v[2] + v[2] * v[0]) / 6.0;
}

// The mean over a triangle of max(0, L)^power (power 1 or 2), L linear with corner values v.
// With one positive corner v0 (v1, v2 <= 0) the positive part lives on the sub-triangle at
// v0 cut where L = 0, a share v0^2 / ((v0 - v1)(v0 - v2)) of the area, on which L runs
// linearly from v0 to 0 and 0: its mean there is v0 / 3, of its square v0^2 / 6. Two
// positive corners: the whole minus the negative part, which has one.
double positive_part_mean(std::array<double, 3> v, int power) {
  std::sort(v.begin(), v.end(), std::greater<>());
  if (v[2] >= 0.0)
    return power == 1 ? linear_mean(v) : linear_square_mean(v);
  if (v[0] <= 0.0)
    return 0.0;
  if (v[1] <= 0.0) {
    const double share = v[0] * v[0] / ((v[0] - v[1]) * (v[0] - v[2]));
    return share * (power == 1 ? v[0] / 3.0 : v[0] * v[0] / 6.0);
  }
  const double negative = positive_part_mean({-v[2], -v[1], -v[0]}, power);
  return std::max(0.0, power == 1 ? linear_mean(v) + negative : linear_square_mean(v) - negative);
}

// The mean of |L| over a triangle, L linear with corner values v.
double absolute_mean(const std::array<double, 3>& v) {
  return positive_part_mean(v, 1) + positive_part_mean({-v[0], -v[1], -v[2]}, 1);
}

// The plane of a triangle (unit normal, a corner as its point); false for a degenerate one.
bool plane_of(const std::array<Point, 3>& t, Plane& plane) {
  const Point n = OpenMesh::cross(t[1] - t[0], t[2] - t[0]);
  const double length = n.norm();
  if (!(length > 0.0))
    return false;
  plane.point = t[0];
  plane.normal = n / length;
  return true;
}

// 2D polygons for the cover test: a convex polygon clipped by a triangle (Sutherland-Hodgman).
struct Point2 {
  double x = 0.0, y = 0.0;
};
using Polygon2 = std::vector<Point2>;

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double polygon_area(const Polygon2& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % p.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * std::abs(twice);
}

// The part of convex `subject` inside triangle t (either orientation).
Polygon2 clip_to_triangle(Polygon2 subject, std::array<Point2, 3> t) {
  if (cross2(t[0], t[1], t[2]) < 0.0)
    std::swap(t[1], t[2]);
  for (int e = 0; e < 3 && !subject.empty(); ++e) {
    const Point2 a = t[e], b = t[(e + 1) % 3];
    Polygon2 kept;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const Point2& p = subject[i];
      const Point2& q = subject[(i + 1) % subject.size()];
      const double sp = cross2(a, b, p), sq = cross2(a, b, q);
      if (sp >= 0.0)
        kept.push_back(p);
      if ((sp >= 0.0) != (sq >= 0.0)) {
        const double s = sp / (sp - sq);
        kept.push_back({p.x + s * (q.x - p.x), p.y + s * (q.y - p.y)});
      }
    }
    subject = std::move(kept);
  }
  return subject;
}

// What MeanSearch::bound() and tighten() give a cell: bounds on d(x, B) over it, and on its
// means of d and of d^2.
struct MeanBounds {
  double hi = 0.0;                          // pointwise: d <= hi on the cell
  double mean_lo = 0.0, mean_hi = 0.0;      // bounds of the cell's mean of d
  double square_lo = 0.0, square_hi = 0.0;  // bounds of the cell's mean of d^2
};

// A (sub)triangle of A with bounds on the mean of d(x, B) and of d(x, B)^2 over it. Its
// priority in the queue is its share of the errors: the largest is refined first.
struct Cell : TriangleCell, MeanBounds {
  Cell() = default;
  explicit Cell(const TriangleCell& cell) : TriangleCell(cell) {}
  // Bounds computed for the same cell elsewhere (a table, or another search's steps).
  void take_bounds(const MeanBounds& from) { static_cast<MeanBounds&>(*this) = from; }
  const MeanBounds& bounds() const { return *this; }
  double area = 0.0;
  bool planes_tried = false;  // the plane bounds (tighten()) are in
};

// The errors of the estimates from the sums of area-weighted bound widths.
struct Estimate {
  double mean = 0.0, mean_error = 0.0, rms = 0.0, rms_error = 0.0;
  double mean_lower() const { return std::max(0.0, mean - mean_error); }
  double rms_lower() const { return std::max(0.0, rms - rms_error); }
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

// The error bounds a search ran under: a cell's bounds and steps computed under them are the
// ones another search takes only when it runs under the same.
struct SearchErrorBounds {
  double error_bound = 0.0;
  double relative_error_bound = 0.0;
  static SearchErrorBounds of(const MeanDistanceOptions& options) {
    return {options.error_bound, options.relative_error_bound};
  }
  bool serve(const MeanDistanceOptions& options) const {
    return options.error_bound == error_bound &&
           options.relative_error_bound == relative_error_bound;
  }
};

// What MeanSearch::bound() gives a cell, with where it read B0.
struct CellBounds {
  MeanBounds bounds;
  GrowingBox reach;  // the balls of B0 the bounds read: valid where B is B0 in this box
};

}  // namespace

struct MeanCellBounds::Table {
  SearchErrorBounds error_bounds;
  std::unordered_map<CellKey, CellBounds, CellKeyHash> cells;
  // The first pass over A0's vertices: each vertex's point and answer, and whether the
  // answer came from a query (not from lying on a face shared with B0).
  std::vector<Point> vertex_points;
  VertexDistances vertices;
  std::vector<char> vertex_queried;
  // Whether a search with `options` bounds a cell as these were bounded.
  bool serves(const MeanDistanceOptions& options) const { return error_bounds.serve(options); }
};

struct MeanSearchSteps::Table {
  bool recorded = false;  // by a search with these error bounds:
  SearchErrorBounds error_bounds;
  // By cell (each a function of the cell's key and of B alone): its first bounds, its
  // bounds after tighten(), and its children (each bounded) after split().
  std::unordered_map<CellKey, MeanBounds, CellKeyHash> bounded;
  std::unordered_map<CellKey, MeanBounds, CellKeyHash> tightened;
  std::unordered_map<CellKey, std::vector<Cell>, CellKeyHash> children;
  bool serves(const MeanDistanceOptions& options) const {
    return recorded && error_bounds.serve(options);
  }
};

MeanSearchSteps::MeanSearchSteps() : table_(std::make_unique<Table>()) {}
MeanSearchSteps::~MeanSearchSteps() = default;
std::size_t MeanSearchSteps::size() const {
  return table_->bounded.size() + table_->tightened.size() + table_->children.size();
}

namespace {

class MeanSearch {
 public:
  MeanSearch(const embree::TriangleScene& scene, const MeanDistanceOptions& options)
      : scene_(scene), options_(options) {}

  // Keeps every cell's first bounds and every refinement step in `steps`, and takes the
  // steps of `replay` for the cells it has (null: none).
  void use_steps(MeanSearchSteps::Table* record, const MeanSearchSteps::Table* replay) {
    if (record) {
      record->recorded = true;
      record->error_bounds = SearchErrorBounds::of(options_);
      record_ = record;
    }
    if (replay && replay->serves(options_))
      replay_ = replay;
  }

  // The first bounds of `cells` (bound()), in parallel (one query each, no shared state),
  // taken from `first` where it holds the same cell and B is its B0 within the cell's reach.
  // Returns how many came from the replayed steps.
  std::size_t bound_each(std::vector<Cell>& cells, const FirstBounds* first) const {
    std::vector<char> done(cells.size(), 0);
    if (first && first->bounds && first->bounds->table().serves(options_)) {
      const auto& table = first->bounds->table().cells;
      const std::vector<int>* b0_face_of_b = first->change.b0_face_of_b;
      for (std::size_t i = 0; i < cells.size(); ++i) {
        TriangleCell as_b0 = cells[i];
        bool mapped = true;
        if (b0_face_of_b) {
          for (int& face : as_b0.corner_face) {
            if (face >= 0)
              face = (*b0_face_of_b)[face];
            mapped = mapped && face >= 0;
          }
        }
        if (!mapped)
          continue;
        const auto it = table.find(key_of(as_b0));
        if (it == table.end() || it->second.reach.meets(first->change.changed))
          continue;
        cells[i].take_bounds(it->second.bounds);
        done[i] = 1;
      }
    }
    std::size_t replayed = 0;
    if (replay_) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (done[i])
          continue;
        const auto it = replay_->bounded.find(key_of(cells[i]));
        if (it != replay_->bounded.end()) {
          cells[i].take_bounds(it->second);
          done[i] = 1;
          ++replayed;
        }
      }
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 256),
                      [&](const auto& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          if (!done[i])
                            bound(cells[i]);
                        }
                      });
    return replayed;
  }

  // bound() of each cell, with the box of the balls of B its bounds read (the corners'
  // included).
  void bound_each_with_reach(std::vector<Cell>& cells, std::vector<GrowingBox>& reach) const {
    reach.assign(cells.size(), GrowingBox());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 256),
                      [&](const auto& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          for (int k = 0; k < 3; ++k)
                            reach[i].add_ball(cells[i].corners[k], cells[i].corner_distance[k]);
                          bound(cells[i], &reach[i]);
                        }
                      });
  }

  DirectedMeanDistance run(const Mesh& a, const KnownDistances& known,
                           const FirstBounds* first_bounds) {
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
      Cell cell(face_cell(a, f, *vertices));
      cell.area = triangle_area(cell.corners);
      if (!(cell.area > 0.0))
        continue;  // a degenerate triangle has no area to integrate
      total_area_ += cell.area;
      if (known.b_face_of_a && (*known.b_face_of_a)[f.idx()] >= 0)
        continue;  // lies on B: contributes zero, exactly
      initial.push_back(std::move(cell));
    }
    // The first cells' bounds; queued below in face order, so the result does not depend
    // on the number of threads.
    result_.steps_taken += bound_each(initial, first_bounds);
    if (record_) {
      for (const Cell& cell : initial)
        record_->bounded.emplace(key_of(cell), cell.bounds());
    }
    if (total_area_ <= 0.0)
      return result_;
    // The RMS error is about the mean-square error / (2 RMS): the scale that weighs the
    // cells' mean-square widths against their mean widths when choosing what to split.
    double sum_square = 0.0;
    for (const Cell& cell : initial)
      sum_square += cell.area * 0.5 * (cell.square_lo + cell.square_hi);
    rms_scale_ = std::max(options_.error_bound, std::sqrt(sum_square / total_area_));
    // Queued all at once, in face order.
    for (Cell& cell : initial)
      prepare(cell);
    queue_.start(std::move(initial));
    // Refine the cell with the largest share of the errors (its plane bounds first, where
    // near enough, else its split) until the estimates are within their bounds.
    const bool bound_met = refine_largest_first(
        queue_, [this](const Cell&) { return within_bound(); },
        [this] {
          return result_.queries >= options_.max_queries ||
                 (result_.queries >= options_.query_budget && within_coarse_bound());
        },
        [this](Cell& cell) {
          remove_sums(cell);
          if (!cell.planes_tried && near_enough_to_tighten(cell)) {
            tighten_or_replay(cell);
            enqueue(std::move(cell));
          } else {
            split_or_replay(cell);
          }
        });
    if (!bound_met)
      result_.converged = false;
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
    // Widened by a relative 1e-12 for the rounding of the sums and closed forms.
    const double rounding = 1e-12;
    result_.mean_lower = e.mean_lower() * (1.0 - rounding);
    result_.mean_upper = (e.mean + e.mean_error) * (1.0 + rounding);
    result_.rms = e.rms;
    result_.rms_error = e.rms_error;
    result_.rms_lower = e.rms_lower() * (1.0 - rounding);
    result_.rms_upper = (e.rms + e.rms_error) * (1.0 + rounding);
    result_.converged = result_.converged && within_bound(e);
    return result_;
  }

 private:
  embree::ClosestPoint query(const Point& p, double bound) {
    ++result_.queries;
    return scene_.closest_point(p, bound);
  }

  bool within_bound() const {
    return within_bound(
        estimate(total_area_, sum_mean_, sum_mean_width_, sum_square_, sum_square_width_));
  }
  bool within_coarse_bound() const {
    const Estimate e =
        estimate(total_area_, sum_mean_, sum_mean_width_, sum_square_, sum_square_width_);
    return e.mean_error <= options_.coarse_error_bound &&
           e.rms_error <= options_.coarse_error_bound;
  }
  // Each half-width within max(relative bound x its lower end, absolute bound).
  bool within_bound(const Estimate& e) const {
    const double rel = options_.relative_error_bound;
    return e.mean_error <= std::max(rel * e.mean_lower(), options_.error_bound) &&
           e.rms_error <= std::max(rel * e.rms_lower(), options_.error_bound);
  }

  void add_sums(const Cell& cell, double sign) {
    sum_mean_ += sign * cell.area * 0.5 * (cell.mean_lo + cell.mean_hi);
    sum_mean_width_ += sign * cell.area * (cell.mean_hi - cell.mean_lo);
    sum_square_ += sign * cell.area * 0.5 * (cell.square_lo + cell.square_hi);
    sum_square_width_ += sign * cell.area * (cell.square_hi - cell.square_lo);
  }
  void remove_sums(const Cell& cell) { add_sums(cell, -1.0); }

  // Counts the cell's query of bound(), gives it its priority (its share of the errors)
  // and adds it to the running sums.
  void prepare(Cell& cell) {
    ++result_.queries;  // the one closest-point query of bound()
    cell.priority = cell.area * ((cell.mean_hi - cell.mean_lo) +
                                 (cell.square_hi - cell.square_lo) / (2.0 * rms_scale_));
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
      f[i] = (closest_point_on_triangle(c[i], t[0], t[1], t[2]) - c[i]).norm();
    return f;
  }

  // Bounds of d over the cell, pointwise (first order) and of its mean and mean square
  // (second order).
  // `reach` (optional): grows to hold every ball of B that the bounds' queries read (the
  // corners' distances come from the first pass, whose balls the caller adds).
  void bound(Cell& cell, GrowingBox* reach = nullptr) const {
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
    if (reach)
      reach->add_ball(centroid, nearest.distance);

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
    const std::array<int, 4> faces = {nearest.face, cell.corner_face[0], cell.corner_face[1],
                                      cell.corner_face[2]};
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const int face = faces[k];
      // Each triangle once: the nearest to the centroid and to the corners are mostly one.
      if (face < 0 || std::find(faces.begin(), faces.begin() + k, face) != faces.begin() + k)
        continue;
      const auto f = corner_distances_to(c, face);
      hi = std::min(hi, std::max({f[0], f[1], f[2]}));
      mean_hi = std::min(mean_hi, (f[0] + f[1] + f[2]) / 3.0);
      // f_T <= its linear interpolant (convex), both >= 0: f_T^2 <= the interpolant squared.
      square_hi = std::min(square_hi, linear_square_mean(f));
    }
    // The exact minimum over the cell where the cell may touch B (there the distance has
    // a kink that no smooth bound follows): its distance to the triangles of B within
    // a + centroid_radius of the centroid, a = the smallest distance sampled on the cell
    // (the minimum is at most a, so farther triangles cannot hold it). Only where it can
    // matter: the gap w > bound / 4 and the minimum able to raise lo by more than that.
    // And only where few triangles of B are that near (kMaxExactMinimumFaces): a large cell
    // over a finely tessellated B would weigh thousands; its children, smaller, do it
    // instead (leaving it out only keeps lo lower, so the bounds still hold).
    const double sampled = std::min({d[0], d[1], d[2], nearest.distance});
    const double useful =
        0.25 * std::max(options_.error_bound, options_.relative_error_bound * sampled);
    if (0.5 * (hi - lo) > useful && sampled - lo > useful && lo < centroid_radius &&
        sampled <= 4.0 * centroid_radius) {
      const auto near =
          scene_.faces_within(centroid, sampled + centroid_radius, kMaxExactMinimumFaces);
      if (reach)
        reach->add_ball(centroid, sampled + centroid_radius);
      if (near) {
        // A triangle whose box is farther from the cell's box than the minimum so far (with
        // a margin far above rounding) is farther than it: only the test that makes
        // triangle_triangle_distance answer 0 is run (it can, for nearly parallel edges,
        // where rounding makes an edge meet a triangle it misses), and the distances
        // are not computed. The minimum is the same number.
        const GrowingBox cell_box = box_of(c);
        const double margin = 1e-9 * cell_box.magnitude();
        double minimum = sampled;
        for (int face : *near) {
          if (minimum == 0.0)
            break;
          const auto& t = scene_.triangle_of_face(face);
          if (cell_box.distance_to(box_of(t)) > minimum + margin) {
            if (edges_meet_triangles(c, t))
              minimum = 0.0;
            continue;
          }
          minimum = std::min(minimum, triangle_triangle_distance(c, t));
        }
        lo = std::max(lo, minimum);
      }
    }
    hi = std::max(lo, hi);
    cell.hi = hi;
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

  // Lower bounds from the planes of the triangles of B that can hold a closest point of a
  // point x of the cell: for x in the cell, d(x) <= hi and |x - g| <= R (g the centroid, R
  // the farthest corner), so its closest point lies within hi + R of g. For each such
  // triangle T, d(x) = dist(x, T) >= |a_T(x)| with a_T the signed distance to T's plane.
  //  - One plane P (that of the triangle nearest to a corner) with every candidate within
  //    a slab |a_P| <= e: d >= |a_P| - e and d^2 >= a_P^2 - 2 e |a_P|, whose cell means are
  //    closed forms of the corner values of a_P. Exact (e = 0) where B is flat there.
  //  - Several planes (a sharp edge or a curved region of B): m(x) = min over T of s_T a_T(x),
  //    s_T the sign at g, is concave and m <= d, so the cell mean of d is at least the corner
  //    mean of m, and d^2 >= max(0, L)^2 with L the linear interpolant of m's corner values.
  // The plane bounds can make a cell exact where B is flat under it; they weigh every
  // triangle of B within hi + R of the cell's centroid (R its radius). Tried only where that
  // reach is within twice the longest edge of the triangle of B nearest to a corner (a ring
  // or two of B's triangles) and hi within 4 R; farther out they would weigh many triangles,
  // and the second-order bounds (error ~ R^2 / distance) do better per query.
  bool near_enough_to_tighten(const Cell& cell) const {
    if (cell.corner_face[0] < 0)
      return false;
    const auto& t = scene_.triangle_of_face(cell.corner_face[0]);
    const double edge =
        std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
    const double radius = cell_radius(cell);
    return cell.hi <= 4.0 * radius && cell.hi + radius <= 2.0 * edge;
  }

  static double cell_radius(const Cell& cell) {
    const auto& c = cell.corners;
    const Point g = (c[0] + c[1] + c[2]) / 3.0;
    double radius = 0.0;
    for (const Point& corner : c)
      radius = std::max(radius, (corner - g).norm());
    return radius;
  }

  void tighten(Cell& cell) {
    cell.planes_tried = true;  // enqueue() counts the candidates' search as one query
    const auto& c = cell.corners;
    const Point g = (c[0] + c[1] + c[2]) / 3.0;
    const double radius = cell_radius(cell);
    const std::vector<int> candidates = scene_.faces_within(g, cell.hi + radius);
    if (candidates.empty())
      return;
    Plane reference;
    bool has_reference = false;
    for (int face :
         {cell.corner_face[0], cell.corner_face[1], cell.corner_face[2], candidates.front()}) {
      if (face >= 0 && std::binary_search(candidates.begin(), candidates.end(), face) &&
          plane_of(scene_.triangle_of_face(face), reference)) {
        has_reference = true;
        break;
      }
    }
    double slab = 0.0;
    bool every_plane = true;
    std::array<double, 3> m = {std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity()};
    for (int face : candidates) {
      const auto& t = scene_.triangle_of_face(face);
      if (has_reference) {
        for (const Point& p : t)
          slab = std::max(slab, std::abs(reference.signed_distance(p)));
      }
      // Two half-spaces that hold T: the side of its plane away from the centroid, and the
      // one through T's point nearest to the centroid facing it (the tangent of dist(., T)
      // at the centroid); the one higher on the cell's corners serves.
      std::array<double, 3> best = {-std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity()};
      const auto offer = [&](const Point& normal) {
        const HalfSpaceBound l = half_space_bound(normal, t);
        const std::array<double, 3> v = {l(c[0]), l(c[1]), l(c[2])};
        if (v[0] + v[1] + v[2] > best[0] + best[1] + best[2])
          best = v;
      };
      Plane plane;
      if (plane_of(t, plane))
        offer(plane.signed_distance(g) < 0.0 ? -plane.normal : plane.normal);
      const Point towards = g - closest_point_on_triangle(g, t[0], t[1], t[2]);
      if (towards.norm() > 0.0)
        offer(towards / towards.norm());
      if (!std::isfinite(best[0])) {
        every_plane = false;
        continue;
      }
      for (int i = 0; i < 3; ++i)
        m[i] = std::min(m[i], best[i]);
    }
    double mean_lo = 0.0, square_lo = 0.0;
    std::array<double, 3> a = {0.0, 0.0, 0.0};  // a_P at the corners
    double mean_abs = 0.0;                      // the cell's mean of |a_P|
    if (has_reference) {
      a = {reference.signed_distance(c[0]), reference.signed_distance(c[1]),
           reference.signed_distance(c[2])};
      mean_abs = absolute_mean(a);
      mean_lo = std::max(mean_lo, mean_abs - slab);
      square_lo = std::max(square_lo, linear_square_mean(a) - 2.0 * slab * mean_abs);
    }
    if (every_plane) {
      mean_lo = std::max(mean_lo, linear_mean(m));
      square_lo = std::max(square_lo, positive_part_mean(m, 2));
    }
    cell.mean_lo = std::max(cell.mean_lo, mean_lo);
    cell.square_lo = std::max(cell.square_lo, square_lo);
    if (has_reference && slab <= 1e-6 * options_.error_bound &&
        covered_by(c, reference, candidates)) {
      // Every point x of the cell lies above a point y of B within the slab: d(x) <= |x - y|
      // <= |a_P(x)| + e, so the means are within e of the closed forms (exact where e = 0).
      // (+ what an uncovered sliver of at most 2e-9 of the cell could add, at most hi there.)
      cell.mean_hi = std::min(cell.mean_hi, mean_abs + slab + 2e-9 * cell.hi);
      cell.square_hi = std::min(cell.square_hi, linear_square_mean(a) + 2.0 * slab * mean_abs +
                                                    slab * slab + 2e-9 * cell.hi * cell.hi);
    }
    // Rounding may cross the bounds by an ulp: then they meet.
    if (cell.mean_lo > cell.mean_hi)
      cell.mean_lo = cell.mean_hi = 0.5 * (cell.mean_lo + cell.mean_hi);
    if (cell.square_lo > cell.square_hi)
      cell.square_lo = cell.square_hi = 0.5 * (cell.square_lo + cell.square_hi);
  }

  // Whether the cell's projection onto P is covered by the candidates' projections: the
  // area of the projected cell equals the sum of its overlaps with each candidate. The
  // triangles of a mesh do not overlap, so the sum counts each covered point once; a sum
  // larger than the area (overlapping candidates) is not taken as covered.
  bool covered_by(const std::array<Point, 3>& c, const Plane& plane,
                  const std::vector<int>& candidates) const {
    const Point& n = plane.normal;
    const Point u = (std::abs(n[0]) < 0.6 ? OpenMesh::cross(n, Point(1.0, 0.0, 0.0))
                                          : OpenMesh::cross(n, Point(0.0, 1.0, 0.0)))
                        .normalized();
    const Point v = OpenMesh::cross(n, u);
    const auto to_plane = [&](const Point& p) {
      const Point d = p - plane.point;
      return Point2{OpenMesh::dot(d, u), OpenMesh::dot(d, v)};
    };
    const Polygon2 cell = {to_plane(c[0]), to_plane(c[1]), to_plane(c[2])};
    const double area = polygon_area(cell);
    if (!(area > 0.0))
      return false;
    double covered = 0.0;
    for (int face : candidates) {
      const auto& t = scene_.triangle_of_face(face);
      covered +=
          polygon_area(clip_to_triangle(cell, {to_plane(t[0]), to_plane(t[1]), to_plane(t[2])}));
    }
    return covered >= area * (1.0 - 1e-9) && covered <= area * (1.0 + 1e-9);
  }

  // tighten(), or its recorded outcome for the same cell: the same bounds.
  void tighten_or_replay(Cell& cell) {
    if (!replay_ && !record_) {
      tighten(cell);
      return;
    }
    const CellKey key = key_of(cell);
    if (replay_) {
      const auto it = replay_->tightened.find(key);
      if (it != replay_->tightened.end()) {
        cell.take_bounds(it->second);
        cell.planes_tried = true;
        ++result_.steps_taken;
        return;
      }
    }
    tighten(cell);
    if (record_)
      record_->tightened.emplace(key, cell.bounds());
  }

  // split(), or its recorded children for the same cell: the same children, found by the
  // same three midpoint queries (counted as made).
  void split_or_replay(const Cell& cell) {
    if (!replay_ && !record_) {
      split(cell, nullptr);
      return;
    }
    const CellKey key = key_of(cell);
    if (replay_) {
      const auto it = replay_->children.find(key);
      if (it != replay_->children.end()) {
        result_.queries += 3;
        ++result_.steps_taken;
        for (const Cell& child : it->second)
          enqueue(child);
        return;
      }
    }
    std::vector<Cell> children;
    split(cell, record_ ? &children : nullptr);
    if (record_)
      record_->children.emplace(key, std::move(children));
  }

  // The midpoints queried first, then each child with area bounded and queued in turn (and
  // kept in `children` when given).
  void split(const Cell& cell, std::vector<Cell>* children) {
    const auto query_midpoint = [this](const Point& p, double bound) { return query(p, bound); };
    for (const TriangleCell& piece : split_at_midpoints(cell, query_midpoint)) {
      Cell child(piece);
      child.area = triangle_area(child.corners);
      if (!(child.area > 0.0))
        continue;
      bound(child);
      if (children)
        children->push_back(child);
      enqueue(std::move(child));
    }
  }

  const embree::TriangleScene& scene_;
  const MeanDistanceOptions& options_;
  MeanSearchSteps::Table* record_ = nullptr;        // keeps the bounds and steps
  const MeanSearchSteps::Table* replay_ = nullptr;  // takes the recorded ones
  DirectedMeanDistance result_;
  CellQueue<Cell> queue_;
  double total_area_ = 0.0;
  double rms_scale_ = 0.0;
  double sum_mean_ = 0.0, sum_mean_width_ = 0.0, sum_square_ = 0.0, sum_square_width_ = 0.0;
};

}  // namespace

DirectedMeanDistance directed_mean_distance(const Mesh& a, const embree::TriangleScene& b_scene,
                                            const MeanDistanceOptions& options,
                                            const KnownDistances& known,
                                            const FirstBounds* first_bounds,
                                            MeanSearchSteps* record) {
  MeanSearch search(b_scene, options);
  search.use_steps(record ? &record->table() : nullptr,
                   first_bounds && first_bounds->steps ? &first_bounds->steps->table() : nullptr);
  return search.run(a, known, first_bounds);
}

MeanCellBounds::MeanCellBounds(const Mesh& a0, const embree::TriangleScene& b0_scene,
                               const FirstPass& first_pass, const MeanDistanceOptions& options)
    : table_(std::make_unique<Table>()) {
  table_->error_bounds = SearchErrorBounds::of(options);
  // The cells as the search makes them: the same first pass over the vertices, the faces
  // lying on B0 left out (the search skips them).
  const std::vector<int>& b0_face_of_a0 = first_pass.b_face_of_a;
  table_->vertices = first_pass.vertices;
  const VertexDistances& vertices = table_->vertices;
  table_->vertex_queried.assign(a0.n_vertices(), 1);
  for (auto f : a0.faces()) {
    if (b0_face_of_a0[f.idx()] >= 0) {
      for (auto v : a0.fv_range(f))
        table_->vertex_queried[v.idx()] = 0;
    }
  }
  table_->vertex_points.reserve(a0.n_vertices());
  for (auto v : a0.vertices())
    table_->vertex_points.push_back(a0.point(v));
  std::vector<Cell> cells;
  cells.reserve(a0.n_faces());
  for (auto f : a0.faces()) {
    if (b0_face_of_a0[f.idx()] >= 0)
      continue;
    Cell cell(face_cell(a0, f, vertices));
    if (triangle_area(cell.corners) > 0.0)
      cells.push_back(std::move(cell));
  }
  std::vector<GrowingBox> reach;
  MeanSearch(b0_scene, options).bound_each_with_reach(cells, reach);
  table_->cells.reserve(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell& cell = cells[i];
    table_->cells.emplace(key_of(cell), CellBounds{cell.bounds(), reach[i]});
  }
}

MeanCellBounds::~MeanCellBounds() = default;

std::size_t MeanCellBounds::size() const {
  return table_->cells.size();
}

namespace {

// Each interval's ends ordered (rounding may cross them by an ulp: the upper end, which
// carries the clamps, is kept) and its value inside.
void settle(DistanceInterval& d) {
  d.lower = std::min(std::max(0.0, d.lower), d.upper);
  d.value = std::clamp(d.value, d.lower, d.upper);
}

}  // namespace

DistanceSummary distance_summary(const DirectedHausdorff& hausdorff,
                                 const DirectedMeanDistance& mean) {
  DistanceSummary s;
  s.hausdorff = {hausdorff.lower, hausdorff.lower, hausdorff.upper};
  s.rms = {mean.rms_lower, mean.rms, mean.rms_upper};
  s.mean = {mean.mean_lower, mean.mean, mean.mean_upper};
  settle(s.hausdorff);
  // True values: mean <= RMS (Jensen) <= Hausdorff (the largest distance).
  s.rms.upper = std::min(s.rms.upper, s.hausdorff.upper);
  s.rms.lower = std::max(s.rms.lower, s.mean.lower);
  settle(s.rms);
  s.mean.upper = std::min(s.mean.upper, s.rms.upper);
  settle(s.mean);
  s.mean.value = std::min(s.mean.value, s.rms.value);
  return s;
}

DistanceSummary max_of(const DistanceSummary& a, const DistanceSummary& b) {
  const auto larger = [](const DistanceInterval& x, const DistanceInterval& y) {
    return DistanceInterval{std::max(x.lower, y.lower), std::max(x.value, y.value),
                            std::max(x.upper, y.upper)};
  };
  return {larger(a.mean, b.mean), larger(a.rms, b.rms), larger(a.hausdorff, b.hausdorff)};
}

namespace {

// The first pass's answers that `first` holds for its A0's vertices (MeanCellBounds), for
// the vertices of A: a vertex of A at the index of an A0 vertex, with its point bit for
// bit, that A0's pass queried has A0's answer against B0. That is its answer against B too
// where B's and B0's faces within the answer's distance are the same triangles in the same
// order (SurfaceChange): the ball about the point (padded far above rounding) misses the
// changed box, and the nearest face of B0 is a face of B.
EarlierVertexAnswer earlier_vertex_answers(const Mesh& a, const FirstBounds* first) {
  if (!first || !first->bounds)
    return {};
  const bool b_is_b0 = first->change.b0_face_of_b == nullptr;
  const std::vector<int>* b_face_of_b0 = first->change.b_face_of_b0;
  if (!b_is_b0 && !b_face_of_b0)
    return {};
  const MeanCellBounds::Table& table = first->bounds->table();
  const GrowingBox changed = first->change.changed;
  return [&a, &table, b_face_of_b0, b_is_b0, changed](int vertex, double& distance, int& face) {
    const std::size_t i = static_cast<std::size_t>(vertex);
    if (i >= table.vertex_points.size() || !table.vertex_queried[i] ||
        a.point(VertexHandle(vertex)) != table.vertex_points[i])
      return false;
    const double d = table.vertices.distance[i];
    int answer = table.vertices.nearest_face[i];
    if (!b_is_b0) {
      const Point& p = table.vertex_points[i];
      GrowingBox ball;
      ball.add_ball(p, d + 1e-9 * (d + std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2])));
      if (answer < 0 || static_cast<std::size_t>(answer) >= b_face_of_b0->size() ||
          (*b_face_of_b0)[answer] < 0 || ball.meets(changed))
        return false;
      answer = (*b_face_of_b0)[answer];
    }
    distance = d;
    face = answer;
    return true;
  };
}

// The Hausdorff search's first bounds that `first` holds, where its B is the search's.
const HausdorffCellBounds* hausdorff_first(const FirstBounds* first) {
  return first && !first->change.b0_face_of_b ? first->hausdorff : nullptr;
}

}  // namespace

SurfaceDistance surface_distance(const Mesh& a, const embree::TriangleScene& a_scene, const Mesh& b,
                                 const embree::TriangleScene& b_scene,
                                 const SurfaceDistanceOptions& options,
                                 const FirstBounds* a_first_bounds,
                                 const FirstBounds* b_first_bounds) {
  // One first pass per direction, shared by the Hausdorff and the mean searches; faces the
  // two meshes share exactly are skipped by both.
  const SharedFaces shared = shared_faces(a, b);
  const VertexDistances a_vertices =
      vertex_distances(a, b_scene, &shared.b_face_of_a, earlier_vertex_answers(a, a_first_bounds));
  const VertexDistances b_vertices =
      vertex_distances(b, a_scene, &shared.a_face_of_b, earlier_vertex_answers(b, b_first_bounds));
  const KnownDistances a_known{&a_vertices, &shared.b_face_of_a};
  const KnownDistances b_known{&b_vertices, &shared.a_face_of_b};
  SurfaceDistance result;
  result.hausdorff.a_to_b =
      directed_hausdorff(a, b_scene, options.hausdorff, a_known, hausdorff_first(a_first_bounds));
  result.hausdorff.b_to_a =
      directed_hausdorff(b, a_scene, options.hausdorff, b_known, hausdorff_first(b_first_bounds));
  result.a_to_b = directed_mean_distance(a, b_scene, options.mean, a_known, a_first_bounds);
  result.b_to_a = directed_mean_distance(b, a_scene, options.mean, b_known, b_first_bounds);
  // The shared first pass counts once, with the Hausdorff search.
  result.hausdorff.a_to_b.queries += a_vertices.queries;
  result.hausdorff.b_to_a.queries += b_vertices.queries;
  return result;
}

}  // namespace holebench
