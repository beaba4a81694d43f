#include "generators/brep/brep_hole_loops.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace holebench::generators::brep {
namespace {

using Key = std::array<double, 3>;
Key key_of(const Point& p) {
  return {p[0], p[1], p[2]};
}

}  // namespace

std::vector<BrepHoleLoop> brep_hole_loops(const PolyhedronTopology& topology,
                                          const std::vector<char>& removed) {
  const Polyhedron& polyhedron = topology.polyhedron();
  // A hole halfedge runs from `to` to `from` of a kept face's edge whose twin is removed
  // (or missing): keyed by its start point, valued by the kept face's edge.
  std::map<Key, LoopEdge> hole_edges;
  for (int f = 0; f < static_cast<int>(polyhedron.faces.size()); ++f) {
    if (removed[f])
      continue;
    const auto& face = polyhedron.faces[f];
    for (int l = 0; l < face.loop_count(); ++l) {
      for (int i = 0; i < static_cast<int>(face.loop(l).size()); ++i) {
        const LoopEdge edge{f, l, i};
        const auto other = topology.twin(edge);
        if (other && !removed[other->face])
          continue;
        if (!hole_edges.emplace(key_of(topology.to(edge)), edge).second)
          throw std::logic_error("brep_hole_loops: a hole loop touches itself at a vertex");
      }
    }
  }
  std::vector<BrepHoleLoop> loops;
  while (!hole_edges.empty()) {
    // Walk one loop: the hole halfedge into point p is followed by the one out of p, i.e.
    // the kept edge ending... keyed by its hole start = the kept edge's `to`.
    std::vector<LoopEdge> edges;
    auto it = hole_edges.begin();
    const Key start = it->first;
    for (;;) {
      const LoopEdge edge = it->second;
      edges.push_back(edge);
      hole_edges.erase(it);
      const Key next = key_of(topology.from(edge));  // the hole halfedge ends at `from`
      if (next == start)
        break;
      it = hole_edges.find(next);
      if (it == hole_edges.end())
        throw std::logic_error("brep_hole_loops: open hole chain");
    }
    // Rotate to start at a change of face, so that visits are contiguous.
    std::size_t first = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (edges[i].face != edges[(i + edges.size() - 1) % edges.size()].face) {
        first = i;
        break;
      }
    }
    std::rotate(edges.begin(), edges.begin() + static_cast<long>(first), edges.end());
    BrepHoleLoop loop;
    std::vector<std::size_t> last_of_visit;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      loop.points.push_back(topology.to(edges[i]));
      if (i == 0 || edges[i].face != edges[i - 1].face) {
        loop.regions.push_back(edges[i].face);
        loop.face_loops.push_back(edges[i].loop);
        last_of_visit.push_back(i);
      } else {
        last_of_visit.back() = i;
      }
      const auto other = topology.twin(edges[i]);
      if (other)
        loop.adjacent_removed_faces.push_back(other->face);
    }
    const std::size_t k = loop.regions.size();
    if (k > 1) {
      for (std::size_t v = 0; v < k; ++v) {
        // The visit's last kept edge runs T -> x (the hole halfedge x -> T arrives at the
        // transition T); the kept face's edge into T, w -> T, is shared with the next face.
        const LoopEdge into = topology.previous(edges[last_of_visit[v]]);
        const auto across = topology.twin(into);
        if (!across || removed[across->face] || across->face != loop.regions[(v + 1) % k])
          throw std::logic_error("brep_hole_loops: a transition passes through a third face");
        loop.transitions.push_back(topology.convexity(into));
        loop.transition_points.push_back(topology.to(into));
      }
    }
    std::sort(loop.adjacent_removed_faces.begin(), loop.adjacent_removed_faces.end());
    loop.adjacent_removed_faces.erase(
        std::unique(loop.adjacent_removed_faces.begin(), loop.adjacent_removed_faces.end()),
        loop.adjacent_removed_faces.end());
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace holebench::generators::brep
