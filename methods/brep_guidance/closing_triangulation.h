// The triangles of a planned closing (closing_plan.h), before the mesh is touched. A polygon
// that passes a corner twice is split there. Each polygon is triangulated by a constrained
// Delaunay triangulation in its face's plane; where its projection is not simple, or that
// triangulation would use an edge the mesh or another part already has (an edge of three
// faces), the attempt (ClosingAttempt) may triangulate it in its own least-squares plane or
// in the loop's own order instead.
#pragma once

#include "core/mesh.h"
#include "methods/brep_guidance/brep_faces.h"
#include "methods/brep_guidance/closing_plan.h"

#include <array>
#include <string>
#include <vector>

namespace holebench::brep_guidance {

struct ClosingTriangles {
  /// By planned face: its triangles, in the mesh's orientation.
  std::vector<std::vector<std::array<PolygonCorner, 3>>> triangles;
  /// How a part was triangulated where the Delaunay triangulation in its face's plane did not
  /// serve (in its own plane, with its angle to the face's; in the loop's order, with its
  /// folded area), in the order of the parts.
  std::vector<std::string> notes;
  bool ok = false;
  std::string error;  ///< the part that could not be triangulated, and why
};

/// Every part of `plan` triangulated, none using an edge the mesh or another part has.
ClosingTriangles triangulate_closing(const Mesh& mesh, const BrepFaces& faces,
                                     const ClosingPlan& plan, const ClosingAttempt& attempt);

}  // namespace holebench::brep_guidance
