// Orthogonal solids built from unit cells, converted to a planar polyhedron: an easy way to
// model plates, pockets, blocks, notches, steps and tunnels exactly.
#pragma once

#include "generators/brep/polyhedron.h"

#include <array>
#include <vector>

namespace holebench::generators::brep {

using CellIndex = std::array<int, 3>;

/// A set of occupied unit cells in a box of `dims` cells; cell (i, j, k) spans
/// [i, i + 1] x [j, j + 1] x [k, k + 1] times `cell` (model units).
class VoxelSolid {
 public:
  explicit VoxelSolid(CellIndex dims, double cell = 1.0);

  /// Occupies the cells of the box [lo, hi) (cell indices).
  VoxelSolid& fill(CellIndex lo, CellIndex hi);
  /// Empties the cells of the box [lo, hi).
  VoxelSolid& carve(CellIndex lo, CellIndex hi);

  bool occupied(CellIndex c) const;
  CellIndex dims() const { return dims_; }
  double cell() const { return cell_; }

 private:
  CellIndex dims_;
  double cell_;
  std::vector<char> cells_;
};

/// The boundary of the solid as maximal planar faces: the connected sets of coplanar cell
/// sides with the same outward normal, each with its outer loop and its inner loops. Loops
/// keep every cell corner on them (collinear points included), so that faces along an edge
/// share their points exactly. Faces are ordered by axis, side (- then +), plane
/// coordinate and first cell side. Throws std::invalid_argument where two cells touch only
/// along an edge or a face touches itself at a point (a non-manifold solid).
Polyhedron to_polyhedron(const VoxelSolid& solid);

}  // namespace holebench::generators::brep
