// Hole identification (crest-line paper, section 3.3): boundary edges (one adjacent
// triangle) traced into closed loops; each loop is a hole. Not in the paper: a loop that
// bounds an island (a piece of surface the hole surrounds) is attached to the hole around it
// instead of being a hole of its own, so that the hole is filled as the region between them.
#pragma once

#include "core/boundary_loops.h"
#include "core/mesh.h"

#include <vector>

namespace holebench::crest_feature {

struct Hole {
  BoundaryLoop loop;                   ///< boundary halfedges, in order
  std::vector<VertexHandle> vertices;  ///< loop order (from-vertex of each halfedge)
  Point centroid{0, 0, 0};
  /// Equation 4: a = sum of the boundary edge lengths / n.
  double average_edge_length = 0.0;
  double radius = 0.0;  ///< largest distance of a boundary vertex from the centroid
  /// The loops of the islands inside the hole (not in the paper), each in loop order.
  std::vector<std::vector<VertexHandle>> islands;
};

struct HoleIdentificationOptions {
  /// Attach each island loop to the hole around it (is_island_of). Off: every loop is a
  /// hole, as in the paper, and an island's loop is filled as if it were one.
  bool attach_islands = true;
};

/// The sum of the normals of the faces along a loop (the faces across its boundary
/// halfedges): the side the surface around the loop faces.
Point loop_face_normal_sum(const Mesh& mesh, const BoundaryLoop& loop);

/// Whether the loop `inner` bounds an island of the hole bounded by `outer`: seen along the
/// normal sum of `outer`'s faces, every point of `inner` lies inside `outer`, `inner`'s
/// faces face the same side, `outer` runs as a hole's loop and `inner` the other way round (the
/// surface lies outside a hole's loop and inside an island's or an open sheet's border). `inner`
/// must also lie within `outer`'s diameter of `outer`'s centroid along that normal, so that a hole
/// on a parallel face is not taken.
bool is_island_of(const Mesh& mesh, const BoundaryLoop& inner, const BoundaryLoop& outer);

/// Every hole of `mesh`, in the order of find_boundary_loops (islands attached to the
/// smallest hole they are an island of, and left out of the list).
std::vector<Hole> identify_holes(const Mesh& mesh, const HoleIdentificationOptions& options = {});

}  // namespace holebench::crest_feature
