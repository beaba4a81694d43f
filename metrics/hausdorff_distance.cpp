#include "metrics/hausdorff_distance.h"

#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <vector>

namespace holebench {
namespace {

// A (sub)triangle of A with its corners' distances to B and its upper bound.
struct Cell {
  std::array<Point, 3> corners;
  std::array<double, 3> corner_distance;
  double upper = 0.0;
  std::size_t order = 0;  // creation order: breaks ties in the queue deterministically
};

struct CellOrder {
  bool operator()(const Cell& x, const Cell& y) const {
    if (x.upper != y.upper)
      return x.upper < y.upper;
    return x.order > y.order;
  }
};

class DirectedSearch {
 public:
  DirectedSearch(const embree::TriangleScene& scene, const HausdorffOptions& options)
      : scene_(scene), options_(options) {}

  DirectedHausdorff run(const Mesh& a) {
    // Corner distances of the original triangles are shared through the vertices.
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
    while (!queue_.empty()) {
      if (queue_.top().upper <= result_.lower + options_.error_bound)
        break;
      if (result_.queries >= options_.max_queries) {
        result_.converged = false;
        break;
      }
      Cell cell = queue_.top();
      queue_.pop();
      split(cell);
    }
    result_.upper = std::max(result_.lower, queue_.empty() ? 0.0 : queue_.top().upper);
    return result_;
  }

 private:
  embree::ClosestPoint query(const Point& p) {
    ++result_.queries;
    const auto closest = scene_.closest_point(p);
    result_.lower = std::max(result_.lower, closest.distance);
    return closest;
  }

  void push(Cell cell) {
    const auto& c = cell.corners;
    const Point centroid = (c[0] + c[1] + c[2]) / 3.0;
    const auto nearest = query(centroid);
    // Bound (i): the distance to one triangle of B is convex, so its maximum over the
    // cell is at a corner.
    const auto& t = scene_.triangle_of_face(nearest.face);
    double bound_single = 0.0;
    for (const Point& corner : c) {
      const Point q = embree::closest_point_on_triangle(corner, t[0], t[1], t[2]);
      bound_single = std::max(bound_single, (q - corner).norm());
    }
    // Bound (ii): every point lies within longest edge / sqrt(3) of a corner (the
    // equilateral triangle is the worst case), and the distance is 1-Lipschitz.
    const double longest = std::sqrt(
        std::max({(c[1] - c[0]).sqrnorm(), (c[2] - c[1]).sqrnorm(), (c[0] - c[2]).sqrnorm()}));
    const double bound_lipschitz =
        *std::max_element(cell.corner_distance.begin(), cell.corner_distance.end()) +
        longest * 0.57735026919;
    cell.upper = std::min(bound_single, bound_lipschitz);
    cell.order = next_order_++;
    queue_.push(std::move(cell));
  }

  void split(const Cell& cell) {
    const auto& c = cell.corners;
    const std::array<Point, 3> mid = {(c[0] + c[1]) * 0.5, (c[1] + c[2]) * 0.5,
                                      (c[2] + c[0]) * 0.5};
    std::array<double, 3> mid_distance;
    for (int i = 0; i < 3; ++i)
      mid_distance[i] = query(mid[i]).distance;
    const auto& d = cell.corner_distance;
    push({{c[0], mid[0], mid[2]}, {d[0], mid_distance[0], mid_distance[2]}});
    push({{mid[0], c[1], mid[1]}, {mid_distance[0], d[1], mid_distance[1]}});
    push({{mid[2], mid[1], c[2]}, {mid_distance[2], mid_distance[1], d[2]}});
    push({{mid[0], mid[1], mid[2]}, {mid_distance[0], mid_distance[1], mid_distance[2]}});
  }

  const embree::TriangleScene& scene_;
  const HausdorffOptions& options_;
  DirectedHausdorff result_;
  std::priority_queue<Cell, std::vector<Cell>, CellOrder> queue_;
  std::size_t next_order_ = 0;
};

}  // namespace

DirectedHausdorff directed_hausdorff(const Mesh& a, const embree::TriangleScene& b_scene,
                                     const HausdorffOptions& options) {
  return DirectedSearch(b_scene, options).run(a);
}

HausdorffResult hausdorff_distance(const Mesh& a, const Mesh& b, const HausdorffOptions& options) {
  const embree::TriangleScene a_scene(a);
  const embree::TriangleScene b_scene(b);
  HausdorffResult result;
  result.a_to_b = directed_hausdorff(a, b_scene, options);
  result.b_to_a = directed_hausdorff(b, a_scene, options);
  return result;
}

}  // namespace holebench
