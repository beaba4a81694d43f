// A mesh made of some faces of another: the region a metric is restricted to (the patch
// of new faces, the removed faces of the complete model).
#pragma once

#include "core/case.h"
#include "core/mesh.h"

#include <vector>

namespace holebench {

/// The faces `faces` (indices into `mesh`) as a mesh of their own, in the order given,
/// with their points, regions and provenance. Faces that would make the subset
/// non-manifold are still kept: each face gets its own three vertices where OpenMesh
/// refuses to share them, so the subset always covers exactly the listed triangles.
Mesh face_subset(const Mesh& mesh, const std::vector<int>& faces);

/// The faces of the complete model removed to make the case's holes, each once, in index
/// order: the hole region's truth (as a mesh: face_subset(c.complete, removed_faces(c))).
std::vector<int> removed_faces(const Case& c);

/// The indices of the faces of `mesh` marked `Provenance::New`, in index order.
std::vector<int> new_face_indices(const Mesh& mesh);
/// The same: `known` where the caller has them (not null), else found here into `found`.
const std::vector<int>& new_face_indices(const Mesh& mesh, const std::vector<int>* known,
                                         std::vector<int>& found);
/// The indices of the vertices marked new (is_new), deleted ones left out, in index order.
std::vector<int> new_vertex_indices(const Mesh& mesh);

}  // namespace holebench
