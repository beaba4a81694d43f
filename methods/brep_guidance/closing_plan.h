// The plan of a closing (section 3.3 of the B-Rep paper, figure 4): the planar polygons
// that the closing adds, one per face it extends. k = 1: the loop itself, in its face's plane.
// k = 2, 3: the part of the loop each face f_i borders (from E_i to E_{i+1}) closed by the
// rebuilt edges on the lines L_i where the faces' fitted planes meet, and for k = 3 by the
// new vertex v_s at S. The rebuilt edges' inner points are new points, shared by the two
// faces along each edge. The attempts after the plan (exact_closing.h) change how the
// polygons are planned: ClosingAttempt says which.
#pragma once

#include "core/mesh.h"
#include "core/plane_fit.h"
#include "methods/brep_guidance/brep_faces.h"
#include "methods/brep_guidance/hole_detection.h"

#include <optional>
#include <string>
#include <vector>

namespace holebench::brep_guidance {

/// A corner of a planned polygon: an existing vertex, or a new point.
struct PolygonCorner {
  VertexHandle vertex;  ///< invalid for a new point
  Point position;
  int new_index = -1;  ///< index into the plan's new points (shared between faces)
};

/// Whether two corners are the same vertex or the same new point.
bool same_corner(const PolygonCorner& a, const PolygonCorner& b);

/// A face's new part: a polygon in the loop's order, to triangulate in a plane.
struct PlannedFace {
  int region;
  std::vector<PolygonCorner> polygon;
  std::optional<Plane> plane;  ///< the plane to triangulate in, if not the region's
};

/// One attempt at the closing: the plan, or the plan with the changes an attempt asks for.
struct ClosingAttempt {
  /// Loop vertices that lie on a rebuilt edge (within the lines' tolerance, strictly between
  /// its ends) become corners of that edge instead of the new points near them; the part that
  /// passes them twice is then split there into polygons that touch.
  bool loop_vertices_on_edges = false;
  /// A part whose Delaunay triangulation in its face's plane fails is triangulated in the
  /// loop's order (triangulate_in_loop_order); otherwise the attempt fails there.
  bool loop_order = false;
  /// A part whose Delaunay triangulation in its face's plane fails is first triangulated by a
  /// Delaunay triangulation in its own least-squares plane (the plane of its corners).
  bool own_plane = false;
  /// k = 3 only: the face (index into the hole's faces) whose part is at most one loop edge
  /// gives its run to a neighbouring face, and the hole is closed as k = 2 on the common line
  /// of the other two faces, without the corner S; -1: not used.
  int absorbed_face = -1;
  /// The run goes to the previous face (f_{j-1}, whose run it follows) or to the next.
  bool into_previous = true;
  /// k >= 2: where the whole loop lies in one plane within its faces' noise (the RMS residual
  /// of the loop's least-squares plane at most three times the largest of its faces' planes),
  /// it is one part in that plane, closed like a k = 1 hole, without rebuilt edges.
  bool one_plane = false;
};

struct ClosingPlan {
  std::vector<Point> new_points;   ///< the new vertices, in the order they are added
  std::vector<PlannedFace> faces;  ///< the parts to fill (a part of at most an edge is left out)
  /// How the plan departs from figure 4's (the loop as one part; a face's run given to a
  /// neighbour); empty otherwise.
  std::string note;
  /// False where the attempt does not apply to this hole (then nothing is planned).
  bool applicable = true;
};

/// The polygons that close `hole` (k <= 3, inner, planes not dependent) as `attempt` plans
/// them.
ClosingPlan plan_closing(const Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                         const ClosingAttempt& attempt);

}  // namespace holebench::brep_guidance
