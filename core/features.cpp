#include "core/features.h"

#include "core/geometry.h"
#include "core/planar_regions.h"

#include <algorithm>
#include <cmath>

namespace holebench {

std::string Corner::signature() const {
  std::string s;
  for (Convexity c : edge_convexity)
    s += c == Convexity::Convex ? 'c' : 'r';
  return s;
}

namespace {

int sharp_degree(const Mesh& mesh, VertexHandle v, const std::vector<char>& sharp) {
  int degree = 0;
  for (auto e : mesh.ve_range(v))
    degree += sharp[e.idx()] ? 1 : 0;
  return degree;
}

std::pair<int, int> region_pair(const Mesh& mesh, EdgeHandle e, const SegmentationResult& s) {
  const int a = s.face_region[mesh.face_handle(mesh.halfedge_handle(e, 0)).idx()];
  const int b = s.face_region[mesh.face_handle(mesh.halfedge_handle(e, 1)).idx()];
  return std::minmax(a, b);
}

// Walks from `start` along `first` over sharp edges of the same region pair until a vertex
// that is a corner (sharp degree != 2) or the start again.
SharpEdgeChain trace_chain(const Mesh& mesh, VertexHandle start, EdgeHandle first,
                           const FeatureAnalysis& analysis, std::vector<char>& used) {
  SharpEdgeChain chain;
  const auto pair = region_pair(mesh, first, analysis.segmentation);
  chain.regions[0] = pair.first;
  chain.regions[1] = pair.second;
  chain.vertices.push_back(start);
  VertexHandle current = start;
  EdgeHandle edge = first;
  int convex = 0;
  while (true) {
    used[edge.idx()] = 1;
    chain.edges.push_back(edge);
    convex += analysis.edge_convexity[edge.idx()] == Convexity::Convex ? 1 : 0;
    chain.length += mesh.calc_edge_length(edge);
    const auto h = mesh.halfedge_handle(edge, 0);
    current = mesh.from_vertex_handle(h) == current ? mesh.to_vertex_handle(h)
                                                    : mesh.from_vertex_handle(h);
    chain.vertices.push_back(current);
    if (current == start) {
      chain.closed = true;
      break;
    }
    if (sharp_degree(mesh, current, analysis.edge_is_sharp) != 2)
      break;
    EdgeHandle next;
    for (auto e : mesh.ve_range(current)) {
      if (analysis.edge_is_sharp[e.idx()] && !used[e.idx()] &&
          region_pair(mesh, e, analysis.segmentation) == pair) {
        next = e;
        break;
      }
    }
    if (!next.is_valid())
      break;
    edge = next;
  }
  chain.convexity =
      2 * convex >= static_cast<int>(chain.edges.size()) ? Convexity::Convex : Convexity::Reflex;
  return chain;
}

// The mesh's own region ids as a segmentation; sharp edges are the region borders whose
// dihedral angle exceeds the segmentation's threshold, or the planar threshold where both
// regions are planar (plane fit residual below 1e-6 of the diagonal).
SegmentationResult regions_of_mesh(const Mesh& mesh, const FeatureOptions& options) {
  const double threshold = options.segmentation.sharp_angle_degrees * M_PI / 180.0;
  const double planar_threshold = options.planar_sharp_angle_degrees * M_PI / 180.0;
  SegmentationResult result;
  result.face_region.assign(mesh.n_faces(), kNoRegion);
  for (auto f : mesh.faces())
    result.face_region[f.idx()] = region(mesh, f);
  result.region_count = region_count(mesh);
  const std::vector<char> is_planar =
      planar_regions(fit_region_planes(mesh), 1e-6 * bounding_box_diagonal(mesh));
  const auto planar = [&](int r) {
    return r >= 0 && r < static_cast<int>(is_planar.size()) && is_planar[r];
  };
  for (auto e : mesh.edges()) {
    if (e.is_boundary())
      continue;
    const int a = region(mesh, e.h0().face()), b = region(mesh, e.h1().face());
    if (a == b)
      continue;
    const double limit = planar(a) && planar(b) ? planar_threshold : threshold;
    if (std::abs(signed_dihedral_angle(mesh, e)) > limit)
      result.sharp_edges.push_back(e);
  }
  return result;
}

}  // namespace

FeatureAnalysis analyse_features(const Mesh& mesh, const FeatureOptions& options) {
  FeatureAnalysis analysis;
  analysis.segmentation = options.regions_from_mesh ? regions_of_mesh(mesh, options)
                                                    : segment_regions(mesh, options.segmentation);
  analysis.edge_is_sharp.assign(mesh.n_edges(), 0);
  analysis.edge_convexity.assign(mesh.n_edges(), Convexity::Convex);
  for (auto e : analysis.segmentation.sharp_edges) {
    analysis.edge_is_sharp[e.idx()] = 1;
    analysis.edge_convexity[e.idx()] =
        signed_dihedral_angle(mesh, e) >= 0.0 ? Convexity::Convex : Convexity::Reflex;
  }

  // Corners: three or more sharp edges meet.
  for (auto v : mesh.vertices()) {
    if (sharp_degree(mesh, v, analysis.edge_is_sharp) < 3)
      continue;
    Corner corner;
    corner.vertex = v;
    for (auto e : mesh.ve_range(v)) {
      if (analysis.edge_is_sharp[e.idx()])
        corner.edge_convexity.push_back(analysis.edge_convexity[e.idx()]);
    }
    std::sort(corner.edge_convexity.begin(), corner.edge_convexity.end());
    analysis.corners.push_back(corner);
  }

  // Chains: first from every chain end (a vertex of sharp degree other than 2), then the
  // closed loops that remain.
  std::vector<char> used(mesh.n_edges(), 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (auto v : mesh.vertices()) {
      const int degree = sharp_degree(mesh, v, analysis.edge_is_sharp);
      if (degree == 0 || (pass == 0 && degree == 2))
        continue;
      for (auto e : mesh.ve_range(v)) {
        if (!analysis.edge_is_sharp[e.idx()] || used[e.idx()])
          continue;
        analysis.chains.push_back(trace_chain(mesh, v, e, analysis, used));
      }
    }
  }
  return analysis;
}

}  // namespace holebench
