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
  return meeting_point(std::vector<Point>(at.begin(), at.end()),
                       std::vector<Point>(direction.begin(), direction.end()));
}

std::optional<Point> meeting_point(const std::vector<Point>& at,
                                   const std::vector<Point>& direction) {
  if (at.size() < 2 || at.size() != direction.size())
    return std::nullopt;
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < at.size(); ++i) {
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

// P0 (or P3) for the feature point f: the crest line continued outwards to distance d. The
// crest points zigzag about the crease by up to an edge length, so the point is not read off
// the polyline: the crest line's deviation from f's tangent line is fitted by a quadratic in
// the distance along it, r(tau) = a + b tau + c tau^2 (least squares over the crest points
// within 2d outside the hole), and P0 = f - d t + r(-d) - a: the crest line's own direction
// and curvature, without its offset at f.
Point outer_control_point(const Hole& hole, const FeaturePoint& f, const CrestLines* crest,
                          double d) {
  const Point along_tangent = f.position - f.tangent * d;
  if (!crest || f.crest_line < 0 || f.crest_line >= static_cast<int>(crest->lines.size()))
    return along_tangent;
  const Point t = f.tangent;
  const double own = (f.position - hole.centroid).norm();
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d rhs = Eigen::Matrix3d::Zero();  // columns: x, y, z of the deviation
  int count = 0;
  for (const Point& q : crest->lines[f.crest_line].points) {
    const double tau = OpenMesh::dot(q - f.position, t);
    if (tau >= 0.0 || tau < -2.0 * d || (q - hole.centroid).norm() <= own)
      continue;  // inside the hole's reach, or too far out
    const Point r = q - f.position - t * tau;
    const Eigen::Vector3d basis(1.0, tau, tau * tau);
    normal += basis * basis.transpose();
    rhs += basis * Eigen::RowVector3d(r[0], r[1], r[2]);
    ++count;
  }
  if (count < 4)
    return along_tangent;
  const Eigen::LDLT<Eigen::Matrix3d> solver(normal);
  if (solver.info() != Eigen::Success || !(std::abs(normal.determinant()) > 1e-300))
    return along_tangent;
  const Eigen::Matrix3d coefficients = solver.solve(rhs);  // rows: a, b, c
  const Eigen::RowVector3d deviation = -d * coefficients.row(1) + d * d * coefficients.row(2);
  if (!deviation.allFinite() || deviation.norm() > d)
    return along_tangent;
  return along_tangent + Point(deviation[0], deviation[1], deviation[2]);
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
  // Each corner (the triple first): its lines from its feature points to where their
  // tangent lines meet.
  for (const auto& corner_points : corners(features)) {
    std::vector<Point> at, direction;
    for (int i : corner_points) {
      at.push_back(features.points[i].position);
      direction.push_back(features.points[i].tangent);
    }
    auto corner = meeting_point(at, direction);
    // A meeting point outside the hole's reach is no estimate: the mean of the points.
    if (!corner || (*corner - hole.centroid).norm() > 1.5 * hole.radius) {
      Point mean(0, 0, 0);
      for (const Point& p : at)
        mean += p;
      corner = mean / static_cast<double>(at.size());
    }
    const int index = static_cast<int>(result.corners.size());
    result.corners.push_back(*corner);
    for (int i : corner_points) {
      const auto& f = features.points[i];
      const double d = (*corner - f.position).norm();
      if (d == 0.0)
        continue;
      const Point p0 = options.control_points == ControlPoints::CrestPoints
                           ? outer_control_point(hole, f, crest, d)
                           : f.position - f.tangent * d;
      const Point p3 = *corner * 2.0 - f.position;
      FeatureLine line{f.loop_index, -1, sample(p0, f.position, *corner, p3)};
      line.to_corner = index;
      result.lines.push_back(std::move(line));
    }
  }
  // Corner links (the user's corner graph): straight lines between two corners.
  for (const auto& link : features.corner_links) {
    const Point a = result.corners[link[0]], b = result.corners[link[1]];
    if ((b - a).norm() == 0.0)
      continue;
    FeatureLine line{-1, -1, sample(a * 2.0 - b, a, b, b * 2.0 - a)};
    line.from_corner = link[0];
    line.to_corner = link[1];
    result.lines.push_back(std::move(line));
  }
  return result;
}

}  // namespace holebench::crest_feature
