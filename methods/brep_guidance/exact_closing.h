// Section 3.3 of the B-Rep paper, automatic closing (figure 4): k = 1, the inner boundary is
// removed and the face filled in its plane; k = 2, the missing edge is rebuilt as the
// intersection line of the two planes and both faces are extended to it; k = 3, a new vertex
// v_s at the intersection S of the three planes and the faces extended to it. The new edges
// continue the faces' existing edges (the "merging of separated edges": in a triangle mesh the
// rebuilt edge shares its end vertices with the edge it continues).
//
// The paper extends B-Rep faces; here each extended face's new part is a planar polygon (the
// hole half-edges on that face, closed by the rebuilt edges) triangulated by a constrained
// Delaunay triangulation in the face's plane. Rebuilt edges are subdivided at about the
// hole's mean edge length, the same points on both faces that share them.
//
// Every closing is kept only if its new faces intersect neither each other nor the mesh
// within two vertex rings (CGAL, exact predicates). The paper's closing is the plan alone. With
// the project's option `later_attempts`, where the plan fails (a part's
// projection is not simple, or its triangulation would reuse an edge, or the closing
// intersects), more attempts follow, in this order: loop vertices that lie on a rebuilt edge
// become its corners and the part is split where it passes them twice (the loop touches the
// faces' common line there); then a part that is still not simple in its plane is
// triangulated in the loop's own order, choosing the triangulation with the least area
// folded against the polygon in the plane; then such a part is first triangulated in its own
// least-squares plane (a part nearly edge-on to its face's fitted plane); then (k = 3) a face
// whose part is at most one loop edge gives its run to a neighbour and the hole is closed as
// k = 2 on the other two faces' common line, without S (S lies beyond that edge, outside the
// hole); then (k >= 2) a loop that lies in one plane within its faces' noise is closed as one
// part in that plane (nearly parallel planes of one segmented face). The note says which was
// needed.
#pragma once

#include "core/mesh.h"
#include "methods/brep_guidance/brep_faces.h"
#include "methods/brep_guidance/hole_detection.h"

#include <string>

namespace holebench::brep_guidance {

struct ClosingResult {
  bool closed = false;
  std::size_t new_faces = 0;
  std::size_t new_vertices = 0;
  std::string error;  ///< why the hole could not be closed
  /// How it was closed where the plan alone did not (loop vertices taken as corners of a
  /// rebuilt edge; a part triangulated in the loop's order, with its folded area, or in its
  /// own plane, with its angle to the face's; a face's run given to a neighbour; the loop as
  /// one part in its own plane); empty otherwise.
  std::string note;
};

/// Closes `hole` (k <= 3, inner, planes not dependent) in `mesh` by figure 4's plan; with
/// `later_attempts` (the project's option, brep_guidance_plus) the attempts above follow where
/// the plan fails. New faces get the region of the face they extend. On failure the mesh is
/// left as it was.
ClosingResult close_hole_exactly(Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                                 bool later_attempts = false);

}  // namespace holebench::brep_guidance
