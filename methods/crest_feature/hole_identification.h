// Hole identification (crest-line paper, section 3.3): boundary edges (one adjacent
// triangle) traced into closed loops; each loop is a hole.
#pragma once

#include "core/boundary_loops.h"
#include "core/mesh.h"

#include <vector>

namespace holebench::crest_feature {

struct Hole {
  BoundaryLoop loop;                   ///< boundary halfedges, in order
  std::vector<VertexHandle> vertices;  ///< loop order (from-vertex of each halfedge)
  Point centroid{0, 0, 0};
  /// Equation 4: a = sum of the boundary edge lengths / n.
  double average_edge_length = 0.0;
  double radius = 0.0;  ///< largest distance of a boundary vertex from the centroid
};

/// Every hole of `mesh`, in the order of find_boundary_loops.
std::vector<Hole> identify_holes(const Mesh& mesh);

}  // namespace holebench::crest_feature
