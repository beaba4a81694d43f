// Feature line interpolation (crest-line paper, section 3.4.3): Catmull-Rom splines
// (equation 3) between paired feature points, with the point density of equations 4-5;
// a corner hole gets three feature lines that meet at the estimated corner.
#pragma once

#include "methods/crest_feature/feature_points.h"
#include "methods/crest_feature/hole_identification.h"

#include <array>
#include <optional>
#include <vector>

namespace holebench::crest_feature {

/// Equation 3: the point at parameter t in [0, 1] between P1 and P2 of the uniform
/// Catmull-Rom spline through P0, P1, P2, P3.
Point catmull_rom(const Point& p0, const Point& p1, const Point& p2, const Point& p3, double t);

/// The least-squares meeting point of two or more lines (point, direction); nullopt where
/// the lines are (nearly) parallel.
std::optional<Point> meeting_point(const std::vector<Point>& at,
                                   const std::vector<Point>& direction);
/// The same for three lines.
std::optional<Point> meeting_point(const std::array<Point, 3>& at,
                                   const std::array<Point, 3>& direction);

struct FeatureLine {
  int from = 0;  ///< loop index of the feature point it starts at; -1: a corner (from_corner)
  int to = -1;   ///< loop index of the feature point it ends at; -1: a corner (to_corner)
  std::vector<Point> interior;  ///< interpolated feature points, from -> to, ends excluded
  int to_corner = -1;           ///< index into FeatureLines::corners where `to` is -1
  int from_corner = -1;         ///< index into FeatureLines::corners where `from` is -1
};

struct FeatureLines {
  /// Pairs first, then each corner's lines (the triple's first), then the corner links.
  std::vector<FeatureLine> lines;
  /// Where each corner's lines meet: the triple's first, then the user's further ones.
  std::vector<Point> corners;
};

/// Where P0 and P3 of equation 3 come from: the crest line continued to distance d outside
/// the hole by a quadratic fitted to its own points (the paper takes the adjacent crest
/// points, so that the spline carries the crest line's curvature; the default), or the point
/// at distance d on the fitted tangent line (the project's option, in crest_feature_plus: on
/// straight creases the crest points' zigzag bends the feature line, docs/crest_feature.md).
enum class ControlPoints { CrestPoints, TangentLine };

struct InterpolationOptions {
  ControlPoints control_points = ControlPoints::CrestPoints;
  /// At least this many segments per feature line (>= 2, so that a line always has an
  /// interpolated point and never coincides with an existing edge).
  int min_segments = 2;
};

/// Control points of a pair (F1, F2): P0 and P3 at distance d = |F1 F2| outward from F1 and
/// F2 (the uniform spacing equation 3 assumes), as `options.control_points` says (on the
/// fitted tangent line where a crest line has too few points, or without `crest`).
/// Equations 4-5: t advances by a / d, i.e. the line gets round(d / a) segments. A corner triple's
/// lines run from each F_i to the meeting point C of the three tangent lines, with P3 = 2C - F_i
/// (straight into the corner). The user's further corners (not in the paper) are placed the same
/// way from their two or more lines, and a corner link is the straight line between two corners.
FeatureLines interpolate_feature_lines(const Hole& hole, const HoleFeatures& features,
                                       const InterpolationOptions& options = {},
                                       const CrestLines* crest = nullptr);

}  // namespace holebench::crest_feature
