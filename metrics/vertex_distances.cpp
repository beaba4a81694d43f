#include "metrics/vertex_distances.h"

#include "metrics/embree/triangle_scene.h"
#include "metrics/shared_faces.h"
#include "metrics/triangle_cell.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <limits>

namespace holebench {

void mark_vertices_on_shared_face(const Mesh& a, FaceHandle f, int match,
                                  VertexDistances& distances) {
  for (auto v : a.fv_range(f)) {
    distances.distance[v.idx()] = 0.0;
    distances.nearest_face[v.idx()] = match;
  }
}

VertexDistances vertex_distances(const Mesh& a, const embree::TriangleScene& b_scene,
                                 const std::vector<int>* b_face_of_a,
                                 const EarlierVertexAnswer& earlier) {
  constexpr double kUnknown = kUnknownVertexDistance;
  VertexDistances result;
  result.distance.assign(a.n_vertices(), kUnknown);
  result.nearest_face.assign(a.n_vertices(), -1);
  if (b_face_of_a) {
    for (auto f : a.faces()) {
      const int match = (*b_face_of_a)[f.idx()];
      if (match >= 0)
        mark_vertices_on_shared_face(a, f, match, result);
    }
  }
  // Blocks of consecutive vertices in parallel; inside a block, in index order, each query
  // bounded through the neighbours done before it in the same block (or known to be on B)
  // so that no block reads what another one writes. The answers do not depend on the
  // bounds, so the result is the same whatever the number of threads.
  const std::vector<double> known = result.distance;
  constexpr std::size_t kBlock = 2048;
  const std::size_t blocks = (a.n_vertices() + kBlock - 1) / kBlock;
  std::atomic<std::size_t> queries{0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1), [&](const auto& range) {
    for (std::size_t block = range.begin(); block != range.end(); ++block) {
      const std::size_t first = block * kBlock, last = std::min(first + kBlock, a.n_vertices());
      std::size_t count = 0;
      for (std::size_t i = first; i < last; ++i) {
        if (known[i] != kUnknown)
          continue;
        if (earlier && earlier(static_cast<int>(i), result.distance[i], result.nearest_face[i]))
          continue;
        const auto v = a.vertex_handle(static_cast<int>(i));
        double bound = std::numeric_limits<double>::infinity();
        for (auto u : a.vv_range(v)) {
          const std::size_t j = static_cast<std::size_t>(u.idx());
          const bool done = known[j] != kUnknown || (j >= first && j < i);
          if (done)
            bound = std::min(bound, result.distance[j] + (a.point(v) - a.point(u)).norm());
        }
        const auto closest = b_scene.closest_point(a.point(v), bound);
        ++count;
        result.distance[i] = closest.distance;
        result.nearest_face[i] = closest.face;
      }
      queries += count;
    }
  });
  result.queries = queries;
  return result;
}

const VertexDistances& vertex_distances(const Mesh& a, const embree::TriangleScene& b_scene,
                                        const KnownDistances& known, VertexDistances& computed) {
  if (known.vertices)
    return *known.vertices;
  computed = vertex_distances(a, b_scene, known.b_face_of_a);
  return computed;
}

FirstPass first_pass(const Mesh& a, const Mesh& b, const embree::TriangleScene& b_scene) {
  FirstPass pass;
  pass.b_face_of_a = shared_faces(a, b).b_face_of_a;
  pass.vertices = vertex_distances(a, b_scene, &pass.b_face_of_a);
  pass.centroid.assign(a.n_faces(), embree::ClosestPoint{});
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, a.n_faces(), 256), [&](const auto& range) {
    for (std::size_t f = range.begin(); f != range.end(); ++f) {
      if (pass.b_face_of_a[f] >= 0)
        continue;
      const TriangleCell cell = face_cell(a, FaceHandle(static_cast<int>(f)), pass.vertices);
      const Point centroid = cell_centroid(cell);
      pass.centroid[f] =
          b_scene.closest_point(centroid, distance_bound_from_corners(cell, centroid));
    }
  });
  return pass;
}

}  // namespace holebench
