// Whether a patch just added to a mesh intersects itself or the mesh around it: the check a
// closing makes before it keeps a triangulation that need not be an embedding.
#pragma once

#include "core/mesh.h"

#include <cstddef>
#include <vector>

namespace holebench {

/// The pairs of faces that intersect other than in a shared vertex or edge
/// (CGAL::Polygon_mesh_processing::self_intersections, exact predicates) among `patch` and
/// the faces within `rings` vertex rings of the patch's vertices, counting only pairs with at
/// least one face of `patch`. Faces farther away are not tested.
std::size_t patch_intersections(const Mesh& mesh, const std::vector<FaceHandle>& patch,
                                int rings = 2);

}  // namespace holebench
