// The faces within a number of rings of a set of vertices: ring 1 is the faces with a vertex
// in the set, ring k + 1 adds the faces with a vertex on a face of ring k.
#pragma once

#include "core/mesh.h"

#include <vector>

namespace holebench {

/// By face index: 1 for the faces within `rings` rings of `seeds`, else 0.
std::vector<char> faces_within_rings(const Mesh& mesh, const std::vector<VertexHandle>& seeds,
                                     int rings);

}  // namespace holebench
