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
};

/// Where a patch is trimmed: the portion's plane (u, w), a projection that is exact and
/// keeps collinear boundary points collinear, or the surface's own domain (u, s), s the arc
/// length along the sections, which stays one to one where the boundary folds over in the
/// plane (a hole around an edge or a curved face).
enum class TrimmingDomain { PortionPlane, Surface };

/// Facets of one trimmed patch. Triangle indices: the portion's boundary nodes first, then
/// the islands' nodes in order, then `interior`. Oriented like the mesh (they use the
/// boundary halfedges).
struct PatchTessellation {
  std::vector<Point> interior;
  std::vector<std::array<int, 3>> triangles;
  TrimmingDomain domain = TrimmingDomain::PortionPlane;
  TriangulationFailure failure = TriangulationFailure::None;
  bool ok = false;
  std::string error;
};

/// Trims in the portion's plane, and where the boundary folds there, on the surface.
PatchTessellation tessellate_trimmed_patch(const Portion& portion, const LoftedPatch& patch,
                                           double edge_length,
                                           const TessellationOptions& options = {});

struct SewingResult {
  bool ok = false;
  std::string error;
  std::size_t new_faces = 0, new_vertices = 0;
};

/// Adds the facets of every portion of one hole to `mesh`, the missing features' points as
/// shared vertices. All or nothing: on failure the mesh is left as it was.
SewingResult sew_patches(Mesh& mesh, const std::vector<Portion>& portions,
                         const std::vector<PatchTessellation>& tessellations,
                         const MissingFeatures& features);

}  // namespace holebench::slice_loft
