#include "methods/crest_feature/boundary_edge_split.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace holebench::crest_feature {
namespace {

// The boundary halfedges that now run from hole.vertices[i] to hole.vertices[i + 1]: the
// input's halfedge, or after splits the chain through the vertices inserted on that edge.
std::vector<HalfedgeHandle> edge_chain(const Mesh& mesh, const Hole& hole, int i,
                                       const std::set<VertexHandle>& inserted) {
  const int n = static_cast<int>(hole.vertices.size());
  const VertexHandle from = hole.vertices[i], to = hole.vertices[(i + 1) % n];
  const HalfedgeHandle original = hole.loop.halfedges[i];
  if (mesh.is_boundary(original) && mesh.from_vertex_handle(original) == from &&
      mesh.to_vertex_handle(original) == to)
    return {original};
  std::vector<HalfedgeHandle> chain;
  for (auto h : mesh.voh_range(from)) {
    if (mesh.is_boundary(h) && inserted.count(mesh.to_vertex_handle(h))) {
      chain.push_back(h);
      break;
    }
  }
  while (!chain.empty() && mesh.to_vertex_handle(chain.back()) != to &&
         chain.size() <= inserted.size()) {
    const HalfedgeHandle next = mesh.next_halfedge_handle(chain.back());
    const VertexHandle v = mesh.to_vertex_handle(next);
    chain.push_back(next);
    if (v != to && !inserted.count(v))
      break;  // left the edge: cannot happen on a manifold boundary
  }
  return chain;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const Point d = b - a;
  const double c = OpenMesh::dot(d, d);
  const double t = c > 0 ? std::clamp(OpenMesh::dot(p - a, d) / c, 0.0, 1.0) : 0.0;
  return (p - (a + d * t)).norm();
}

// Splits the boundary edge of `h` and its one face at `p`; the halves and the new vertex
// are patch (Provenance::New).
VertexHandle split_boundary_edge(Mesh& mesh, HalfedgeHandle h, const Point& p) {
  const VertexHandle v = mesh.add_vertex(p);
  mesh.split(mesh.edge_handle(h), v);
  mesh.data(v).provenance = Provenance::New;
  for (auto f : mesh.vf_range(v))
    mesh.data(f).provenance = Provenance::New;
  return v;
}

}  // namespace

InsertedFeaturePoints insert_feature_points(Mesh& mesh, const Hole& hole,
                                            const HoleFeatures& features) {
  InsertedFeaturePoints result{hole, features, 0};
  const int n = static_cast<int>(hole.vertices.size());
  std::set<VertexHandle> inserted;
  std::map<int, VertexHandle> vertex_of_point;  // feature point -> its vertex
  for (std::size_t k = 0; k < features.points.size(); ++k) {
    const FeaturePoint& f = features.points[k];
    if (!f.edge_parameter) {
      vertex_of_point[static_cast<int>(k)] = hole.vertices[f.loop_index];
      continue;
    }
    // The piece of the (possibly already split) edge that holds the point.
    const auto chain = edge_chain(mesh, hole, f.loop_index, inserted);
    HalfedgeHandle best;
    double best_distance = std::numeric_limits<double>::infinity();
    for (auto h : chain) {
      const double d = distance_to_segment(f.position, mesh.point(mesh.from_vertex_handle(h)),
                                           mesh.point(mesh.to_vertex_handle(h)));
      if (d < best_distance) {
        best_distance = d;
        best = h;
      }
    }
    if (!best.is_valid() || !mesh.is_boundary(best)) {  // not found: the edge's start vertex
      vertex_of_point[static_cast<int>(k)] = hole.vertices[f.loop_index];
      continue;
    }
    const VertexHandle v = split_boundary_edge(mesh, best, f.position);
    inserted.insert(v);
    vertex_of_point[static_cast<int>(k)] = v;
    ++result.inserted;
  }
  if (result.inserted == 0 && std::none_of(features.points.begin(), features.points.end(),
                                           [](const FeaturePoint& f) { return f.edge_parameter; }))
    return result;

  // The new loop, edge by edge in the input's order.
  result.hole.loop.halfedges.clear();
  for (int i = 0; i < n; ++i) {
    for (auto h : edge_chain(mesh, hole, i, inserted))
      result.hole.loop.halfedges.push_back(h);
  }
  result.hole.vertices = loop_vertices(mesh, result.hole.loop);
  std::map<VertexHandle, int> index;
  for (std::size_t i = 0; i < result.hole.vertices.size(); ++i)
    index[result.hole.vertices[i]] = static_cast<int>(i);
  for (std::size_t k = 0; k < result.features.points.size(); ++k) {
    FeaturePoint& f = result.features.points[k];
    const VertexHandle v = vertex_of_point[static_cast<int>(k)];
    f.loop_index = index.count(v) ? index[v] : 0;
    f.position = mesh.point(v);
    f.edge_parameter.reset();
  }
  return result;
}

}  // namespace holebench::crest_feature
