// Punching holes: removing a set of faces from a complete mesh so that the rest stays a
// valid manifold surface with boundary.
#pragma once

#include "core/mesh.h"

#include <vector>

namespace holebench::generators {

/// Indices of the faces whose centroid lies within `radius` of `center`.
std::vector<int> faces_in_ball(const Mesh& mesh, const Point& center, double radius);

struct PunchResult {
  Mesh holed;                           ///< the complete mesh without the removed faces
  std::vector<int> removed_faces;       ///< sorted face indices in the complete mesh
  std::vector<int> vertex_to_complete;  ///< holed vertex index -> complete vertex index
};

/// Removes `faces` from `complete`. Faces are added to the removed set where removing
/// only `faces` would leave a non-manifold vertex (two boundary loops touching at a
/// vertex) or a face hanging by no edge. The holed mesh keeps the complete mesh's vertex
/// order (unused vertices dropped), region ids and provenance.
PunchResult punch_faces(const Mesh& complete, std::vector<int> faces);

}  // namespace holebench::generators
