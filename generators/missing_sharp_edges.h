// The ground truth's missing sharp edges: the sharp edges of the complete model that a hole
// removed (both of their faces removed), chained into polylines.
#pragma once

#include "core/features.h"
#include "core/mesh.h"

#include <variant>
#include <vector>

namespace holebench::generators {

/// Sharp edges are the borders between two of the mesh's regions (B-Rep faces), whatever
/// their dihedral angle. The missing ones are chained among themselves: a polyline runs on
/// through every vertex where exactly two missing edges meet (also a corner whose other
/// edges are kept) and ends elsewhere or where it closes. Open polylines come first, then
/// closed ones, each pass from the lowest vertex index.
struct RegionBorderEdges {};

/// Sharp edges are those of a feature analysis of the mesh (`edge_is_sharp`: the borders of
/// its segmented regions, or of the mesh's regions where the dihedral angle exceeds its
/// threshold). The missing ones follow the analysis' chains, in their order, each cut where
/// one of its edges is kept: a polyline ends at every corner and wherever the pair of regions
/// changes, even if the next edge is missing too.
struct FeatureChainEdges {
  const FeatureAnalysis& features;
};

/// Which edges are sharp and how the missing ones are chained. The two generator families
/// have always differed here; each keeps its own so that its cases stay the same.
using SharpEdges = std::variant<RegionBorderEdges, FeatureChainEdges>;

/// The sharp edges of `complete` whose two faces are both removed (`removed` per face
/// index, non-zero for a removed face), chained into polylines of points.
std::vector<std::vector<Point>> missing_sharp_edges(const Mesh& complete,
                                                    const std::vector<char>& removed,
                                                    const SharpEdges& sharp_edges);

/// The corners of `features` whose faces are all removed: the truth's missing corners.
std::vector<Point> missing_corners(const Mesh& complete, const std::vector<char>& removed,
                                   const FeatureAnalysis& features);

}  // namespace holebench::generators
