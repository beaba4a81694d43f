// The human in the loop. Where a paper asks a person (agree to an automatic closing,
// pair feature points), a method asks this interface; the harness answers from the
// ground truth (an oracle user) or not at all (no user), and counts the interventions.
#pragma once

#include "core/mesh.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace holebench {

/// What a method proposes for one hole before closing it automatically.
struct ClosingProposal {
  int hole_index = 0;            ///< index of the hole in the method's detection order
  Point hole_centroid{0, 0, 0};  ///< where the hole is, so that an oracle can find its ground truth
  double hole_size = 0.0;
};

/// The crest-line paper's user step (section 3.4.2) for one hole: the feature points the
/// method detected on the hole boundary (where crest lines meet it), how it pairs them
/// (one feature line per pair) and, for a corner hole, the triple of feature points whose
/// feature lines meet at the missing corner. A user may move, add or remove feature points
/// (positions are snapped to the nearest boundary vertex by the method), re-pair them and
/// name or clear the corner triple.
struct FeaturePointProposal {
  int hole_index = 0;            ///< index of the hole in the method's detection order
  Point hole_centroid{0, 0, 0};  ///< where the hole is, so that an oracle can find its ground truth
  std::vector<Point> boundary;   ///< the hole's boundary vertices, in loop order
  std::vector<Point> feature_points;         ///< on the boundary (each one of `boundary`)
  std::vector<std::array<int, 2>> pairs;     ///< indices into feature_points
  std::optional<std::array<int, 3>> corner;  ///< indices into feature_points
  /// Not in the paper, whose user names one corner triple: the project's corner graph (see
  /// docs/crest_feature.md). Further missing corners inside the hole, each given by the
  /// feature points (two or more; indices into feature_points) whose lines end at it ...
  std::vector<std::vector<int>> more_corners;
  /// ... and feature lines between two corners: indices into the hole's corners, the triple
  /// `corner` first where there is one, then `more_corners` in order.
  std::vector<std::array<int, 2>> corner_links;
};

/// The crest-line paper's correction of crest lines (3.4.2, figures 2 and 9c) at the feature
/// points of one hole, after the points, pairs and corner are settled: the crest line's
/// direction as it enters the hole at each feature point (unit; it sets the Catmull-Rom
/// control points P0 and P3 of equation 3 and a corner's meeting point). A user may replace
/// any direction; an empty or zero answer keeps the method's.
struct CrestLineProposal {
  int hole_index = 0;            ///< index of the hole in the method's detection order
  Point hole_centroid{0, 0, 0};  ///< where the hole is, so that an oracle can find its ground truth
  std::vector<Point> boundary;   ///< the hole's boundary vertices, in loop order
  std::vector<Point> feature_points;  ///< the feature points (after review_feature_points)
  std::vector<Point> directions;  ///< per feature point: the crest line's direction into the hole
};

class User {
 public:
  virtual ~User() = default;

  /// "no_user" or "oracle": written into every record.
  virtual std::string kind() const = 0;

  /// The B-Rep paper's cases a and b: may the hole be closed automatically?
  virtual bool agree_to_closing(const ClosingProposal& proposal) = 0;

  /// The crest-line paper's user step (3.4.2): returns the feature points, pairs and corner
  /// triple to use for one hole. The default accepts the proposal unchanged.
  virtual FeaturePointProposal review_feature_points(const FeaturePointProposal& proposal) {
    return proposal;
  }

  /// The crest-line paper's crest-line correction (3.4.2): returns the crest lines'
  /// directions at the feature points of one hole. The default accepts them unchanged.
  virtual CrestLineProposal review_crest_lines(const CrestLineProposal& proposal) {
    return proposal;
  }

  /// How many times this user changed what the method would have done alone.
  int interventions() const { return interventions_; }
  /// The same count by kind (e.g. "feature_point_moved", "crest_line_direction").
  const std::map<std::string, int>& interventions_by_kind() const { return by_kind_; }

 protected:
  void count_intervention(const std::string& kind = "other") {
    ++interventions_;
    ++by_kind_[kind];
  }

 private:
  int interventions_ = 0;
  std::map<std::string, int> by_kind_;
};

/// No human: agrees to everything, accepts every proposal, never intervenes.
class NoUser final : public User {
 public:
  std::string kind() const override { return "no_user"; }
  bool agree_to_closing(const ClosingProposal&) override { return true; }
};

}  // namespace holebench
