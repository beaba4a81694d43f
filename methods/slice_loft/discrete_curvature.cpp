#include "methods/slice_loft/discrete_curvature.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace holebench::slice_loft {
namespace {

// Rodrigues' rotation of v about the unit axis k by angle a.
Point rotate(const Point& v, const Point& k, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return v * c + OpenMesh::cross(k, v) * s + k * (OpenMesh::dot(k, v) * (1.0 - c));
}

// Closest point on segment ab to p, as the parameter in [0, 1].
double segment_parameter(const Point& a, const Point& b, const Point& p) {
  const Point ab = b - a;
  const double len2 = OpenMesh::dot(ab, ab);
  if (len2 <= 0.0)
    return 0.0;
  return std::clamp(OpenMesh::dot(p - a, ab) / len2, 0.0, 1.0);
}

}  // namespace

std::vector<Point> trace_curvature_continuous(const Point& q2, const Point& q1, const Point& q0,
                                              const TraceOptions& options,
                                              const std::function<bool(const Point&)>& stop) {
  std::vector<Point> points{q0};
  const double d10 = (q0 - q1).norm(), d21 = (q1 - q2).norm();
  if (d10 <= 0.0 || d21 <= 0.0)
    return points;
  const Point t_prev = (q1 - q2) / d21;  // eq. 2 at q1
  Point tangent = (q0 - q1) / d10;       // eq. 2 at q0
  Point axis = OpenMesh::cross(t_prev, tangent);
  const double sin_turn = axis.norm();
  const double turn = std::atan2(sin_turn, OpenMesh::dot(t_prev, tangent));
  // Equal forward and backward curvature (eqs. 1 and 3): the same turn per unit length.
  const double curvature = sin_turn > 1e-12 ? turn / (0.5 * (d10 + d21)) : 0.0;
  if (sin_turn > 1e-12)
    axis /= sin_turn;
  const double step_turn =
      std::clamp(curvature * options.step, -options.max_turn_rad, options.max_turn_rad);
  Point p = q0;
  for (int i = 0; i < options.max_steps; ++i) {
    if (curvature != 0.0)
      tangent = rotate(tangent, axis, step_turn);
    const Point next = p + tangent * options.step;
    if (stop && stop(next))
      break;
    points.push_back(next);
    p = next;
  }
  return points;
}

BackPoints back_points(const std::vector<Point>& curve, double baseline) {
  BackPoints result;
  const double length = polyline_length(curve);
  if (curve.size() < 2 || length <= 0.0)
    return result;
  const double b = std::min(baseline, 0.5 * length);
  result.q0 = curve.front();
  result.q1 = point_at_arc_length(curve, b);
  result.q2 = point_at_arc_length(curve, 2.0 * b);
  result.valid = (result.q0 - result.q1).norm() > 0.0 && (result.q1 - result.q2).norm() > 0.0;
  return result;
}

double polyline_length(const std::vector<Point>& polyline) {
  double length = 0.0;
  for (std::size_t i = 1; i < polyline.size(); ++i)
    length += (polyline[i] - polyline[i - 1]).norm();
  return length;
}

Point point_at_arc_length(const std::vector<Point>& polyline, double t) {
  if (polyline.empty())
    return Point(0, 0, 0);
  if (polyline.size() == 1)
    return polyline.front();
  if (t <= 0.0) {
    const Point d = polyline[1] - polyline[0];
    const double len = d.norm();
    return len > 0.0 ? polyline[0] + d * (t / len) : polyline[0];
  }
  double walked = 0.0;
  for (std::size_t i = 1; i < polyline.size(); ++i) {
    const double len = (polyline[i] - polyline[i - 1]).norm();
    if (walked + len >= t && len > 0.0)
      return polyline[i - 1] + (polyline[i] - polyline[i - 1]) * ((t - walked) / len);
    walked += len;
  }
  // Beyond the end: extend the last segment.
  const std::size_t n = polyline.size();
  const Point d = polyline[n - 1] - polyline[n - 2];
  const double len = d.norm();
  return len > 0.0 ? polyline[n - 1] + d * ((t - walked) / len) : polyline[n - 1];
}

double closest_arc_length(const std::vector<Point>& polyline, const Point& p) {
  if (polyline.size() < 2)
    return 0.0;
  double best = std::numeric_limits<double>::max(), best_t = 0.0, walked = 0.0;
  for (std::size_t i = 1; i < polyline.size(); ++i) {
    const double len = (polyline[i] - polyline[i - 1]).norm();
    const double s = segment_parameter(polyline[i - 1], polyline[i], p);
    const double d = (polyline[i - 1] + (polyline[i] - polyline[i - 1]) * s - p).norm();
    if (d < best) {
      best = d;
      best_t = walked + s * len;
    }
    walked += len;
  }
  return best_t;
}

double distance_to_polyline(const std::vector<Point>& polyline, const Point& p) {
  if (polyline.size() == 1)
    return (polyline[0] - p).norm();
  return (point_at_arc_length(polyline, closest_arc_length(polyline, p)) - p).norm();
}

double smootherstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * t * (t * (6.0 * t - 15.0) + 10.0);
}

std::vector<Point> bridge(const std::vector<Point>& from_a, const std::vector<Point>& from_b,
                          double spacing) {
  std::vector<Point> points;
  if (from_a.empty() || from_b.empty())
    return points;
  const Point& a = from_a.front();
  const Point& b = from_b.front();
  // The arc length of the gap as each trace sees it.
  const double la = from_a.size() > 1 ? closest_arc_length(from_a, b) : (b - a).norm();
  const double lb = from_b.size() > 1 ? closest_arc_length(from_b, a) : (b - a).norm();
  double length = 0.5 * (la + lb);
  if (length <= 0.0)
    length = (b - a).norm();
  const int pieces = std::max(1, static_cast<int>(std::lround(length / spacing)));
  for (int k = 1; k < pieces; ++k) {
    const double t = static_cast<double>(k) / pieces;
    const Point pa = from_a.size() > 1 ? point_at_arc_length(from_a, t * length) : a + (b - a) * t;
    const Point pb =
        from_b.size() > 1 ? point_at_arc_length(from_b, (1.0 - t) * length) : a + (b - a) * t;
    const double w = smootherstep(t);
    points.push_back(pa * (1.0 - w) + pb * w);
  }
  return points;
}

std::vector<Point> bend_to(const std::vector<Point>& from_a, const Point& target, double spacing) {
  std::vector<Point> points;
  if (from_a.empty())
    return points;
  const Point& a = from_a.front();
  double length = from_a.size() > 1 ? closest_arc_length(from_a, target) : 0.0;
  if (length <= 0.0)
    length = (target - a).norm();
  const Point miss = target - point_at_arc_length(from_a, length);
  const int pieces = std::max(1, static_cast<int>(std::lround(length / spacing)));
  for (int k = 1; k < pieces; ++k) {
    const double t = static_cast<double>(k) / pieces;
    const Point p = from_a.size() > 1 ? point_at_arc_length(from_a, t * length) : a;
    points.push_back(p + miss * smootherstep(t));
  }
  return points;
}

}  // namespace holebench::slice_loft
