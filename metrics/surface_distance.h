// Mean and RMS surface distance with a guaranteed error bound, and the distance report of
// a repaired model against the complete one (whole model and hole region).
//
// Definitions, for surfaces A and B with d(x, B) = min over points b of B |x - b|:
//  - directed mean   m(A, B) = (1 / area(A)) * integral over A of d(x, B) dA;
//  - directed RMS    r(A, B) = sqrt((1 / area(A)) * integral over A of d(x, B)^2 dA);
//  - the symmetric values are the larger of the two directions (as Metro reports them);
//  - the Hausdorff distance is hausdorff_distance.h's.
// The integrals are computed by branch and bound on the triangles of A, as the Hausdorff
// distance is: each (sub)triangle t gets an interval [lo(t), hi(t)] that contains d(x, B)
// for every x of t:
//  - hi(t): the smaller of the largest corner distance to the single triangle of B closest
//    to t's centroid (convexity), and min over sample points p of d(p, B) + r(p), where r(p)
//    is the farthest any point of t is from p (1-Lipschitz);
//  - lo(t): the larger of max(0, max over sample points p of d(p, B) - r(p)) and, where
//    that leaves a gap wider than half the error bound, the exact minimum of d over t: the
//    triangle-triangle distance from t to the triangles of B within hi(t) + r(centroid) of t's
//    centroid (the only ones that can hold a closest point of a point of t).
// With w(t) = (hi - lo) / 2 and the estimate m(t) = (hi + lo) / 2 on t, the error of the
// mean is at most sum area(t) w(t) / area(A), and (Minkowski) the error of the RMS at most
// sqrt(sum area(t) w(t)^2 / area(A)), which is also >= the mean's. The triangle with the
// largest area(t) w(t)^2 is split in four until that RMS bound is <= the error bound, so
// both values are within the bound. Sample points are corners and centroids; closest
// points come from Embree (rtcPointQuery), ties broken by face index: the same inputs give
// the same numbers on every run.
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
                                            const MeanDistanceOptions& options = {});

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
