// Real holes: the boundary loops an open mesh already has (a scan's gaps, a part exported with
// faces missing), as cases.
//
//   file/<stem>/hole/<i>             hole i of the mesh as it is: no ground truth; the
//                                    evaluation reports what needs none (validity, the patch's
//                                    self-intersections, normal jump across the hole's boundary,
//                                    dihedral angles inside the patch, triangle quality)
//   file/<stem>/hole/<i>/rings-<r>   the same hole enlarged by removing the r rings of faces
//                                    around it (r = 1, 2, 4): the removed rings are the ground
//                                    truth, and every metric is reported
//
// The ring-removal truth follows Rojas et al., who made ground truth for real holes by moving
// them onto complete surfaces: here the surface around the hole is the complete surface, and
// the hole is made larger by its own rings (docs/generators.md, "Real holes").
//
// Which loops are holes: a loop is the border of an open sheet, not a hole, when its vector
// area (|1/2 sum p_i x p_(i+1)|, the area it spans) is at least half the surface area of its
// connected component. A surface that encloses a volume spans a hole with a small part of its
// area (the vector area of a closed surface is zero, so a hole's equals the missing part's);
// a sheet spans its border with about all of its area (a flat sheet: exactly).
#pragma once

#include "core/boundary_loops.h"
#include "core/case.h"
#include "core/mesh.h"

#include <string>
#include <vector>

namespace holebench::generators {

/// The ring counts of the ring-removal cases.
const std::vector<int>& ring_removal_counts();

struct MeshLoops {
  std::vector<BoundaryLoop> loops;  ///< find_boundary_loops(mesh)
  /// Indices into `loops` of the loops that are holes, in that order: hole i of the case ids
  /// is loops[holes[i]].
  std::vector<int> holes;
  /// ... and of the loops that are the border of an open sheet.
  std::vector<int> sheet_borders;
};

/// The mesh's boundary loops sorted into holes and sheet borders (the rule in the file comment).
MeshLoops classify_boundary_loops(const Mesh& mesh);

/// The loop of hole `hole` (an index into MeshLoops::holes). Throws std::invalid_argument where
/// there is no such hole.
const BoundaryLoop& hole_loop(const MeshLoops& loops, int hole);

/// The faces within `rings` rings of `loop`: ring 1 is the faces with a vertex on the loop,
/// ring k + 1 adds the faces with a vertex on a face of ring k. Sorted face indices.
std::vector<int> faces_around_loop(const Mesh& mesh, const BoundaryLoop& loop, int rings);

/// Case `id` for hole `hole` (an index into MeshLoops::holes) of the open mesh `mesh`, without
/// ground truth: the input and the complete model are the mesh; one HoleTruth with target
/// "real_hole" and no removed faces. Throws std::invalid_argument where there is no such hole.
Case make_real_hole_case(const Mesh& mesh, int hole, const std::string& id);

/// Case `id`: hole `hole` enlarged by `rings` rings (faces_around_loop; a face whose removal
/// would leave a non-manifold vertex is removed too, generators/hole_punch.h). The complete
/// model is the open mesh, the input the mesh without the rings; the truth's removed faces are
/// the rings, target "rings-<r>". Throws std::invalid_argument where there is no such hole,
/// InvalidInputError where removing the rings leaves no face.
Case make_ring_removal_case(const Mesh& mesh, int hole, int rings, const std::string& id);

}  // namespace holebench::generators
