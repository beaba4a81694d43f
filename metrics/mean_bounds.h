// The mean search's bounds on one cell of A (surface_distance.h describes them): pointwise
// bounds of d(x, B) over the cell and bounds of its means of d and of d^2, first and second
// order (bound()), and from the planes of the triangles of B near it (tighten()). Each is a
// function of the cell, of B and of the options' error bounds only.
#pragma once

#include "core/mesh.h"
#include "core/plane_fit.h"
#include "metrics/growing_box.h"
#include "metrics/surface_distance.h"
#include "metrics/triangle_cell.h"

#include <array>
#include <vector>

namespace holebench {

namespace embree {
class TriangleScene;
}

// What MeanCellBounder::bound() and tighten() give a cell: bounds on d(x, B) over it, and on its
// means of d and of d^2.
struct MeanBounds {
  double hi = 0.0;                          // pointwise: d <= hi on the cell
  double mean_lo = 0.0, mean_hi = 0.0;      // bounds of the cell's mean of d
  double square_lo = 0.0, square_hi = 0.0;  // bounds of the cell's mean of d^2
};

// A (sub)triangle of A with bounds on the mean of d(x, B) and of d(x, B)^2 over it. Its
// priority in the queue is its share of the errors: the largest is refined first.
struct MeanCell : TriangleCell, MeanBounds {
  MeanCell() = default;
  explicit MeanCell(const TriangleCell& cell) : TriangleCell(cell) {}
  // Bounds computed for the same cell elsewhere (a table, or another search's steps).
  void take_bounds(const MeanBounds& from) { static_cast<MeanBounds&>(*this) = from; }
  const MeanBounds& bounds() const { return *this; }
  double area = 0.0;
  bool planes_tried = false;  // the plane bounds (tighten()) are in
};

class MeanCellBounder {
 public:
  MeanCellBounder(const embree::TriangleScene& scene, const MeanDistanceOptions& options)
      : scene_(scene), options_(options) {}

  /// The cell's first bounds: pointwise, of its mean and of its mean square. One
  /// closest-point query (the centroid's). `reach` (optional): grows to hold every ball of B
  /// that the bounds' queries read (the corners' distances come from the first pass, whose
  /// balls the caller adds). `centroid` (optional): the answer of the centroid's query,
  /// asked before (FirstPass::centroid); then no query is made.
  void bound(MeanCell& cell, GrowingBox* reach = nullptr,
             const embree::ClosestPoint* centroid = nullptr) const;

  /// Whether the plane bounds are worth trying on the cell (B's triangles near it few).
  bool near_enough_to_tighten(const MeanCell& cell) const;

  /// The cell's bounds tightened by the planes of the triangles of B that can hold a
  /// closest point of it; sets `planes_tried`.
  void tighten(MeanCell& cell) const;

 private:
  static double cell_radius(const MeanCell& cell);
  /// Whether the triangle `c` meets one of the triangles of B `faces` (-1: none) that lie
  /// within `radius` of `p` (point_triangle_distance(), as faces_within() takes them), by
  /// edges_meet_triangles(): then their triangle_triangle_distance() is 0.
  bool meets_one_of(const std::array<Point, 3>& c, const std::array<int, 4>& faces, const Point& p,
                    double radius) const;
  bool covered_by(const std::array<Point, 3>& c, const Plane& plane,
                  const std::vector<int>& candidates) const;

  const embree::TriangleScene& scene_;
  const MeanDistanceOptions& options_;
};

}  // namespace holebench
