#include "methods/crest_feature/hole_identification.h"

#include <algorithm>

namespace holebench::crest_feature {

std::vector<Hole> identify_holes(const Mesh& mesh) {
  std::vector<Hole> holes;
  for (auto& loop : find_boundary_loops(mesh)) {
    Hole hole;
    hole.vertices = loop_vertices(mesh, loop);
    hole.centroid = loop_centroid(mesh, loop);
    hole.average_edge_length = loop_length(mesh, loop) / static_cast<double>(loop.size());
    for (auto v : hole.vertices)
      hole.radius = std::max(hole.radius, (mesh.point(v) - hole.centroid).norm());
    hole.loop = std::move(loop);
    holes.push_back(std::move(hole));
  }
  return holes;
}

}  // namespace holebench::crest_feature
