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
// The mean is the sum of the cells' mid-bounds (error: half the area-weighted width), the
// RMS the square root of the mean-square's mid-bound (error: half the width of the roots of
// its interval). The cell with the largest share of the errors is split in four until both
// are within the error bound. Closest points come from Embree (rtcPointQuery) with an upper
// bound on each answer, ties broken by face index: the same inputs give the same numbers on
// every run.
#pragma once

#include "core/mesh.h"
#include "metrics/hausdorff_distance.h"

#include <cstddef>
#include <optional>

namespace holebench {

namespace embree {
class TriangleScene;
}

struct MeanDistanceOptions {
  /// Absolute bound on the error of both the mean and the RMS distance, in model units.
  double error_bound = 1e-3;
  /// Stop after this many closest-point queries (then `converged` = false and the bounds
  /// are the ones reached).
  std::size_t max_queries = 8'000'000;
};

struct DirectedMeanDistance {
  double mean = 0.0;        ///< estimate of m(A, B)
  double mean_error = 0.0;  ///< |mean - m(A, B)| <= mean_error
  double rms = 0.0;         ///< estimate of r(A, B)
  double rms_error = 0.0;   ///< |rms - r(A, B)| <= rms_error
  double area = 0.0;        ///< area of A
  std::size_t queries = 0;
  bool converged = true;
};

/// m(A, B) and r(A, B) with `b_scene` an Embree scene of B. A mesh without area gives
/// zeros with area 0.
DirectedMeanDistance directed_mean_distance(const Mesh& a, const embree::TriangleScene& b_scene,
                                            const MeanDistanceOptions& options = {},
                                            const KnownDistances& known = {});

struct SurfaceDistanceOptions {
  HausdorffOptions hausdorff;  ///< error bound of the Hausdorff distance (model units)
  MeanDistanceOptions mean;    ///< error bound of the mean and RMS distance (model units)
};

/// Hausdorff, mean and RMS distance between A and B, both directions.
struct SurfaceDistance {
  HausdorffResult hausdorff;
  DirectedMeanDistance a_to_b;
  DirectedMeanDistance b_to_a;
  double mean() const { return std::max(a_to_b.mean, b_to_a.mean); }
  double mean_error() const { return std::max(a_to_b.mean_error, b_to_a.mean_error); }
  double rms() const { return std::max(a_to_b.rms, b_to_a.rms); }
  double rms_error() const { return std::max(a_to_b.rms_error, b_to_a.rms_error); }
  bool converged() const { return hausdorff.converged() && a_to_b.converged && b_to_a.converged; }
};

/// The two-sided distances between A and B, with Embree scenes of both built by the caller
/// (so that they are built once and reused).
SurfaceDistance surface_distance(const Mesh& a, const embree::TriangleScene& a_scene, const Mesh& b,
                                 const embree::TriangleScene& b_scene,
                                 const SurfaceDistanceOptions& options = {});

}  // namespace holebench
