#include "generators/missing_sharp_edges.h"

#include <algorithm>
#include <map>
#include <set>

namespace holebench::generators {
namespace {

using Polylines = std::vector<std::vector<Point>>;

// Whether both faces of `e` are removed (a boundary edge has only one face: never).
bool is_missing(const Mesh& mesh, EdgeHandle e, const std::vector<char>& removed) {
  return !mesh.is_boundary(e) && removed[mesh.face_handle(mesh.halfedge_handle(e, 0)).idx()] &&
         removed[mesh.face_handle(mesh.halfedge_handle(e, 1)).idx()];
}

bool is_region_border(const Mesh& mesh, EdgeHandle e) {
  return region(mesh, mesh.face_handle(mesh.halfedge_handle(e, 0))) !=
         region(mesh, mesh.face_handle(mesh.halfedge_handle(e, 1)));
}

// The missing region borders, chained among themselves (see RegionBorderEdges).
Polylines chained_region_borders(const Mesh& complete, const std::vector<char>& removed) {
  std::map<int, std::vector<int>> adjacency;
  for (auto e : complete.edges()) {
    if (!is_missing(complete, e, removed) || !is_region_border(complete, e))
      continue;
    adjacency[e.v0().idx()].push_back(e.v1().idx());
    adjacency[e.v1().idx()].push_back(e.v0().idx());
  }
  Polylines polylines;
  std::set<std::pair<int, int>> used;
  auto walk = [&](int start, int next) {
    std::vector<Point> line{complete.point(VertexHandle(start))};
    int previous = start, current = next;
    for (;;) {
      used.insert({std::min(previous, current), std::max(previous, current)});
      line.push_back(complete.point(VertexHandle(current)));
      const auto& around = adjacency[current];
      if (around.size() != 2 || current == start)
        break;
      const int following = around[0] == previous ? around[1] : around[0];
      if (used.count({std::min(current, following), std::max(current, following)}))
        break;
      previous = current;
      current = following;
    }
    polylines.push_back(std::move(line));
  };
  for (int pass = 0; pass < 2; ++pass) {  // open chains first, then cycles
    for (const auto& [v, around] : adjacency) {
      if (pass == 0 && around.size() == 2)
        continue;
      for (int w : around) {
        if (!used.count({std::min(v, w), std::max(v, w)}))
          walk(v, w);
      }
    }
  }
  return polylines;
}

// The missing runs of the feature analysis' chains (see FeatureChainEdges).
Polylines missing_runs_of_chains(const Mesh& complete, const std::vector<char>& removed,
                                 const FeatureAnalysis& features) {
  Polylines polylines;
  for (const auto& chain : features.chains) {
    std::vector<Point> current;
    for (std::size_t i = 0; i < chain.edges.size(); ++i) {
      if (is_missing(complete, chain.edges[i], removed)) {
        if (current.empty())
          current.push_back(complete.point(chain.vertices[i]));
        current.push_back(complete.point(chain.vertices[i + 1]));
      } else if (!current.empty()) {
        polylines.push_back(std::move(current));
        current.clear();
      }
    }
    if (!current.empty())
      polylines.push_back(std::move(current));
  }
  return polylines;
}

}  // namespace

std::vector<std::vector<Point>> missing_sharp_edges(const Mesh& complete,
                                                    const std::vector<char>& removed,
                                                    const SharpEdges& sharp_edges) {
  if (const auto* chains = std::get_if<FeatureChainEdges>(&sharp_edges))
    return missing_runs_of_chains(complete, removed, chains->features);
  return chained_region_borders(complete, removed);
}

std::vector<Point> missing_corners(const Mesh& complete, const std::vector<char>& removed,
                                   const FeatureAnalysis& features) {
  std::vector<Point> corners;
  for (const auto& corner : features.corners) {
    bool all = true;
    for (auto f : complete.vf_range(corner.vertex))
      all = all && removed[f.idx()];
    if (all)
      corners.push_back(complete.point(corner.vertex));
  }
  return corners;
}

}  // namespace holebench::generators
