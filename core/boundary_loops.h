// Boundary loops (holes): closed loops of boundary halfedges.
#pragma once

#include "core/mesh.h"

#include <vector>

namespace holebench {

/// One boundary loop: its halfedges in order, each the `next` of the one before.
/// The halfedges are boundary halfedges (no face); the mesh's faces lie on their
/// opposite side, so the loop runs clockwise when seen from outside the surface.
struct BoundaryLoop {
  std::vector<HalfedgeHandle> halfedges;

  std::size_t size() const { return halfedges.size(); }
};

/// Every boundary loop of `mesh`, each once, in the order of their smallest halfedge
/// index; each loop starts at its smallest halfedge index, so the result depends only on
/// the mesh. A mesh without boundary gives an empty list.
std::vector<BoundaryLoop> find_boundary_loops(const Mesh& mesh);

/// The vertices of a loop, in loop order (the `from` vertex of each halfedge).
std::vector<VertexHandle> loop_vertices(const Mesh& mesh, const BoundaryLoop& loop);

/// The positions of the loop's vertices, in loop order.
std::vector<Point> loop_points(const Mesh& mesh, const BoundaryLoop& loop);

/// The total length of the loop's edges.
double loop_length(const Mesh& mesh, const BoundaryLoop& loop);

/// The mean of the loop's vertex positions.
Point loop_centroid(const Mesh& mesh, const BoundaryLoop& loop);

}  // namespace holebench
