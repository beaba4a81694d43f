// Discrete curvature continuity (section 3, equations 1-3 of the slice paper) and the
// polyline helpers the tracing of missing edges (4.3) and section curves (4.4) share.
#pragma once

#include "core/mesh.h"

#include <functional>
#include <vector>

namespace holebench::slice_loft {

struct TraceOptions {
  double step = 1.0;           ///< distance between traced points (model units)
  int max_steps = 100;         ///< hard stop
  double max_turn_rad = 0.35;  ///< cap on the tangent turn per step (noise guard)
};

/// Traces a curve from q0 onwards, given the two points q1, q2 behind it (q2 farthest).
/// Each new point P_{i+1} makes the forward discrete curvature at P_i (eq. 1) equal to the
/// backward one (eq. 3), tangents by eq. 2: the tangent turns, per unit length, by the
/// angle it turned between q2-q1 and q1-q0, about the same axis (so a curve in a plane stays
/// in it, and a circle or a line is continued exactly). Stops before the first point for
/// which `stop` is true. The result starts with q0.
std::vector<Point> trace_curvature_continuous(const Point& q2, const Point& q1, const Point& q0,
                                              const TraceOptions& options,
                                              const std::function<bool(const Point&)>& stop);

/// The three points (q2, q1, q0) to start a trace from the first point of `curve`, which
/// runs away from where the trace goes: q0 = curve[0], q1 and q2 at arc lengths `baseline`
/// and 2 x `baseline` (shortened to fit the curve). Needs two distinct points.
struct BackPoints {
  Point q2, q1, q0;
  bool valid = false;
};
BackPoints back_points(const std::vector<Point>& curve, double baseline);

double polyline_length(const std::vector<Point>& polyline);
/// The point at arc length t from the first point; linear extrapolation beyond either end.
Point point_at_arc_length(const std::vector<Point>& polyline, double t);
/// Arc length of the point of `polyline` closest to p.
double closest_arc_length(const std::vector<Point>& polyline, const Point& p);
/// Distance from p to the polyline.
double distance_to_polyline(const std::vector<Point>& polyline, const Point& p);

/// C2 smooth step 6t^5 - 15t^4 + 10t^3: zero first and second derivatives at 0 and 1, so
/// blending with it keeps the curvature of each end.
double smootherstep(double t);

/// A curve from a to b traced from both ends (the paper's two-ended tracing, section 5):
/// `from_a` starts at a, `from_b` at b; the two are blended with `smootherstep`. Returns the
/// points strictly between a and b, about `spacing` apart.
std::vector<Point> bridge(const std::vector<Point>& from_a, const std::vector<Point>& from_b,
                          double spacing);

/// The curve `from_a` (starting at a) bent to end at `target` by a smootherstep correction.
/// Returns the points strictly between a and the target, about `spacing` apart.
std::vector<Point> bend_to(const std::vector<Point>& from_a, const Point& target, double spacing);

}  // namespace holebench::slice_loft
