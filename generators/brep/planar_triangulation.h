// Constrained Delaunay triangulation of a planar polygonal domain (the only CGAL translation
// unit of the B-Rep generator).
#pragma once

#include <array>
#include <vector>

namespace holebench::generators::brep {

/// A polygonal domain in the plane: closed loops of points (the constraints) and free
/// interior points.
struct PlanarDomain {
  std::vector<std::array<double, 2>> points;
  /// Closed loops as indices into `points` (last point connects to the first). The domain
  /// is the set of points inside an odd number of loops.
  std::vector<std::vector<int>> loops;
};

/// The constrained Delaunay triangulation of `domain.points` with every loop edge as a
/// constraint, restricted to the domain. Triangles are counter-clockwise index triples.
/// \pre The loops are simple, do not touch each other and no free point lies on a loop, so
///      that no Steiner point is created on a constrained edge (checked: throws
///      std::logic_error otherwise). Deterministic: the same domain gives the same triangles
///      in the same order.
std::vector<std::array<int, 3>> triangulate_domain(const PlanarDomain& domain);

}  // namespace holebench::generators::brep
