// Feature points (crest-line paper, sections 3.4.1 and 3.4.2): detected feature points
// where crest lines meet a hole boundary; the automatic pairing rule and corner rule used
// when no user answers; and the user step (pairing, adjusting, naming the corner triple)
// through the methods' User interface.
#pragma once

#include "methods/crest_feature/crest_lines.h"
#include "methods/crest_feature/hole_identification.h"
#include "methods/user.h"

#include <array>
#include <optional>
#include <vector>

namespace holebench::crest_feature {

struct FeaturePointOptions {
  /// A crest line whose end lies within this many mean boundary edge lengths a (eq. 4) of
  /// the hole boundary, extrapolated along its direction, meets the boundary there.
  double reach_edges = 4.0;
  /// A crest line ray passes a boundary vertex if it comes within this many a of it.
  double ray_tolerance_edges = 1.5;
  /// Crest points within this many a of a feature point give its tangent.
  double tangent_radius_edges = 6.0;
  /// Detected feature points closer than this many a are one (the stronger line wins): two
  /// crest-line ends that reach the boundary at the same place. The paper merges nothing; 2.5a
  /// (the value before issue 16) made one point of the two ends of a crease on small holes
  /// (a 9-vertex hole across a cylinder's rim: 2.3a apart), so the crease got no pair.
  double merge_edges = 0.5;
  /// 3.4.2: a point the user moves or adds takes the crest line of the detected point within
  /// this many a of it (for its tangent), else the nearest crest line.
  double adopt_crest_line_edges = 2.5;
  /// Automatic rule: two feature points are paired if the chord between them is within this
  /// angle of both tangents (degrees), best pairs first.
  double pair_max_angle_degrees = 35.0;
  /// Automatic rule: three feature points are a corner triple if their tangent lines pass
  /// within this angle (degrees) of their least-squares meeting point inside the hole, and
  /// fit it better than any pair among them.
  double corner_max_angle_degrees = 25.0;
  /// 3.4.1: a detected feature point is where the extrapolated crest line crosses a boundary
  /// edge (the point of the edge nearest the ray, within `ray_tolerance_edges`), inserted
  /// into that edge (boundary_edge_split.h): the paper's "intersection point between the
  /// crest line ... with the hole boundary", the default. Off (the project's option, in
  /// crest_feature_plus): the boundary vertex nearest the ray, within `ray_tolerance_edges`.
  /// Where the boundary runs along the ray, its edges hold no single crossing: the feature
  /// point is the vertex where the line enters the hole, as below (before this rule, the
  /// first edge along the ray was taken and its sub-hole folded: 5 to 38 intersecting face
  /// pairs on crease/fandisk/1-3).
  bool on_boundary_edges = true;
  /// A crossing within this fraction of the edge's length from one of its vertices is that
  /// vertex (no sliver triangles). Also: where the hole's boundary runs along a crest line's
  /// ray (each next boundary vertex ahead and within this fraction of its edge's length of
  /// the ray), the feature point is the last vertex of that run, where the line enters the
  /// hole (a crease whose first edges the hole's boundary follows).
  double edge_snap_fraction = 0.2;
};

struct FeaturePoint {
  int loop_index = 0;  ///< index into Hole::vertices
  Point position{0, 0, 0};
  /// Set where the point lies inside the boundary edge from vertex `loop_index` to the next
  /// (the edge's parameter in (0, 1)), until it is inserted there (insert_feature_points).
  std::optional<double> edge_parameter;
  Point tangent{0, 0, 0};  ///< unit: the crest line's direction as it enters the hole
  int crest_line = -1;     ///< index into CrestLines::lines; -1 none
};

struct HoleFeatures {
  std::vector<FeaturePoint> points;
  std::vector<std::array<int, 2>> pairs;     ///< one feature line per pair
  std::optional<std::array<int, 3>> corner;  ///< three feature lines meeting at a corner
  /// Not in the paper: the user's corner graph (FeaturePointProposal::more_corners and
  /// corner_links). The automatic rule proposes none.
  std::vector<std::vector<int>> more_corners;
  std::vector<std::array<int, 2>> corner_links;  ///< indices into corners(): triple first
};

/// The hole's corners as lists of feature points: the triple first where there is one, then
/// `more_corners`.
std::vector<std::vector<int>> corners(const HoleFeatures& features);

/// 3.4.1: the feature points of `hole` (crest lines ending at its boundary), then the
/// automatic rule of 3.4.2 (what the method proposes before a user answers): corner triple
/// first if one fits, then pairs by the angle rule. Deterministic.
HoleFeatures detect_feature_points(const Mesh& mesh, const Hole& hole, const CrestLines& crest,
                                   const FeaturePointOptions& options = {});

/// 3.4.2: asks `user` about `proposed` and returns its answer, feature points snapped to the
/// hole's boundary vertices, tangents re-estimated from the crest lines where a point moved
/// or was added. Invalid pairs or triples in the answer are dropped.
HoleFeatures review_feature_points(const Mesh& mesh, const Hole& hole, int hole_index,
                                   const CrestLines& crest, const HoleFeatures& proposed,
                                   User& user, const FeaturePointOptions& options = {});

/// The unit tangent at boundary vertex `loop_index` from the crest points of line
/// `preferred` (or of the crest line nearest the point), pointing into the hole; from the
/// normals of the boundary triangles on either side where no crest line is near.
Point estimate_tangent(const Mesh& mesh, const Hole& hole, const CrestLines& crest, int loop_index,
                       int preferred, const FeaturePointOptions& options);

}  // namespace holebench::crest_feature
