// The lofted surface of step IV of the slice paper (section 4.4): the section curves, each a
// C2 cubic spline in 3D parametrised by arc length, skinned into one tensor-product surface
// that is C2 across the sections as well. The paper lofts with ACIS; this is the same
// construction written out (docs/slice_loft.md says why no kernel): a bicubic spline that
// interpolates a grid of section points, natural cubic splines in both parameters.
//
// Parameters: u is the offset of a section's plane along the slicing direction d (so every
// surface point at u lies in the plane dot(p - origin, d) = u: the natural spline across the
// sections reproduces linear data exactly), and s is arc length along the section, measured
// from the section's reference point (its point nearest the slicing axis origin + u d).
#pragma once

#include "core/mesh.h"

#include <array>
#include <string>
#include <vector>

namespace holebench::slice_loft {

/// One section curve as the loft takes it: a polyline in the plane dot(p - origin, d) = u,
/// in its own order (it need not be a graph over any line).
struct SectionPolyline {
  double u = 0.0;
  std::vector<Point> points;
};

struct LoftOptions {
  double sample_spacing = 1.0;  ///< arc-length spacing of the grid along the sections
};

/// A natural cubic spline through values y_i at increasing x_i (second derivatives zero at
/// both ends), extended linearly beyond the ends with the end slopes: C2 inside.
class NaturalCubicSpline {
 public:
  NaturalCubicSpline() = default;
  NaturalCubicSpline(std::vector<double> x, std::vector<Point> y);
  Point operator()(double at) const;
  /// First and second derivatives at `at`.
  std::pair<Point, Point> derivatives(double at) const;
  /// The weights w_i with spline(at) = sum_i w_i y_i (the spline is linear in its data).
  static std::vector<double> weights(const std::vector<double>& x, double at);

 private:
  std::vector<double> x_;
  std::vector<Point> y_, second_;  ///< second derivatives at the knots
};

class LoftedSurface {
 public:
  /// Lofts sections given in increasing u (at least two, each with two distinct points).
  static LoftedSurface loft(const Point& origin, const Point& d,
                            const std::vector<SectionPolyline>& sections,
                            const LoftOptions& options = {});

  bool ok() const { return error_.empty() && !u_.empty(); }
  const std::string& error() const { return error_; }

  double u_of(const Point& p) const { return OpenMesh::dot(p - origin_, d_); }
  /// S(u, s).
  Point evaluate(double u, double s) const;
  /// The point of the curve S(u, .) whose coordinate dot(S - origin, axis) is `value` (the
  /// first crossing along s; the nearer end continued linearly if none).
  Point point_with_coordinate(double u, const Point& axis, double value) const;
  /// The parameters (u, s) of the surface point nearest p in p's own section plane.
  std::array<double, 2> parameters(const Point& p) const;

  const std::vector<double>& section_u() const { return u_; }
  const std::vector<double>& s_grid() const { return s_; }

 private:
  Point origin_, d_;
  std::vector<double> u_;                  ///< the sections' offsets
  std::vector<double> s_;                  ///< the common arc-length grid
  std::vector<std::vector<Point>> grid_;   ///< grid_[k][j] = section k at s_[j]
  std::vector<NaturalCubicSpline> along_;  ///< section k as a spline in s
  std::vector<double> reference_;          ///< per section: arc length of its s = 0
  std::string error_;

  double reference_arc_length(const std::vector<Point>& polyline, double u) const;
  /// sum_k w_k C_k(s): the curve S(u, .) at s, w the spline weights across sections at u.
  Point across(const std::vector<double>& w, double s) const;
  /// The same at every grid value s_j (exact there: C_k(s_j) is a grid point).
  std::vector<Point> across_on_grid(const std::vector<double>& w) const;
};

}  // namespace holebench::slice_loft
