// Mean and RMS surface distance with a guaranteed error bound, and the distance report of
// a repaired model against the complete one (whole model and hole region).
//
// Definitions, for surfaces A and B with d(x, B) = min over points b of B |x - b|:
//  - directed mean   m(A, B) = (1 / area(A)) * integral over A of d(x, B) dA;
//  - directed RMS    r(A, B) = sqrt((1 / area(A)) * integral over A of d(x, B)^2 dA);
//  - the symmetric values are the larger of the two directions (as Metro reports them);
//  - the Hausdorff distance is hausdorff_distance.h's.
// The integrals are computed by branch and bound on the triangles of A that B does not share
// (shared_faces.h: d = 0 there), as the Hausdorff distance is. Each (sub)triangle t gets
// bounds on its mean of d and of d^2:
//  - first order, pointwise: d(x, B) in [lo(t), hi(t)] for x in t, from 1-Lipschitz bounds
//    at the corners and centroid, the convex distance to the single triangle of B closest to
//    the centroid or a corner, and, where t may touch B, the exact minimum of d over t (the
//    triangle-triangle distance to the triangles of B that can hold a closest point);
//  - second order: the mean of the convex f_T (distance to one triangle T, d <= f_T) and of
//    f_T^2 is at most their corner mean; from below, |x|^2 - d(x)^2 is convex (d is
//    semiconcave), so d(x)^2 >= sum l_i d_i^2 - sum l_i |c_i - x|^2 (l_i barycentric), whose
//    cell mean is mean(d_i^2) - V with V = sum |c_i - g|^2 / 4; and the mean of d is at least
//    mean(d_i) - V / min(d_i). These shrink with the square of the cell size.
//  - exact where the distance is affine: every triangle of B that can hold a closest point
//    of the cell (within its pointwise upper bound plus its radius) lies within a slab of
//    half-width e about one plane P, so d >= |a_P| - e with a_P the signed distance to P,
//    whose mean (and the mean of a_P^2) over the cell is computed in closed form; and
//    min over those triangles T of s_T a_T (s_T = +-1) is concave, so its mean is at least
//    its corner mean (several planes, as at a sharp edge). From above, f_T <= its linear
//    interpolant on the cell, so the mean of f_T^2 is at most the mean of that interpolant
//    squared. Where B is flat under the cell the two sides meet.
// Each direction reports an interval [lower, upper] of the mean and of the RMS, and an
// estimate inside it (the midpoint). The cell with the largest share of the widths is split
// in four (after its exact bounds have been tried) until each half-width is within
// max(relative_error_bound x lower end, error_bound). distance_summary() then clamps the
// intervals by what holds for true values, mean <= RMS <= Hausdorff, so the reported numbers
// never contradict each other.
#pragma once

#include "core/mesh.h"
#include "core/statistics.h"
#include "metrics/growing_box.h"
#include "metrics/hausdorff_distance.h"
#include "metrics/shared_faces.h"
#include "metrics/surface_change.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace holebench {

namespace embree {
class TriangleScene;
}

struct MeanDistanceOptions {
  /// Absolute bound on the error of the mean and the RMS (half the width of each interval),
  /// in model units (callers pass a fraction of the diagonal).
  double error_bound = 1e-5;
  /// Relative bound: the search also stops a value once its half-width is at most this
  /// fraction of its lower end. The bound met is the larger of the two.
  double relative_error_bound = 0.01;
  /// Work limit: past this many closest-point queries the search stops as soon as each
  /// half-width is within `coarse_error_bound` (then `converged` = false: the interval holds
  /// but is wider than the bounds above).
  std::size_t query_budget = 8'000'000;
  /// The half-width every search reaches, budget or not (model units).
  double coarse_error_bound = std::numeric_limits<double>::infinity();
  /// Stop after this many closest-point queries whatever the widths (then `converged` =
  /// false and the bounds are the ones reached).
  std::size_t max_queries = 8'000'000;
};

struct DirectedMeanDistance {
  double mean = 0.0;        ///< estimate of m(A, B), in [mean_lower, mean_upper]
  double mean_lower = 0.0;  ///< m(A, B) >= mean_lower
  double mean_upper = 0.0;  ///< m(A, B) <= mean_upper
  double mean_error = 0.0;  ///< |mean - m(A, B)| <= mean_error (half the interval)
  double rms = 0.0;         ///< estimate of r(A, B), in [rms_lower, rms_upper]
  double rms_lower = 0.0;
  double rms_upper = 0.0;
  double rms_error = 0.0;  ///< |rms - r(A, B)| <= rms_error
  double area = 0.0;       ///< area of A
  std::size_t queries = 0;
  /// Cells' first bounds and refinement steps taken from another search (MeanSearchSteps);
  /// the queries they stand for are counted in `queries` all the same.
  std::size_t steps_taken = 0;
  bool converged = true;
};

class MeanCellBounds;
class MeanSearchSteps;

/// Bounds already computed for the first pass of a mean search (MeanCellBounds) and of a
/// Hausdorff search (HausdorffCellBounds), and how the search's B differs from theirs.
struct FirstBounds {
  const MeanCellBounds* bounds = nullptr;
  SurfaceChange change;
  /// surface_distance()'s Hausdorff search of A against B takes them as the mean search
  /// takes `bounds`: for A's faces with the same cells, where B is B0 within what their
  /// steps read (`change`).
  const HausdorffCellBounds* hausdorff = nullptr;
  /// What another mean search against this same B recorded (MeanSearchSteps), taken by the
  /// mean search of A for the cells it shares with that search's.
  const MeanSearchSteps* steps = nullptr;
};

/// m(A, B) and r(A, B) with `b_scene` an Embree scene of B. A mesh without area gives
/// zeros with area 0. `first_bounds` (optional): the first pass's bounds of cells of another
/// mesh against B or a B0 that differs from B only where `first_bounds->change` says: taken
/// for A's faces with the same cells; and the steps another search against B recorded.
/// `record` (optional): receives this search's cells' first bounds and refinement steps.
DirectedMeanDistance directed_mean_distance(const Mesh& a, const embree::TriangleScene& b_scene,
                                            const MeanDistanceOptions& options = {},
                                            const KnownDistances& known = {},
                                            const FirstBounds* first_bounds = nullptr,
                                            MeanSearchSteps* record = nullptr);

/// What a mean search computed for its cells against its B: each cell's first bounds, its
/// bounds once its plane bounds were tried, and its four children (the midpoints queried,
/// each child bounded). Each is a function of the cell (its corners, their distances and
/// nearest faces: CellKey) and of B only, so another search against the same B with the same
/// error bounds takes them for every cell with the same key instead of computing them,
/// counts the queries they would have made, and gives the same result, bit for bit. In a
/// job's evaluation the hole region's search of the patch against the complete model records
/// them, and the whole model's search of the repair against the complete model, whose new
/// faces are the patch's, takes them (evaluation.cpp).
class MeanSearchSteps {
 public:
  MeanSearchSteps();
  ~MeanSearchSteps();
  MeanSearchSteps(const MeanSearchSteps&) = delete;
  MeanSearchSteps& operator=(const MeanSearchSteps&) = delete;
  std::size_t size() const;  ///< cells and steps held

  struct Table;  ///< mean_search.cpp
  const Table& table() const { return *table_; }
  Table& table() { return *table_; }

 private:
  std::unique_ptr<Table> table_;
};

/// The mean search's first-pass bounds of the faces of a mesh A0 against a surface B0: each
/// face's cell (its corners in the face's order, their distances to B0 and nearest faces of
/// B0, as surface_distance's first pass over A0's vertices gives them) with its pointwise,
/// mean and mean-square bounds, and the box of the balls of B0 those bounds read (the
/// closest-point and nearby-face queries). The bounds are a function of the cell, of B0
/// inside that box and of the options' error bounds only. A search of another mesh A
/// against a B takes them for every face of A whose cell is the same, bit for bit (its
/// nearest faces read as B0's), where B is B0 inside the box (FirstBounds), and so gives the
/// same result as without them. Built once per case (case_evaluation.h): the input's faces
/// against the complete model (a repair keeps most of them), and the complete model's faces
/// against the input (a repair differs from it only around the holes).
class MeanCellBounds {
 public:
  /// `first_pass`: A0's against B0 (vertex_distances.h; the faces A0 shares with B0 need
  /// no bounds).
  MeanCellBounds(const Mesh& a0, const embree::TriangleScene& b0_scene, const FirstPass& first_pass,
                 const MeanDistanceOptions& options);
  ~MeanCellBounds();
  MeanCellBounds(const MeanCellBounds&) = delete;
  MeanCellBounds& operator=(const MeanCellBounds&) = delete;
  std::size_t size() const;  ///< cells held

  struct Table;  ///< mean_search.cpp
  const Table& table() const { return *table_; }

 private:
  std::unique_ptr<Table> table_;
};

/// A value with a guaranteed interval: lower <= true value <= upper, value in between.
using DistanceInterval = BoundedValue;

/// Mean, RMS and Hausdorff distance of one comparison, each with its interval, clamped by
/// the relations of the true values (0 <= mean <= RMS <= Hausdorff): mean.upper <=
/// rms.upper <= hausdorff.upper, rms.lower >= mean.lower, and the values too satisfy
/// mean.value <= rms.value <= hausdorff.upper. The Hausdorff value is its lower end (a
/// distance attained at a point).
struct DistanceSummary {
  DistanceInterval mean;
  DistanceInterval rms;
  DistanceInterval hausdorff;
};

/// One direction's summary from its Hausdorff and mean searches (the same A and B).
DistanceSummary distance_summary(const DirectedHausdorff& hausdorff,
                                 const DirectedMeanDistance& mean);

/// The larger of two summaries, interval by interval (the symmetric distances are the larger
/// of the two directions): the relations above still hold.
DistanceSummary max_of(const DistanceSummary& a, const DistanceSummary& b);

struct SurfaceDistanceOptions {
  HausdorffOptions hausdorff;  ///< error bound of the Hausdorff distance (model units)
  MeanDistanceOptions mean;    ///< error bound of the mean and RMS distance (model units)
};

/// Hausdorff, mean and RMS distance between A and B, both directions.
struct SurfaceDistance {
  HausdorffResult hausdorff;
  DirectedMeanDistance a_to_b;
  DirectedMeanDistance b_to_a;
  /// The faces A and B share exactly (skipped by both searches), for later metrics.
  SharedFaces shared;
  /// The symmetric values with their clamped intervals.
  DistanceSummary summary() const {
    return max_of(distance_summary(hausdorff.a_to_b, a_to_b),
                  distance_summary(hausdorff.b_to_a, b_to_a));
  }
  double mean() const { return summary().mean.value; }
  double mean_error() const { return std::max(a_to_b.mean_error, b_to_a.mean_error); }
  double rms() const { return summary().rms.value; }
  double rms_error() const { return std::max(a_to_b.rms_error, b_to_a.rms_error); }
  bool converged() const { return hausdorff.converged() && a_to_b.converged && b_to_a.converged; }
};

/// The two-sided distances between A and B, with Embree scenes of both built by the caller
/// (so that they are built once and reused).
/// `a_first_bounds`, `b_first_bounds` (optional): first-pass bounds (FirstBounds) for the
/// mean search from A to B and from B to A. `known_shared` (optional): shared_faces(a, b)
/// where the caller has it (SharedFacesOfInput::of_repair), taken instead of computed.
/// `a_start`, `b_start` (optional): where the search from A to B and from B to A starts
/// (SearchStart, with `known_shared`'s faces), taken instead of a pass over every face.
SurfaceDistance surface_distance(const Mesh& a, const embree::TriangleScene& a_scene, const Mesh& b,
                                 const embree::TriangleScene& b_scene,
                                 const SurfaceDistanceOptions& options = {},
                                 const FirstBounds* a_first_bounds = nullptr,
                                 const FirstBounds* b_first_bounds = nullptr,
                                 std::optional<SharedFaces> known_shared = std::nullopt,
                                 const SearchStart* a_start = nullptr,
                                 const SearchStart* b_start = nullptr);

}  // namespace holebench
