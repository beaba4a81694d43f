#include "metrics/mean_bounds.h"

#include "core/distances.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/linear_means.h"
#include "metrics/triangle_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace holebench {
namespace {

// The most triangles of B the mean search weighs for one cell's exact minimum (bound()).
constexpr std::size_t kMaxExactMinimumFaces = 256;

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

}  // namespace

bool MeanCellBounder::meets_one_of(const std::array<Point, 3>& c, const std::array<int, 4>& faces,
                                   const Point& p, double radius) const {
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const int face = faces[k];
    // Each triangle once: the nearest to the centroid and to the corners are mostly one.
    if (face < 0 || std::find(faces.begin(), faces.begin() + k, face) != faces.begin() + k)
      continue;
    const auto& t = scene_.triangle_of_face(face);
    if (point_triangle_distance(p, t) <= radius && edges_meet_triangles(c, t))
      return true;
  }
  return false;
}

// Bounds of d over the cell, pointwise (first order) and of its mean and mean square
// (second order).
// `reach` (optional): grows to hold every ball of B that the bounds' queries read (the
// corners' distances come from the first pass, whose balls the caller adds).
void MeanCellBounder::bound(MeanCell& cell, GrowingBox* reach,
                            const embree::ClosestPoint* centroid_answer) const {
  const auto& c = cell.corners;
  const auto& d = cell.corner_distance;
  const Point centroid = cell_centroid(cell);
  // Farthest any point of the cell is from a corner (its longest incident edge) or from
  // the centroid (its farthest corner).
  const std::array<double, 3> edge = {(c[1] - c[0]).norm(), (c[2] - c[1]).norm(),
                                      (c[0] - c[2]).norm()};
  const std::array<double, 3> corner_radius = {
      std::max(edge[0], edge[2]), std::max(edge[0], edge[1]), std::max(edge[1], edge[2])};
  double centroid_radius = 0.0;
  for (const Point& corner : c)
    centroid_radius = std::max(centroid_radius, (corner - centroid).norm());
  const auto nearest =
      centroid_answer ? *centroid_answer
                      : scene_.closest_point(centroid, distance_bound_from_corners(cell, centroid));
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
    const auto f = corner_distances_to_triangle(c, scene_.triangle_of_face(face));
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
    const double radius = sampled + centroid_radius;
    if (reach)
      reach->add_ball(centroid, radius);
    // A cell that meets one of the triangles nearest to its centroid and corners within the
    // radius (under noise, most cells that get this far cross B there) has minimum 0, which
    // leaves lo as it is: the search for the near triangles is skipped. meets_one_of() asks
    // what the loop below would: whether faces_within() holds the triangle (its distance
    // within the radius) and the test that makes triangle_triangle_distance answer 0.
    const auto near = meets_one_of(c, faces, centroid, radius)
                          ? std::nullopt
                          : scene_.faces_within(centroid, radius, kMaxExactMinimumFaces);
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
bool MeanCellBounder::near_enough_to_tighten(const MeanCell& cell) const {
  if (cell.corner_face[0] < 0)
    return false;
  const auto& t = scene_.triangle_of_face(cell.corner_face[0]);
  const double edge = std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
  const double radius = cell_radius(cell);
  return cell.hi <= 4.0 * radius && cell.hi + radius <= 2.0 * edge;
}

double MeanCellBounder::cell_radius(const MeanCell& cell) {
  const auto& c = cell.corners;
  const Point g = cell_centroid(cell);
  double radius = 0.0;
  for (const Point& corner : c)
    radius = std::max(radius, (corner - g).norm());
  return radius;
}

void MeanCellBounder::tighten(MeanCell& cell) const {
  cell.planes_tried = true;  // enqueue() counts the candidates' search as one query
  const auto& c = cell.corners;
  const Point g = cell_centroid(cell);
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
bool MeanCellBounder::covered_by(const std::array<Point, 3>& c, const Plane& plane,
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

}  // namespace holebench
