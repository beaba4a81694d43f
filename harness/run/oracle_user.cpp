#include "harness/run/oracle_user.h"

#include "core/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace holebench::harness {

int nearest_truth_hole(const Case& c, const Point& point) {
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < c.holes.size(); ++i) {
    for (int f : c.holes[i].removed_faces) {
      const double d = (face_centroid(c.complete, c.complete.face_handle(f)) - point).norm();
      if (d < best_distance) {
        best_distance = d;
        best = static_cast<int>(i);
      }
    }
  }
  return best;
}

bool OracleUser::agree_to_closing(const ClosingProposal& proposal) {
  const int hole = nearest_truth_hole(case_, proposal.hole_centroid);
  if (hole < 0 || !case_.holes[hole].labels)
    return true;
  const bool agree = case_.holes[hole].labels->expected_decision == Decision::CloseAutomatically;
  if (!agree)
    count_intervention("closing_refused");
  return agree;
}

namespace {

// The true feature points of a hole: ends of its missing sharp edges on the hole boundary,
// the pairs (both ends of one edge) and the corner triple (the far ends of the edges that
// meet at a missing corner). Polylines that continue each other (they meet at a point that
// is no missing corner) are joined first.
// With the corner graph (not in the paper): every further missing corner with two or more
// edges reaching the boundary, and the edges between two such corners.
struct TrueFeatures {
  std::vector<Point> points;
  std::vector<std::array<int, 2>> pairs;
  std::optional<std::array<int, 3>> corner;
  std::vector<std::vector<int>> more_corners;
  std::vector<std::array<int, 2>> corner_links;
};

// The polylines of `edges` that run from boundary to boundary (neither end `at_corner`), cut
// where one turns by more than `bend_angle_degrees` at an inner point (a bend, appended to
// `bends`); unchanged where the angle is 180 or more. An edge that ends at a missing corner is
// left whole: a bend beside the corner would take the edge from the corner's lines.
std::vector<std::vector<Point>> cut_at_bends(const std::vector<std::vector<Point>>& edges,
                                             double bend_angle_degrees,
                                             const std::function<bool(const Point&)>& at_corner,
                                             std::vector<Point>& bends) {
  std::vector<std::vector<Point>> pieces;
  for (const auto& polyline : edges) {
    if (polyline.empty() || at_corner(polyline.front()) || at_corner(polyline.back())) {
      pieces.push_back(polyline);
      continue;
    }
    std::vector<Point> piece;
    for (std::size_t k = 0; k < polyline.size(); ++k) {
      piece.push_back(polyline[k]);
      if (k == 0 || k + 1 == polyline.size())
        continue;
      const Point in = polyline[k] - polyline[k - 1], out = polyline[k + 1] - polyline[k];
      const double c = OpenMesh::dot(in, out) / (in.norm() * out.norm());
      if (!(std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI > bend_angle_degrees))
        continue;
      bends.push_back(polyline[k]);
      pieces.push_back(std::move(piece));
      piece = {polyline[k]};
    }
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

TrueFeatures true_features(const HoleTruth& truth, double tolerance, const OracleOptions& options) {
  const bool corner_graph = options.corner_graph;
  auto same = [&](const Point& a, const Point& b) { return (a - b).norm() <= tolerance; };
  // The missing corners, then (with the corner graph) the bends of the missing edges: the
  // user draws a bent edge as two feature lines that meet at the bend.
  std::vector<Point> corner_points = truth.missing_corners;
  auto at_missing_corner = [&](const Point& p) {
    return std::any_of(truth.missing_corners.begin(), truth.missing_corners.end(),
                       [&](const Point& c) { return same(p, c); });
  };
  const std::vector<std::vector<Point>> edges =
      corner_graph ? cut_at_bends(truth.missing_edges, options.bend_angle_degrees,
                                  at_missing_corner, corner_points)
                   : truth.missing_edges;
  auto at_corner = [&](const Point& p) -> int {
    for (std::size_t i = 0; i < corner_points.size(); ++i) {
      if (same(p, corner_points[i]))
        return static_cast<int>(i);
    }
    return -1;
  };
  std::vector<std::array<Point, 2>> ends;
  for (const auto& polyline : edges) {
    if (polyline.size() >= 2)
      ends.push_back({polyline.front(), polyline.back()});
  }
  // Join polylines that continue each other.
  for (bool joined = true; joined;) {
    joined = false;
    for (std::size_t i = 0; i < ends.size() && !joined; ++i) {
      for (std::size_t j = i + 1; j < ends.size() && !joined; ++j) {
        for (int a = 0; a < 2 && !joined; ++a) {
          for (int b = 0; b < 2 && !joined; ++b) {
            if (!same(ends[i][a], ends[j][b]) || at_corner(ends[i][a]) >= 0)
              continue;
            ends[i] = {ends[i][1 - a], ends[j][1 - b]};
            ends.erase(ends.begin() + static_cast<std::ptrdiff_t>(j));
            joined = true;
          }
        }
      }
    }
  }
  TrueFeatures result;
  std::vector<std::vector<int>> corner_ends(corner_points.size());
  std::vector<std::array<int, 2>> between_corners;
  for (const auto& e : ends) {
    const int c0 = at_corner(e[0]), c1 = at_corner(e[1]);
    if (c0 >= 0 && c1 >= 0) {  // an edge between two missing corners meets no boundary
      if (c0 != c1)
        between_corners.push_back({c0, c1});
      continue;
    }
    if (c0 < 0 && c1 < 0) {
      const int i = static_cast<int>(result.points.size());
      result.points.push_back(e[0]);
      result.points.push_back(e[1]);
      result.pairs.push_back({i, i + 1});
      continue;
    }
    corner_ends[c0 >= 0 ? c0 : c1].push_back(static_cast<int>(result.points.size()));
    result.points.push_back(c0 >= 0 ? e[1] : e[0]);
  }
  std::vector<int> named(corner_ends.size(), -1);  // truth corner -> index among the named
  for (std::size_t c = 0; c < corner_ends.size(); ++c) {
    const auto& triple = corner_ends[c];
    if (triple.size() == 3 && !result.corner) {
      result.corner = std::array<int, 3>{triple[0], triple[1], triple[2]};
      named[c] = 0;
    }
  }
  if (!corner_graph)
    return result;
  int count = result.corner ? 1 : 0;
  for (std::size_t c = 0; c < corner_ends.size(); ++c) {
    if (named[c] < 0 && corner_ends[c].size() >= 2) {
      result.more_corners.push_back(corner_ends[c]);
      named[c] = count++;
    }
  }
  for (const auto& [c0, c1] : between_corners) {
    if (named[c0] >= 0 && named[c1] >= 0)
      result.corner_links.push_back({named[c0], named[c1]});
  }
  return result;
}

int nearest_index(const std::vector<Point>& points, const Point& p) {
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = (points[i] - p).norm();
    if (d < best_distance) {
      best_distance = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

std::array<int, 2> sorted_pair(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

FeaturePointProposal OracleUser::review_feature_points(const FeaturePointProposal& proposal) {
  const int hole = nearest_truth_hole(case_, proposal.hole_centroid);
  if (hole < 0 || proposal.boundary.size() < 3)
    return proposal;
  double mean_edge = 0.0;
  for (std::size_t i = 0; i < proposal.boundary.size(); ++i) {
    mean_edge +=
        (proposal.boundary[i] - proposal.boundary[(i + 1) % proposal.boundary.size()]).norm();
  }
  mean_edge /= static_cast<double>(proposal.boundary.size());
  const TrueFeatures truth = true_features(case_.holes[hole], 1e-9 * (1.0 + mean_edge), options_);

  // The true points as the user would click them: on the proposed boundary.
  std::vector<int> truth_vertex;
  for (const Point& p : truth.points)
    truth_vertex.push_back(nearest_index(proposal.boundary, p));
  std::vector<int> proposed_vertex;
  for (const Point& p : proposal.feature_points)
    proposed_vertex.push_back(nearest_index(proposal.boundary, p));

  // Greedy matching of proposed to true points, nearest first.
  const double tolerance = 3.0 * mean_edge;
  std::vector<std::tuple<double, int, int>> candidates;
  for (std::size_t i = 0; i < proposal.feature_points.size(); ++i) {
    for (std::size_t j = 0; j < truth.points.size(); ++j) {
      const double d = (proposal.feature_points[i] - proposal.boundary[truth_vertex[j]]).norm();
      if (d <= tolerance)
        candidates.emplace_back(d, static_cast<int>(i), static_cast<int>(j));
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<int> proposed_to_truth(proposal.feature_points.size(), -1);
  std::vector<int> truth_to_proposed(truth.points.size(), -1);
  for (const auto& [d, i, j] : candidates) {
    if (proposed_to_truth[i] >= 0 || truth_to_proposed[j] >= 0)
      continue;
    proposed_to_truth[i] = j;
    truth_to_proposed[j] = i;
  }

  FeaturePointProposal answer = proposal;
  answer.feature_points.clear();
  for (int v : truth_vertex)
    answer.feature_points.push_back(proposal.boundary[v]);
  answer.pairs = truth.pairs;
  answer.corner = truth.corner;
  answer.more_corners = truth.more_corners;
  answer.corner_links = truth.corner_links;

  // Interventions: moved, removed and added points.
  for (std::size_t i = 0; i < proposal.feature_points.size(); ++i) {
    const int j = proposed_to_truth[i];
    if (j < 0)
      count_intervention("feature_point_removed");
    else if (proposed_vertex[i] != truth_vertex[j])
      count_intervention("feature_point_moved");
  }
  for (int i : truth_to_proposed) {
    if (i < 0)
      count_intervention("feature_point_added");
  }
  // Pairs made or undone (pairs of removed points went with the points).
  std::set<std::array<int, 2>> proposed_pairs, true_pairs;
  for (const auto& p : proposal.pairs) {
    const int a = proposed_to_truth[p[0]], b = proposed_to_truth[p[1]];
    if (a >= 0 && b >= 0)
      proposed_pairs.insert(sorted_pair(a, b));
  }
  for (const auto& p : truth.pairs)
    true_pairs.insert(sorted_pair(p[0], p[1]));
  for (const auto& p : proposed_pairs)
    if (!true_pairs.count(p))
      count_intervention("pair_undone");
  for (const auto& p : true_pairs)
    if (!proposed_pairs.count(p))
      count_intervention("pair_made");
  // The corner triple named, changed or cleared.
  std::optional<std::set<int>> proposed_corner, true_corner;
  if (proposal.corner) {
    proposed_corner.emplace();
    for (int i : *proposal.corner)
      proposed_corner->insert(proposed_to_truth[i]);
  }
  if (truth.corner)
    true_corner = std::set<int>(truth.corner->begin(), truth.corner->end());
  if (proposed_corner != true_corner)
    count_intervention("corner_triple");
  // The corner graph: each further corner named and each link drawn (the method proposes
  // none).
  for (std::size_t i = 0; i < truth.more_corners.size(); ++i)
    count_intervention("corner_named");
  for (std::size_t i = 0; i < truth.corner_links.size(); ++i)
    count_intervention("corner_link");
  return answer;
}

namespace {

double mean_loop_edge(const std::vector<Point>& loop) {
  double sum = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    sum += (loop[i] - loop[(i + 1) % loop.size()]).norm();
  return loop.empty() ? 0.0 : sum / static_cast<double>(loop.size());
}

// The direction in which a missing edge leaves its end `from` (index 0 or size - 1 of the
// polyline): towards the polyline's point at arc length `reach` from that end (or its other
// end, if shorter), so that a curved crease gives its tangent at the edge-length scale.
Point leaving_direction(const std::vector<Point>& polyline, bool from_front, double reach) {
  const int n = static_cast<int>(polyline.size());
  const int start = from_front ? 0 : n - 1, step = from_front ? 1 : -1;
  double length = 0.0;
  int k = start;
  while (k + step >= 0 && k + step < n && length < reach) {
    length += (polyline[k + step] - polyline[k]).norm();
    k += step;
  }
  const Point d = polyline[k] - polyline[start];
  return d.norm() > 0 ? d / d.norm() : d;
}

}  // namespace

std::optional<Point> true_crease_direction(const HoleTruth& truth, const Point& at,
                                           double tolerance, double reach) {
  std::optional<Point> best;
  double best_distance = tolerance;
  auto at_corner = [&](const Point& p) {
    for (const Point& c : truth.missing_corners)
      if ((c - p).norm() <= 1e-9 * (1.0 + tolerance))
        return true;
    return false;
  };
  for (const auto& polyline : truth.missing_edges) {
    if (polyline.size() < 2)
      continue;
    for (bool front : {true, false}) {
      const Point& end = front ? polyline.front() : polyline.back();
      const double d = (end - at).norm();
      if (d <= best_distance && !at_corner(end)) {
        best_distance = d;
        best = leaving_direction(polyline, front, reach);
      }
    }
  }
  return best;
}

CrestLineProposal OracleUser::review_crest_lines(const CrestLineProposal& proposal) {
  const int hole = nearest_truth_hole(case_, proposal.hole_centroid);
  if (hole < 0 || proposal.directions.size() != proposal.feature_points.size())
    return proposal;
  const double a = mean_loop_edge(proposal.boundary);
  CrestLineProposal answer = proposal;
  for (std::size_t i = 0; i < proposal.feature_points.size(); ++i) {
    const auto truth = true_crease_direction(case_.holes[hole], proposal.feature_points[i],
                                             options_.crest_match_edges * a, a);
    if (!truth || truth->norm() == 0.0)
      continue;  // no missing sharp edge starts here: nothing to correct against
    const Point& d = proposal.directions[i];
    const double c = d.norm() > 0 ? OpenMesh::dot(d, *truth) / d.norm() : -1.0;
    if (std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI <= options_.crest_max_angle_degrees)
      continue;
    answer.directions[i] = *truth;
    count_intervention("crest_line_direction");
  }
  return answer;
}

void check_user_kind(const std::string& kind) {
  if (kind != "no_user" && kind != "oracle") {
    throw std::invalid_argument("unknown user '" + kind + "' (no_user or oracle)");
  }
}

std::unique_ptr<User> make_user(const std::string& kind, const Case& c) {
  check_user_kind(kind);
  if (kind == "oracle")
    return std::make_unique<OracleUser>(c);
  return std::make_unique<NoUser>();
}

}  // namespace holebench::harness
