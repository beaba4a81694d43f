#include "methods/crest_feature/planarity_split.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace holebench::crest_feature {
namespace {

// Running sums of the loop's points and their outer products: the least-squares residual of
// any run of consecutive points in constant time.
struct LoopMoments {
  std::vector<Eigen::Vector3d> sum;  // sum[i]: points 0 .. i-1
  std::vector<Eigen::Matrix3d> outer;

  explicit LoopMoments(const std::vector<Point>& points) {
    sum.assign(points.size() + 1, Eigen::Vector3d::Zero());
    outer.assign(points.size() + 1, Eigen::Matrix3d::Zero());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d p(points[i][0], points[i][1], points[i][2]);
      sum[i + 1] = sum[i] + p;
      outer[i + 1] = outer[i] + p * p.transpose();
    }
  }

  // Mean squared distance to the least-squares plane of points first .. last (inclusive,
  // cyclic): the smallest eigenvalue of their covariance.
  double residual(std::size_t first, std::size_t last) const {
    const std::size_t n = sum.size() - 1;
    Eigen::Vector3d s;
    Eigen::Matrix3d o;
    if (first <= last) {
      s = sum[last + 1] - sum[first];
      o = outer[last + 1] - outer[first];
    } else {
      s = sum[n] - sum[first] + sum[last + 1];
      o = outer[n] - outer[first] + outer[last + 1];
    }
    const double count =
        static_cast<double>(first <= last ? last - first + 1 : n - first + last + 1);
    const Eigen::Matrix3d covariance = o / count - (s / count) * (s / count).transpose();
    return std::max(
        0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance, Eigen::EigenvaluesOnly)
                 .eigenvalues()[0]);
  }
};

// The loop's points from index `from` to `to` (cyclic, inclusive).
std::vector<Node> run(const std::vector<Node>& loop, std::size_t from, std::size_t to) {
  std::vector<Node> nodes;
  for (std::size_t k = from;; k = (k + 1) % loop.size()) {
    nodes.push_back(loop[k]);
    if (k == to)
      break;
  }
  return nodes;
}

PlanaritySplit split(const std::vector<Node>& loop, std::vector<Point>& new_points,
                     const std::function<Point(Node)>& point,
                     const std::function<PolygonTriangulation(const std::vector<Node>&)>& project,
                     const PlanaritySplitOptions& options, int depth) {
  PlanaritySplit result;
  PolygonTriangulation whole = project(loop);
  if (whole.ok) {
    result.ok = true;
    result.pieces.push_back({loop, std::move(whole)});
    return result;
  }
  const std::size_t n = loop.size();
  if (depth >= options.max_depth || n < 5)
    return result;
  std::vector<Point> points;
  double perimeter = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    points.push_back(point(loop[k]));
  for (std::size_t k = 0; k < n; ++k)
    perimeter += (points[(k + 1) % n] - points[k]).norm();
  const double spacing = perimeter / static_cast<double>(n);
  const LoopMoments moments(points);

  // Chords (i, j) leaving at least three points on either side, by the worse residual of
  // the two pieces they make.
  std::vector<std::tuple<double, std::size_t, std::size_t>> chords;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (n - (j - i) < 2)
        continue;
      const double worse = std::max(moments.residual(i, j), moments.residual(j, i));
      chords.emplace_back(worse, i, j);
    }
  }
  const std::size_t tried = std::min(chords.size(), std::size_t(options.max_chords_tried));
  std::partial_sort(chords.begin(), chords.begin() + tried, chords.end());
  for (std::size_t c = 0; c < tried; ++c) {
    const auto [worse, i, j] = chords[c];
    // The chord's interior points, from loop[j] to loop[i].
    const Point a = points[j], b = points[i];
    const int steps = std::max(1, static_cast<int>(std::lround((b - a).norm() / spacing)));
    const std::size_t mark = new_points.size();
    std::vector<Node> chord;
    for (int s = 1; s < steps; ++s) {
      chord.push_back(new_point_node(static_cast<int>(new_points.size())));
      new_points.push_back(a + (b - a) * (static_cast<double>(s) / steps));
    }
    std::vector<Node> first = run(loop, i, j);  // loop[i] .. loop[j], back along the chord
    first.insert(first.end(), chord.begin(), chord.end());
    std::vector<Node> second = run(loop, j, i);  // loop[j] .. loop[i], on along the chord
    second.insert(second.end(), chord.rbegin(), chord.rend());
    PlanaritySplit one = split(first, new_points, point, project, options, depth + 1);
    PlanaritySplit two =
        one.ok ? split(second, new_points, point, project, options, depth + 1) : PlanaritySplit{};
    if (one.ok && two.ok) {
      result.ok = true;
      result.chords = 1 + one.chords + two.chords;
      for (auto* part : {&one, &two})
        std::move(part->pieces.begin(), part->pieces.end(), std::back_inserter(result.pieces));
      return result;
    }
    new_points.resize(mark);
  }
  return result;
}

}  // namespace

PlanaritySplit split_for_equation_6(
    const std::vector<Node>& loop, std::vector<Point>& new_points,
    const std::function<Point(Node)>& point,
    const std::function<PolygonTriangulation(const std::vector<Node>&)>& project,
    const PlanaritySplitOptions& options) {
  if (!options.enabled)
    return {};
  return split(loop, new_points, point, project, options, 0);
}

}  // namespace holebench::crest_feature
