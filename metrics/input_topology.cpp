#include "metrics/input_topology.h"

#include "core/boundary_loops.h"

#include <algorithm>
#include <array>
#include <unordered_set>

namespace holebench {
namespace {

// The directed edges used twice or more among `faces`, each once, sorted.
std::vector<std::pair<int, int>> repeated_edges(const std::vector<std::array<int, 3>>& faces) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * faces.size());
  for (const auto& ids : faces) {
    for (int i = 0; i < 3; ++i)
      edges.emplace_back(ids[i], ids[(i + 1) % 3]);
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<int, int>> repeated;
  for (std::size_t i = 1; i < edges.size(); ++i) {
    if (edges[i] == edges[i - 1] && (repeated.empty() || repeated.back() != edges[i]))
      repeated.push_back(edges[i]);
  }
  return repeated;
}

}  // namespace

std::vector<std::pair<int, int>> conflicting_edges(const Mesh& mesh) {
  std::vector<std::array<int, 3>> faces;
  faces.reserve(mesh.n_faces());
  for (auto f : mesh.faces())
    faces.push_back(triangle_vertex_indices(mesh, f));
  return repeated_edges(faces);
}

InputTopology input_topology(const Mesh& input) {
  InputTopology known;
  for (const auto& loop : find_boundary_loops(input)) {
    std::vector<int> vertices;
    for (auto v : loop_vertices(input, loop))
      vertices.push_back(v.idx());
    known.boundary_loop_vertices.push_back(std::move(vertices));
  }
  for (auto v : input.vertices()) {
    if (!input.is_manifold(v))
      known.non_manifold_vertices.push_back(v.idx());
  }
  known.conflicting_edges = conflicting_edges(input);
  return known;
}

std::optional<TopologyCounts> topology_from_input(const Mesh& input, const Mesh& repaired,
                                                  const InputTopology& known,
                                                  const KeptFaces& kept) {
  // A: the vertices of the faces the repair changed, on either side.
  std::vector<int> changed_vertices;
  for (int f : kept.repaired_faces_not_kept) {
    const FaceHandle face(f);
    if (!repaired.status(face).deleted()) {
      for (int v : triangle_vertex_indices(repaired, face))
        changed_vertices.push_back(v);
    }
  }
  for (int f : kept.input_faces_not_kept) {
    const FaceHandle face(f);
    if (!input.status(face).deleted()) {
      for (int v : triangle_vertex_indices(input, face))
        changed_vertices.push_back(v);
    }
  }
  std::sort(changed_vertices.begin(), changed_vertices.end());
  changed_vertices.erase(std::unique(changed_vertices.begin(), changed_vertices.end()),
                         changed_vertices.end());
  const auto changed = [&](int v) {
    return std::binary_search(changed_vertices.begin(), changed_vertices.end(), v);
  };
  const auto in_repaired = [&](int v) {
    return v >= 0 && static_cast<std::size_t>(v) < repaired.n_vertices() &&
           !repaired.status(VertexHandle(v)).deleted();
  };

  TopologyCounts counts;
  // Away from A: the input's.
  for (const auto& loop : known.boundary_loop_vertices) {
    if (std::none_of(loop.begin(), loop.end(), changed))
      ++counts.open_boundary_loops;
  }
  for (int v : known.non_manifold_vertices)
    counts.non_manifold_vertices += !changed(v);
  for (const auto& edge : known.conflicting_edges)
    counts.orientation_conflicts += !changed(edge.first);

  // At A: the repair's loops through a vertex of A, walked as find_boundary_loops walks them,
  // its vertices' fans, and the directed edges from them among the faces around them.
  std::unordered_set<int> visited;
  std::vector<int> faces_at_changed;
  for (int index : changed_vertices) {
    if (!in_repaired(index))
      continue;
    const VertexHandle v(index);
    counts.non_manifold_vertices += !repaired.is_manifold(v);
    for (auto f : repaired.vf_range(v))
      faces_at_changed.push_back(f.idx());
    for (auto h : repaired.voh_range(v)) {
      if (!repaired.is_boundary(h) || visited.count(h.idx()))
        continue;
      HalfedgeHandle current = h;
      bool closed = false;
      for (std::size_t steps = 0; steps <= repaired.n_halfedges(); ++steps) {
        visited.insert(current.idx());
        current = repaired.next_halfedge_handle(current);
        if (current == h) {
          closed = true;
          break;
        }
      }
      if (!closed)
        return std::nullopt;
      ++counts.open_boundary_loops;
    }
  }
  std::sort(faces_at_changed.begin(), faces_at_changed.end());
  faces_at_changed.erase(std::unique(faces_at_changed.begin(), faces_at_changed.end()),
                         faces_at_changed.end());
  std::vector<std::array<int, 3>> triples;
  for (int f : faces_at_changed)
    triples.push_back(triangle_vertex_indices(repaired, FaceHandle(f)));
  for (const auto& edge : repeated_edges(triples))
    counts.orientation_conflicts += changed(edge.first);
  return counts;
}

}  // namespace holebench
