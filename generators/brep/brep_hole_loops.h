// The holes left in a planar polyhedron when whole faces are removed, with their labels
// read off the exact B-Rep (face loops, plane normals): the construction-side labelling of
// outer holes.
#pragma once

#include "core/case.h"
#include "generators/brep/polyhedron.h"

#include <vector>

namespace holebench::generators::brep {

/// One hole loop of the kept faces, at B-Rep level.
struct BrepHoleLoop {
  /// Faces (= region ids) along the loop, in the order in which the mesh's boundary
  /// halfedges run (the hole on their left), one entry per visit.
  std::vector<int> regions;
  /// Per visit: 0 if the loop runs along that face's outer loop, i > 0 for inner loop i-1.
  std::vector<int> face_loops;
  /// transitions[i]: convexity of the edge between regions[i] and regions[i + 1] at the
  /// vertex where the loop passes from one to the other.
  std::vector<Convexity> transitions;
  std::vector<Point> transition_points;  ///< the transition vertices, same order
  std::vector<Point> points;             ///< the loop's polygon vertices, in loop order
  /// Faces whose boundary the loop touches that are removed.
  std::vector<int> adjacent_removed_faces;
};

/// The hole loops of the faces not in `removed` (a flag per face), each starting at a
/// transition vertex, ordered by their smallest vertex. Throws std::logic_error when a
/// loop touches itself at a vertex or a transition passes through a third face.
std::vector<BrepHoleLoop> brep_hole_loops(const PolyhedronTopology& topology,
                                          const std::vector<char>& removed);

}  // namespace holebench::generators::brep
