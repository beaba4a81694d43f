// The users that answer a method's questions: none at all, or an oracle that answers from
// the case's ground truth (which the harness may see and a method may not).
#pragma once

#include "core/case.h"
#include "methods/user.h"

#include <memory>
#include <optional>
#include <string>

namespace holebench::harness {

/// Answers from the ground truth: agrees to closing a hole only where the hole it is
/// about (the ground-truth hole whose removed faces lie nearest the proposal's centroid)
/// is expected to be closed automatically. Each refusal counts as an intervention.
///
/// Feature points (crest-line paper 3.4.2): the true feature points of the hole are the
/// ends of its missing sharp edges on the hole boundary (ends at a missing corner are not),
/// each snapped to the nearest proposed boundary point; the true pairs are the two ends of
/// one missing edge; the true corner triple the ends of the three missing edges that meet
/// at its missing corner. A proposed point within three mean boundary edge lengths of a true
/// one (greedy, nearest first) is matched to it. One intervention each: a matched point
/// moved to another boundary vertex, a proposed point removed, a true point added, a pair
/// made or undone, the corner triple named, changed or cleared. With the corner graph
/// (OracleOptions), a missing edge that bends sharply inside the hole is two edges meeting at
/// a corner of the graph.
///
/// Crest lines (3.4.2, the paper's figures 2 and 9c): at a feature point within
/// `crest_match_edges` mean boundary edge lengths of a missing sharp edge's end (not a missing
/// corner), the true direction is the one in which that edge leaves the boundary (towards its
/// point one mean edge length in). Where the method's direction differs from it by more than
/// `crest_max_angle_degrees`, the oracle replaces it: one intervention of kind
/// "crest_line_direction" each.
struct OracleOptions {
  double crest_max_angle_degrees = 15.0;
  double crest_match_edges = 1.0;
  /// Not in the paper, whose user names one corner triple: the user also names every further
  /// missing corner that two or more missing edges reach from the boundary (four-edge
  /// corners, two corners joined by an edge) and draws the edges between such corners
  /// (FeaturePointProposal::more_corners, corner_links). False: the paper's user step only.
  bool corner_graph = true;
  /// With the corner graph: a missing edge from boundary to boundary that turns by more than
  /// this angle at a point inside the hole (a bend, no missing corner) is drawn as two feature
  /// lines meeting at the bend, a corner of the graph reached by two lines; the paper's
  /// Catmull-Rom spline (eq. 3) cannot bend there. The fandisk's two-crease hole has one
  /// (about 100 degrees).
  double bend_angle_degrees = 45.0;
};

class OracleUser final : public User {
 public:
  explicit OracleUser(const Case& c, OracleOptions options = {}) : case_(c), options_(options) {}
  std::string kind() const override { return "oracle"; }
  bool agree_to_closing(const ClosingProposal& proposal) override;
  FeaturePointProposal review_feature_points(const FeaturePointProposal& proposal) override;
  CrestLineProposal review_crest_lines(const CrestLineProposal& proposal) override;

 private:
  const Case& case_;
  OracleOptions options_;
};

/// The unit direction in which the missing sharp edge of `truth` whose end (not a missing
/// corner) lies nearest `at`, within `tolerance`, leaves that end: towards its point at arc
/// length `reach` (or its other end). nullopt where no such end is near.
std::optional<Point> true_crease_direction(const HoleTruth& truth, const Point& at,
                                           double tolerance, double reach);

/// The index of the ground-truth hole nearest `point` (by its removed faces' centroids in
/// the complete model), or -1 if the case has no hole.
int nearest_truth_hole(const Case& c, const Point& point);

/// "no_user" or "oracle"; throws std::invalid_argument for anything else.
void check_user_kind(const std::string& kind);
std::unique_ptr<User> make_user(const std::string& kind, const Case& c);

}  // namespace holebench::harness
