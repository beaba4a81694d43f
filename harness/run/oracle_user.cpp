#include "harness/run/oracle_user.h"

#include "core/geometry.h"

#include <algorithm>
#include <array>
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
    count_intervention();
  return agree;
}

namespace {

// The true feature points of a hole: ends of its missing sharp edges on the hole boundary,
// the pairs (both ends of one edge) and the corner triple (the far ends of the edges that
// meet at a missing corner). Polylines that continue each other (they meet at a point that
// is no missing corner) are joined first.
struct TrueFeatures {
  std::vector<Point> points;
  std::vector<std::array<int, 2>> pairs;
  std::optional<std::array<int, 3>> corner;
};

TrueFeatures true_features(const HoleTruth& truth, double tolerance) {
  auto same = [&](const Point& a, const Point& b) { return (a - b).norm() <= tolerance; };
  auto at_corner = [&](const Point& p) -> int {
    for (std::size_t i = 0; i < truth.missing_corners.size(); ++i) {
      if (same(p, truth.missing_corners[i]))
        return static_cast<int>(i);
    }
    return -1;
  };
  std::vector<std::array<Point, 2>> ends;
  for (const auto& polyline : truth.missing_edges) {
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
  std::vector<std::vector<int>> corner_ends(truth.missing_corners.size());
  for (const auto& e : ends) {
    const int c0 = at_corner(e[0]), c1 = at_corner(e[1]);
    if (c0 >= 0 && c1 >= 0)
      continue;  // an edge between two missing corners meets no boundary
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
  for (const auto& triple : corner_ends) {
    if (triple.size() == 3 && !result.corner)
      result.corner = std::array<int, 3>{triple[0], triple[1], triple[2]};
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
  const TrueFeatures truth = true_features(case_.holes[hole], 1e-9 * (1.0 + mean_edge));

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

  // Interventions: moved, removed and added points.
  for (std::size_t i = 0; i < proposal.feature_points.size(); ++i) {
    const int j = proposed_to_truth[i];
    if (j < 0 || proposed_vertex[i] != truth_vertex[j])
      count_intervention();
  }
  for (int i : truth_to_proposed) {
    if (i < 0)
      count_intervention();
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
      count_intervention();
  for (const auto& p : true_pairs)
    if (!proposed_pairs.count(p))
      count_intervention();
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
    count_intervention();
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
