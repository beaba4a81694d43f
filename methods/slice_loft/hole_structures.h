// The data structures of section 3.1 of the slice paper: Hole and Segment, plus the
// contours of section 4.1 they are built from.
#pragma once

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "core/mesh.h"
#include "core/plane_fit.h"

#include <optional>
#include <string>
#include <vector>

namespace holebench::slice_loft {

/// Hole types of section 3: one region, several regions, several regions meeting at a corner.
enum class HoleType { SingleSegment, MultiSegmentOrdinary, MultiSegmentCorner };
const char* to_string(HoleType type);

/// A bounding contour of section 4.1: one boundary loop of the mesh.
struct Contour {
  BoundaryLoop loop;
  std::vector<VertexHandle> vertices;  ///< loop order (the `from` vertex of each halfedge)
  Plane span_plane;                    ///< plane of maximum span (normal: least variance)
  bool island = false;                 ///< classified island (4.1) rather than hole
};

/// Segment of section 3.1: a maximal run of the hole boundary lying in one region.
struct Segment {
  std::vector<HalfedgeHandle> halfedges;  ///< boundary halfedges, in loop order
  std::vector<VertexHandle> vertices;     ///< from the start vertex to the end vertex
  int region = kNoRegion;
  VertexHandle start, end;  ///< equal for a single-segment hole
  /// Region-boundary (sharp) edges incident on the start / end vertex; invalid if none.
  OpenMesh::EdgeHandle start_region_edge, end_region_edge;
  int missing_curve_at_start = -1;  ///< index into MissingFeatures::edges, -1 if none
  int missing_curve_at_end = -1;
};

/// Hole of section 3.1.
struct Hole {
  HoleType type = HoleType::SingleSegment;
  int contour = -1;                      ///< the hole-boundary contour
  std::vector<HalfedgeHandle> boundary;  ///< list of boundary edges
  BoundingBox box;                       ///< hole-enclosing box (boundary vertices)
  std::vector<int> islands;              ///< contours of the islands inside it
  std::vector<Segment> segments;         ///< in loop order
  std::vector<FaceHandle> influencing;   ///< triangles of the influencing area (4.1)
  double mean_edge_length = 0.0;         ///< of the hole boundary
  bool orphan_island = false;            ///< an island contour no hole claimed, filled as a hole
};

/// A missing edge of section 4.3, from a segment end towards the corner or the other end.
struct MissingEdge {
  int end_index = -1;        ///< the segment end (segment index) it starts at
  std::vector<Point> trace;  ///< traced points, the end vertex first (eqs. 1-3)
  std::vector<int> points;   ///< re-interpolated points (indices into `points`)
};

/// The reconstructed missing features of one hole (section 4.3).
struct MissingFeatures {
  std::vector<Point> points;       ///< new points on missing edges (and the corner)
  std::vector<MissingEdge> edges;  ///< one per segment end, in segment order
  int corner = -1;                 ///< index into `points` of the missing corner, -1 if none
  bool through_edge = false;       ///< two ends joined by one edge (no corner)
  bool straight = false;  ///< that edge joined straight: the traces led away from each other
  std::string note;       ///< why features were not used, if so
};

}  // namespace holebench::slice_loft
