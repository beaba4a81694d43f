// The topology counts of a repair (open boundary loops, non-manifold vertices, orientation
// conflicts) from what every repair of one input shares, at the cost of the repair's changes
// rather than the model's size.
//
// Let P be the repaired faces that are not the input's own (kept_faces.h) and D the input faces
// the repair did not keep, and A the vertices of P and D. A vertex outside A has the same
// incident faces in both meshes (all kept, with the same vertex indices), hence the same fan:
// it is manifold in the repair exactly when it is in the input, the directed edges from it
// have the same faces, and a boundary loop through no vertex of A is one of the input's.
// So each count is the input's part away from A (computed once per case) plus the repair's
// part at A (walked from A's vertices).
#pragma once

#include "core/mesh.h"
#include "metrics/kept_faces.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace holebench {

/// What the topology counts of every repair of one input share.
struct InputTopology {
  std::vector<std::vector<int>> boundary_loop_vertices;  ///< per loop (find_boundary_loops)
  std::vector<int> non_manifold_vertices;
  std::vector<std::pair<int, int>> conflicting_edges;  ///< directed (u, v) with two faces or more
};

InputTopology input_topology(const Mesh& input);

struct TopologyCounts {
  std::size_t open_boundary_loops = 0;
  std::size_t non_manifold_vertices = 0;
  std::size_t orientation_conflicts = 0;
};

/// The counts of `repaired` as find_boundary_loops, Mesh::is_manifold and validity.h's
/// orientation conflicts give them on the whole mesh; nothing where a boundary walk from A
/// does not close (a corrupt mesh: the caller counts on the whole mesh).
std::optional<TopologyCounts> topology_from_input(const Mesh& input, const Mesh& repaired,
                                                  const InputTopology& known,
                                                  const KeptFaces& kept);

/// Directed edges (u, v) used by two faces or more, each counted once, on the whole mesh.
std::vector<std::pair<int, int>> conflicting_edges(const Mesh& mesh);

}  // namespace holebench
