#include "methods/crest_feature/feature_line_interpolation.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace holebench::crest_feature {

Point catmull_rom(const Point& p0, const Point& p1, const Point& p2, const Point& p3, double t) {
  // 0.5 * (1, t, t^2, t^3) * M * (P0, P1, P2, P3)^T with M the matrix of equation 3.
  const double t2 = t * t, t3 = t2 * t;
  const double w0 = 0.5 * (-t + 2.0 * t2 - t3);
  const double w1 = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
  const double w2 = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
  const double w3 = 0.5 * (-t2 + t3);
  return p0 * w0 + p1 * w1 + p2 * w2 + p3 * w3;
}

std::optional<Point> meeting_point(const std::array<Point, 3>& at,
                                   const std::array<Point, 3>& direction) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d d(direction[i][0], direction[i][1], direction[i][2]);
    if (d.norm() == 0.0)
      return std::nullopt;
    d.normalize();
    const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - d * d.transpose();
    a += projector;
    b += projector * Eigen::Vector3d(at[i][0], at[i][1], at[i][2]);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(a);
  if (solver.eigenvalues()[0] < 0.05)  // the directions nearly span a plane or a line
    return std::nullopt;
  const Eigen::Vector3d x = a.ldlt().solve(b);
  return Point(x[0], x[1], x[2]);
}

Point outer_control_point(const Hole& hole, const FeaturePoint& f, const CrestLines* crest,
                          double d) {
  const Point along_tangent = f.position - f.tangent * d;
  if (!crest || f.crest_line < 0 || f.crest_line >= static_cast<int>(crest->lines.size()))
    return along_tangent;
  const std::vector<Point>& points = crest->lines[f.crest_line].points;
  if (points.size() < 2)
    return along_tangent;
  // The crest line runs into the hole at one of its ends: walk from that end outwards.
  const bool front_at_hole =
      (points.front() - hole.centroid).norm() < (points.back() - hole.centroid).norm();
  std::vector<Point> outward{f.position};
  if (front_at_hole) {
    outward.insert(outward.end(), points.begin(), points.end());
  } else {
    outward.insert(outward.end(), points.rbegin(), points.rend());
  }
  // Skip crest points that lie inside the hole's reach, nearer the centroid than F.
  const double own = (f.position - hole.centroid).norm();
  std::vector<Point> kept{f.position};
  for (std::size_t i = 1; i < outward.size(); ++i) {
    if ((outward[i] - hole.centroid).norm() > own)
      kept.push_back(outward[i]);
  }
  double walked = 0.0;
  for (std::size_t i = 1; i < kept.size(); ++i) {
    const double step = (kept[i] - kept[i - 1]).norm();
    if (walked + step >= d && step > 0.0)
      return kept[i - 1] + (kept[i] - kept[i - 1]) * ((d - walked) / step);
    walked += step;
  }
  return along_tangent;  // the crest line is shorter than d outside the hole
}

FeatureLines interpolate_feature_lines(const Hole& hole, const HoleFeatures& features,
                                       const InterpolationOptions& options,
                                       const CrestLines* crest) {
  FeatureLines result;
  const double a = hole.average_edge_length;  // equation 4
  auto segments = [&](double d) {             // equation 5: t = d / a segments' worth
    return std::max(options.min_segments, static_cast<int>(std::lround(d / a)));
  };
  auto sample = [&](const Point& p0, const Point& p1, const Point& p2, const Point& p3) {
    const int n = segments((p2 - p1).norm());
    std::vector<Point> interior;
    for (int k = 1; k < n; ++k)
      interior.push_back(catmull_rom(p0, p1, p2, p3, static_cast<double>(k) / n));
    return interior;
  };
  for (const auto& pair : features.pairs) {
    const auto& f1 = features.points[pair[0]];
    const auto& f2 = features.points[pair[1]];
    const double d = (f2.position - f1.position).norm();
    if (d == 0.0)
      continue;
    const Point p0 = options.control_points == ControlPoints::CrestPoints
                         ? outer_control_point(hole, f1, crest, d)
                         : f1.position - f1.tangent * d;
    const Point p3 = options.control_points == ControlPoints::CrestPoints
                         ? outer_control_point(hole, f2, crest, d)
                         : f2.position - f2.tangent * d;
    result.lines.push_back(
        {f1.loop_index, f2.loop_index, sample(p0, f1.position, f2.position, p3)});
  }
  if (features.corner) {
    std::array<Point, 3> at, direction;
    for (int m = 0; m < 3; ++m) {
      at[m] = features.points[(*features.corner)[m]].position;
      direction[m] = features.points[(*features.corner)[m]].tangent;
    }
    auto corner = meeting_point(at, direction);
    // A meeting point outside the hole's reach is no estimate: the mean of the three points.
    if (!corner || (*corner - hole.centroid).norm() > 1.5 * hole.radius)
      corner = (at[0] + at[1] + at[2]) / 3.0;
    result.corner = corner;
    for (int m = 0; m < 3; ++m) {
      const auto& f = features.points[(*features.corner)[m]];
      const double d = (*corner - f.position).norm();
      if (d == 0.0)
        continue;
      const Point p0 = options.control_points == ControlPoints::CrestPoints
                           ? outer_control_point(hole, f, crest, d)
                           : f.position - f.tangent * d;
      const Point p3 = *corner * 2.0 - f.position;
      result.lines.push_back({f.loop_index, -1, sample(p0, f.position, *corner, p3)});
    }
  }
  return result;
}

}  // namespace holebench::crest_feature
