#include "methods/slice_loft/pinched_portions.h"

#include "core/polygon.h"

#include <algorithm>

namespace holebench::slice_loft {
namespace {

// The identity of a node: its vertex, or its missing-feature point.
long node_key(const BoundaryNode& node) {
  return node.vertex.is_valid() ? node.vertex.idx() : -2L - node.feature;
}

// Merges repeated consecutive nodes (cyclically) and cuts off spikes (a, b, a) until none is
// left.
void remove_repeats_and_spikes(std::vector<BoundaryNode>& loop) {
  bool changed = true;
  while (changed && loop.size() >= 2) {
    changed = false;
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (node_key(loop[i]) == node_key(loop[(i + 1) % n])) {
        loop.erase(loop.begin() + static_cast<long>((i + 1) % n));
        changed = true;
        break;
      }
      if (n >= 3 && node_key(loop[i]) == node_key(loop[(i + 2) % n])) {
        // a, b, a: drop b and the second a.
        const std::size_t b = (i + 1) % n, second = (i + 2) % n;
        loop.erase(loop.begin() + static_cast<long>(std::max(b, second)));
        loop.erase(loop.begin() + static_cast<long>(std::min(b, second)));
        changed = true;
        break;
      }
    }
  }
}

void split_into_simple_loops(std::vector<BoundaryNode> loop,
                             std::vector<std::vector<BoundaryNode>>& out) {
  remove_repeats_and_spikes(loop);
  if (loop.size() < 3)
    return;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    for (std::size_t j = i + 1; j < loop.size(); ++j) {
      if (node_key(loop[i]) != node_key(loop[j]))
        continue;
      // The loop passes the node twice: [i, j) is one loop, [j, end) + [0, i) the other.
      std::vector<BoundaryNode> first(loop.begin() + static_cast<long>(i),
                                      loop.begin() + static_cast<long>(j));
      std::vector<BoundaryNode> second(loop.begin() + static_cast<long>(j), loop.end());
      second.insert(second.end(), loop.begin(), loop.begin() + static_cast<long>(i));
      split_into_simple_loops(std::move(first), out);
      split_into_simple_loops(std::move(second), out);
      return;
    }
  }
  out.push_back(std::move(loop));
}

}  // namespace

std::vector<VertexHandle> feature_points_on_boundary(
    const Mesh& mesh, const std::vector<VertexHandle>& boundary_vertices,
    const MissingFeatures& features, double tolerance) {
  std::vector<VertexHandle> on(features.points.size());
  for (std::size_t k = 0; k < features.points.size(); ++k) {
    double best = tolerance;
    for (auto v : boundary_vertices) {
      const double distance = (mesh.point(v) - features.points[k]).norm();
      if (distance < best) {
        best = distance;
        on[k] = v;
      }
    }
  }
  return on;
}

void snap_feature_nodes(const Mesh& mesh, const std::vector<VertexHandle>& on_boundary,
                        std::vector<BoundaryNode>& nodes) {
  for (auto& node : nodes) {
    if (node.vertex.is_valid() || node.feature < 0 ||
        node.feature >= static_cast<int>(on_boundary.size()) ||
        !on_boundary[node.feature].is_valid())
      continue;
    node = {on_boundary[node.feature], -1, mesh.point(on_boundary[node.feature])};
  }
}

std::vector<std::vector<BoundaryNode>> simple_boundary_loops(
    const std::vector<BoundaryNode>& boundary) {
  std::vector<std::vector<BoundaryNode>> loops;
  split_into_simple_loops(boundary, loops);
  return loops;
}

std::vector<Portion> split_pinched_portion(const Portion& portion, const LoftedPatch& patch) {
  std::vector<Portion> pieces;
  for (auto& loop : simple_boundary_loops(portion.boundary)) {
    Portion piece;
    piece.region = portion.region;
    piece.boundary = std::move(loop);
    piece.missing_edges = portion.missing_edges;
    pieces.push_back(std::move(piece));
  }
  if (pieces.empty())
    return pieces;
  for (const auto& island : portion.islands) {
    std::size_t owner = 0;
    for (std::size_t p = 0; p < pieces.size() && !island.empty(); ++p) {
      std::vector<Point> loop;
      for (const auto& node : pieces[p].boundary)
        loop.push_back(node.position);
      if (inside_projected_polygon(loop, patch.n, island.front().position)) {
        owner = p;
        break;
      }
    }
    pieces[owner].islands.push_back(island);
  }
  return pieces;
}

}  // namespace holebench::slice_loft
