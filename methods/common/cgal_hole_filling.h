// CGAL's hole filling (CGAL::Polygon_mesh_processing, after Liepa 2003) applied to every
// boundary loop of a mesh: the one translation unit that includes it, shared by the
// baselines liepa_cgal (triangulate, refine, fair) and cgal_triangulate (triangulate only).
#pragma once

#include "core/method_result.h"

namespace holebench {

/// Which of CGAL's three hole-filling functions runs on each hole.
enum class CgalHoleSteps {
  Triangulate,            ///< triangulate_hole: no new vertices
  TriangulateRefine,      ///< triangulate_and_refine_hole
  TriangulateRefineFair,  ///< triangulate_refine_and_fair_hole
};

struct CgalHoleFillingOptions {
  CgalHoleSteps steps = CgalHoleSteps::TriangulateRefineFair;
  double density_control_factor = 1.4142135623730951;  ///< refinement; CGAL's default sqrt(2)
  unsigned fairing_continuity = 1;                     ///< fairing: 0 C0, 1 C1, 2 C2
  /// Search the triangulation among the faces of a 3D Delaunay triangulation of the loop
  /// (CGAL's default true). Off by default here: on co-spherical loops that triangulation
  /// depends on memory addresses, and the same job gave different patches (docs/methods.md).
  bool use_delaunay_triangulation = false;
  /// Try a 2D constrained Delaunay triangulation of the loop projected onto its fitted plane
  /// first, where the loop is near planar (CGAL's threshold: a quarter of the loop's bounding
  /// box height).
  bool use_2d_constrained_delaunay_triangulation = false;
};

/// The name of the CGAL function `steps` runs ("triangulate_hole", ...): the phase name.
const char* cgal_function_name(CgalHoleSteps steps);

/// Fills every boundary loop of `holed` (loops found before any filling). New faces and
/// vertices are `Provenance::New` and belong to no region. One HoleReport per loop; status
/// ok when every loop was closed, failed when none was, partial otherwise. A loop refined
/// but not faired (CGAL's fairing solver failed) is closed with the fallback
/// "refined_without_fairing".
MethodResult fill_holes_cgal(const Mesh& holed, const CgalHoleFillingOptions& options);

}  // namespace holebench
