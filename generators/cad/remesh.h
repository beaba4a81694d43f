// Isotropic remeshing of a CAD mesh with its sharp edges kept (CGAL).
//
// The CAD meshes of CGAL's data set are coarse, with long thin triangles: a hole of 2 % of
// the diagonal would remove one triangle or none. Remeshing to a uniform edge length makes
// hole sizes meaningful. CGAL projects every new vertex back onto the input surface and
// keeps the sharp edges as constrained polylines, so the shape (the ground truth) is the
// data set's; only its tessellation changes.
#pragma once

#include "core/mesh.h"

namespace holebench::generators {

struct RemeshOptions {
  double target_edge_length = 0.0;    ///< model units
  double sharp_angle_degrees = 30.0;  ///< edges with a larger dihedral angle are kept
  unsigned iterations = 3;
  /// Keep the input's region ids (e.g. B-Rep faces): the borders between regions are kept
  /// like sharp edges and every new face takes the region of the face it was made from.
  bool keep_regions = false;
};

/// The remeshed surface as a new, compact mesh (every element `Provenance::Original`; no
/// regions unless options.keep_regions). Deterministic. Throws AlgorithmError if the result is not
/// a valid mesh.
Mesh remesh_isotropic(const Mesh& mesh, const RemeshOptions& options);

}  // namespace holebench::generators
