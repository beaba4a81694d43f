// Hole partitioning (crest-line paper, section 3.4.4): the hole is traced again along its
// boundary edges and its feature lines, which splits it into sub-holes at the feature lines.
#pragma once

#include "methods/crest_feature/feature_line_interpolation.h"
#include "methods/crest_feature/hole_identification.h"

#include <string>
#include <vector>

namespace holebench::crest_feature {

/// A node of a sub-hole: a mesh vertex (index >= 0) or a new point (-1 - index into
/// HolePartition::new_points).
using Node = int;
inline Node new_point_node(int index) {
  return -1 - index;
}
inline int new_point_index(Node node) {
  return -1 - node;
}

struct HolePartition {
  std::vector<Point> new_points;  ///< interpolated feature points and the corner
  /// Closed loops of nodes; each runs in the direction of the hole's boundary halfedges
  /// where it follows them, so a patch that follows each loop is oriented like the mesh.
  std::vector<std::vector<Node>> sub_holes;
  std::vector<Node> feature_nodes;   ///< the nodes on feature lines (interior and corner)
  std::vector<std::string> dropped;  ///< feature lines left out, and why
  /// The hole's island loops (not in the paper), as nodes in loop order; filling places each
  /// in the sub-hole around it.
  std::vector<std::vector<Node>> islands;
};

/// Splits the hole's loop by each feature line in turn (a pair's line is a chord between
/// two boundary vertices; a corner's first two lines make one chord through the corner, each
/// further line a chord from its feature point to the corner; a corner link, of the user's
/// corner graph, a chord between two corners). A line whose ends are not on one current
/// sub-hole (it would cross an earlier line) or that would leave a sub-hole with fewer than
/// three nodes is dropped.
HolePartition partition_hole(const Hole& hole, const FeatureLines& lines);

}  // namespace holebench::crest_feature
