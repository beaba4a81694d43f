#include "metrics/vertex_distances.h"

#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <limits>

namespace holebench {

VertexDistances vertex_distances(const Mesh& a, const embree::TriangleScene& b_scene,
                                 const std::vector<int>* b_face_of_a) {
  constexpr double kUnknown = -1.0;
  VertexDistances result;
  result.distance.assign(a.n_vertices(), kUnknown);
  result.nearest_face.assign(a.n_vertices(), -1);
  if (b_face_of_a) {
    for (auto f : a.faces()) {
      const int match = (*b_face_of_a)[f.idx()];
      if (match < 0)
        continue;
      for (auto v : f.vertices()) {
        result.distance[v.idx()] = 0.0;
        result.nearest_face[v.idx()] = match;
      }
    }
  }
  for (auto v : a.vertices()) {
    if (result.distance[v.idx()] != kUnknown)
      continue;
    double bound = std::numeric_limits<double>::infinity();
    for (auto u : a.vv_range(v)) {
      const double du = result.distance[u.idx()];
      if (du != kUnknown)
        bound = std::min(bound, du + (a.point(v) - a.point(u)).norm());
    }
    const auto closest = b_scene.closest_point(a.point(v), bound);
    ++result.queries;
    result.distance[v.idx()] = closest.distance;
    result.nearest_face[v.idx()] = closest.face;
  }
  return result;
}

}  // namespace holebench
