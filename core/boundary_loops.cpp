#include "core/boundary_loops.h"

namespace holebench {

std::vector<BoundaryLoop> find_boundary_loops(const Mesh& mesh) {
  std::vector<BoundaryLoop> loops;
  std::vector<char> visited(mesh.n_halfedges(), 0);
  for (auto h : mesh.halfedges()) {
    if (visited[h.idx()] || !mesh.is_boundary(h))
      continue;
    BoundaryLoop loop;
    HalfedgeHandle current = h;
    // A manifold boundary vertex has one outgoing boundary halfedge, so `next` walks the
    // loop; the bound guards against a corrupt mesh.
    for (std::size_t steps = 0; steps <= mesh.n_halfedges(); ++steps) {
      visited[current.idx()] = 1;
      loop.halfedges.push_back(current);
      current = mesh.next_halfedge_handle(current);
      if (current == h)
        break;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<VertexHandle> loop_vertices(const Mesh& mesh, const BoundaryLoop& loop) {
  std::vector<VertexHandle> vertices;
  vertices.reserve(loop.size());
  for (auto h : loop.halfedges)
    vertices.push_back(mesh.from_vertex_handle(h));
  return vertices;
}

double loop_length(const Mesh& mesh, const BoundaryLoop& loop) {
  double length = 0.0;
  for (auto h : loop.halfedges)
    length += mesh.calc_edge_length(h);
  return length;
}

std::vector<Point> loop_points(const Mesh& mesh, const BoundaryLoop& loop) {
  std::vector<Point> points;
  for (auto v : loop_vertices(mesh, loop))
    points.push_back(mesh.point(v));
  return points;
}

Point loop_centroid(const Mesh& mesh, const BoundaryLoop& loop) {
  Point sum(0.0, 0.0, 0.0);
  for (auto h : loop.halfedges)
    sum += mesh.point(mesh.from_vertex_handle(h));
  return loop.halfedges.empty() ? sum : sum / static_cast<double>(loop.size());
}

}  // namespace holebench
