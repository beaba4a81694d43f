// Sharp features of a segmented mesh: sharp edges classified convex or reflex, chained
// into polylines, and corners (vertices where three or more regions meet) with the
// convexity signature of their sharp edges.
#pragma once

#include "core/hole_labels.h"
#include "core/mesh.h"
#include "core/region_segmentation.h"

#include <string>
#include <vector>

namespace holebench {

struct SharpEdgeChain {
  std::vector<VertexHandle> vertices;       ///< in order along the chain
  std::vector<EdgeHandle> edges;            ///< edges[i] joins vertices[i] and vertices[i + 1]
  Convexity convexity = Convexity::Convex;  ///< the convexity of (most of) its edges
  bool closed = false;                      ///< the chain is a loop
  int regions[2] = {kNoRegion, kNoRegion};  ///< the two regions it separates
  double length = 0.0;
};

struct Corner {
  VertexHandle vertex;
  std::vector<Convexity> edge_convexity;  ///< per incident sharp edge, sorted convex first
  /// "c" per convex and "r" per reflex sharp edge, convex first: "ccc", "ccr", "crr", ...
  std::string signature() const;
};

struct FeatureOptions {
  SegmentationOptions segmentation;  ///< regions and sharp edges come from this
  /// Take the regions from the mesh's region ids (e.g. B-Rep faces) instead of segmenting;
  /// sharp edges are then the borders between two regions whose dihedral angle exceeds
  /// segmentation.sharp_angle_degrees (a tangent border, as along a fillet, is not sharp), or
  /// planar_sharp_angle_degrees between two planar regions.
  bool regions_from_mesh = false;
  /// With regions_from_mesh: a border between two planar regions is sharp where their
  /// dihedral angle exceeds this (degrees). Two planes meet tangentially only where they are
  /// one plane, so a draft of a few degrees between two planar B-Rep faces is an edge of the
  /// model, where a curved face's border needs the larger threshold above (its facets meet
  /// the next face at an angle that depends on the tessellation).
  double planar_sharp_angle_degrees = 0.1;
};

struct FeatureAnalysis {
  SegmentationResult segmentation;
  std::vector<char> edge_is_sharp;        ///< per edge index
  std::vector<Convexity> edge_convexity;  ///< per edge index (meaningful where sharp)
  std::vector<SharpEdgeChain> chains;
  std::vector<Corner> corners;
};

/// Segments `mesh` into regions and analyses its sharp edges and corners. Chains run between
/// corners (vertices with other than two incident sharp edges) or close on themselves; a
/// chain never changes region pair. Deterministic.
FeatureAnalysis analyse_features(const Mesh& mesh, const FeatureOptions& options = {});

}  // namespace holebench
