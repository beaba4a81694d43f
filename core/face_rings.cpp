#include "core/face_rings.h"

#include <utility>

namespace holebench {

std::vector<char> faces_within_rings(const Mesh& mesh, const std::vector<VertexHandle>& seeds,
                                     int rings) {
  std::vector<char> chosen(mesh.n_faces(), 0);
  std::vector<char> visited(mesh.n_vertices(), 0);
  std::vector<VertexHandle> frontier;
  for (VertexHandle v : seeds) {
    if (!visited[v.idx()]) {
      visited[v.idx()] = 1;
      frontier.push_back(v);
    }
  }
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<VertexHandle> next;
    for (VertexHandle v : frontier) {
      for (auto f : mesh.vf_range(v)) {
        if (chosen[f.idx()])
          continue;
        chosen[f.idx()] = 1;
        for (auto w : mesh.fv_range(f)) {
          if (!visited[w.idx()]) {
            visited[w.idx()] = 1;
            next.push_back(w);
          }
        }
      }
    }
    frontier = std::move(next);
  }
  return chosen;
}

}  // namespace holebench
