// Steps V and VI of the slice paper (sections 4.5, 4.6): each lofted patch trimmed by the
// hole's and islands' boundaries in its parameter domain, faceted by a constrained Delaunay
// triangulation (CGAL) whose constraints are the original boundary edges (so the facets
// conform to them), and the facets sewn into the mesh along those edges.
#pragma once

#include "methods/common/planar_polygon_triangulation.h"
#include "methods/slice_loft/composite_surface.h"

#include <array>
#include <string>
#include <vector>

namespace holebench::slice_loft {

struct TessellationOptions {
  double spacing_edges = 1.0;  ///< interior points about this many boundary-edge lengths apart
  double clearance = 0.45;     ///< no interior point nearer the boundary (x spacing)
  /// The paper's comparison (Table 2, right column): facet the discrete section points
  /// themselves instead of points of the lofted surface.
  bool direct = false;
  /// A missing-feature point nearer a hole or island vertex than this many mean
  /// boundary-edge lengths is that vertex (the missing edge runs along the boundary there;
  /// pinched_portions.h).
  double feature_snap_edges = 0.25;
  /// A facet edge between two boundary vertices that the mesh already joins by an inner edge
  /// would give that edge three faces: such a chord gets a point at its middle and the
  /// patch is triangulated again, at most this many times.
  int max_chord_splits = 8;
  /// Trim on the developed disc where the plane and the surface domain both fold.
  bool developed_disc = true;
  /// Trim in the portion's plane first (a projection; the project's option) instead of the
  /// paper's order, the lofted surface's own parameter domain first (section 4.5: the
  /// composite surface split by the boundary edges projected onto it, figure 14b).
  bool plane_first = false;
};

/// Where a patch is trimmed: the portion's plane (u, w), a projection that is exact and
/// keeps collinear boundary points collinear; the surface's own domain (u, s), s the arc
/// length along the sections, which stays one to one where the boundary folds over in the
/// plane (a hole around an edge or a curved face); or, where the boundary's pre-image folds
/// on the surface too, the boundary developed onto a disc (developed_disc.h), whose points
/// are mapped to the surface's (u, s) by mean value coordinates.
enum class TrimmingDomain { PortionPlane, Surface, DevelopedDisc };

/// Facets of one trimmed patch. Triangle indices: the portion's boundary nodes first, then
/// the islands' nodes in order, then `interior`. Oriented like the mesh (they use the
/// boundary halfedges).
struct PatchTessellation {
  std::vector<Point> interior;
  std::vector<std::array<int, 3>> triangles;
  std::size_t chords_split = 0;  ///< points added in chords the mesh already has
  TrimmingDomain domain = TrimmingDomain::PortionPlane;
  TriangulationFailure failure = TriangulationFailure::None;
  bool ok = false;
  std::string error;
};

/// Trims on the surface's (u, s) domain, where the boundary folds there in the portion's
/// plane (`plane_first`: the plane first, then the surface), and where it folds in both on the
/// developed disc (not for slice_direct, whose section points have
/// no place on the disc). `mesh`
/// is the holed input (for the chords it already has).
PatchTessellation tessellate_trimmed_patch(const Mesh& mesh, const Portion& portion,
                                           const LoftedPatch& patch, double edge_length,
                                           const TessellationOptions& options = {});

struct SewingResult {
  bool ok = false;
  std::string error;
  std::size_t new_faces = 0, new_vertices = 0;
};

/// Adds the facets of every portion of one hole to `mesh`, the missing features' points as
/// shared vertices. All or nothing: on failure the mesh is left as it was, and it fails where
/// a facet would make the mesh non-manifold or where the facets leave a boundary edge of
/// `hole_boundary` or a new vertex on a boundary (the patch does not close the hole).
SewingResult sew_patches(Mesh& mesh, const std::vector<Portion>& portions,
                         const std::vector<PatchTessellation>& tessellations,
                         const MissingFeatures& features,
                         const std::vector<HalfedgeHandle>& hole_boundary);

}  // namespace holebench::slice_loft
