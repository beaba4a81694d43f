#include "core/nearest_segment.h"

#include "core/distances.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace holebench {

namespace {

constexpr int kLeafSize = 4;
// A box is skipped only where it lies farther than the best distance so far by more than this
// fraction of the largest coordinate: point_segment_distance() rounds by some 1e-16 of it.
constexpr double kMarginOfScale = 1e-9;

bool finite(const Point& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

Point centre(const SegmentEnds& s) {
  return (s.a + s.b) * 0.5;
}

}  // namespace

NearestSegment::NearestSegment(std::vector<SegmentEnds> segments) {
  for (auto& s : segments) {
    if (finite(s.a) && finite(s.b))
      segments_.push_back(s);
    else
      unbounded_.push_back(s);
  }
  for (const auto& s : segments_) {
    for (int i = 0; i < 3; ++i)
      scale_ = std::max({scale_, std::abs(s.a[i]), std::abs(s.b[i])});
  }
  if (!segments_.empty()) {
    nodes_.reserve(2 * segments_.size() / kLeafSize + 2);
    build(0, static_cast<int>(segments_.size()));
  }
}

int NearestSegment::build(int first, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Point lower = segments_[first].a, upper = segments_[first].a;
  Point centre_lower = centre(segments_[first]), centre_upper = centre_lower;
  for (int i = first; i < first + count; ++i) {
    const SegmentEnds& s = segments_[i];
    const Point c = centre(s);
    for (int k = 0; k < 3; ++k) {
      lower[k] = std::min({lower[k], s.a[k], s.b[k]});
      upper[k] = std::max({upper[k], s.a[k], s.b[k]});
      centre_lower[k] = std::min(centre_lower[k], c[k]);
      centre_upper[k] = std::max(centre_upper[k], c[k]);
    }
  }
  nodes_[index].lower = lower;
  nodes_[index].upper = upper;
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (centre_upper[k] - centre_lower[k] > centre_upper[axis] - centre_lower[axis])
      axis = k;
  }
  const int half = count / 2;
  std::nth_element(segments_.begin() + first, segments_.begin() + first + half,
                   segments_.begin() + first + count,
                   [axis](const SegmentEnds& x, const SegmentEnds& y) {
                     return centre(x)[axis] < centre(y)[axis];
                   });
  const int left = build(first, half);
  const int right = build(first + half, count - half);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

double NearestSegment::box_squared_distance(const Node& node, const Point& p) const {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double gap = std::max({node.lower[k] - p[k], 0.0, p[k] - node.upper[k]});
    sum += gap * gap;
  }
  return sum;
}

double NearestSegment::distance(const Point& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : unbounded_)
    best = std::min(best, point_segment_distance(p, s.a, s.b));
  if (nodes_.empty())
    return best;
  const double margin =
      kMarginOfScale * std::max({scale_, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  // Skip a box whose distance exceeds best + margin; compared in squares (both sides >= 0).
  const auto beyond = [&](double box_squared) {
    const double reach = best + margin;
    return box_squared > reach * reach;
  };
  // A depth-first walk, nearer child first; a tree of n segments is at most 2 log2(n) deep.
  std::array<std::pair<int, double>, 128> stack;
  int top = 0;
  stack[top++] = {0, box_squared_distance(nodes_[0], p)};
  while (top > 0) {
    const auto [index, box_squared] = stack[--top];
    if (beyond(box_squared))
      continue;
    const Node& node = nodes_[index];
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i)
        best = std::min(best, point_segment_distance(p, segments_[i].a, segments_[i].b));
      continue;
    }
    const double left = box_squared_distance(nodes_[node.left], p);
    const double right = box_squared_distance(nodes_[node.right], p);
    // Pushed farther first, so the nearer is taken next.
    if (left <= right) {
      stack[top++] = {node.right, right};
      stack[top++] = {node.left, left};
    } else {
      stack[top++] = {node.left, left};
      stack[top++] = {node.right, right};
    }
  }
  return best;
}

}  // namespace holebench
