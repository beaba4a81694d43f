// Whether a patch just added to a mesh intersects itself or the mesh around it: the check a
// closing makes before it keeps a triangulation that need not be an embedding.
#pragma once

#include "core/mesh.h"
#include "core/method_result.h"

#include <cstddef>
#include <vector>

namespace holebench {

/// The pairs of faces that intersect other than in a shared vertex or edge
/// (CGAL::Polygon_mesh_processing::self_intersections, exact predicates) among `patch` and
/// the faces within `rings` vertex rings of the patch's vertices, counting only pairs with at
/// least one face of `patch`. Faces farther away are not tested.
std::size_t patch_intersections(const Mesh& mesh, const std::vector<FaceHandle>& patch,
                                int rings = 2);

/// The defect name a method's hole report carries where its patch intersects (HoleReport).
inline constexpr char kSelfIntersectingPatch[] = "self_intersecting_patch";

/// A method's check of its own patch for one hole: the faces `mesh` gained from index
/// `first_new_face` on, tested by patch_intersections. Where they intersect, `report.defect`
/// is kSelfIntersectingPatch and its note says how many face pairs. Returns the pairs.
std::size_t check_patch_intersections(const Mesh& mesh, std::size_t first_new_face,
                                      HoleReport& report);

}  // namespace holebench
