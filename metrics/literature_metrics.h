// The metrics the surface-reconstruction and CAD-reconstruction literature quotes, so that a
// reader can put holebench's numbers beside a published table: Chamfer distance (L1 and L2),
// F-score at a distance threshold, normal consistency, and the edge Chamfer distance between
// sharp edges. docs/metrics.md gives each definition with the paper and evaluation code it
// follows, and how it relates to holebench's own bounded distances.
//
// Definitions, for a repair R and the truth C (the whole models, or over the hole region the
// patch and the removed faces of the complete model), d(x, S) the distance to a surface:
//  - Chamfer-L1 = (m(R, C) + m(C, R)) / 2 and Chamfer-L2 = (r(R, C)^2 + r(C, R)^2) / 2 with
//    m and r the area-weighted directed mean and RMS distances (surface_distance.h): taken
//    from those bounded searches (each direction's summary), so each comes with a guaranteed
//    interval;
//  - precision(tau) = area share of R within tau of C, recall(tau) = area share of C within
//    tau of R, F(tau) = 2 P R / (P + R) (0 where P + R = 0);
//  - normal consistency = (a(R, C) + a(C, R)) / 2 with a(A, B) the area-weighted mean over A of
//    |n_A . n_B|, n_B from B's normal cone at the closest point (normal_cone.h);
//  - precision, recall and normal consistency are estimated from `samples` points per surface
//    spread over its area (systematic sampling along the faces' cumulative area, a fixed
//    low-discrepancy point inside each face; where the caller splits A in two parts, as the
//    whole model does for a repair's input faces and new faces under noise, each part gets
//    `samples` points and combined_agreement() weighs them by area); faces A shares exactly
//    with B count exactly (distance 0, |cosine| 1) and are not sampled. Sampling error
//    (99 %): at most
//    2.58 sqrt(p (1 - p) / N) <= 1.29 / sqrt(N) of the sampled area's share, for P and R; at
//    most twice that for F.
//  - edge Chamfer distance = (e(S_R, S_C) + e(S_C, S_R)) / 2, with S_R the sharp edges of the
//    repair that bound a new face, S_C the sharp edges of the complete model that bound a
//    removed face (|dihedral angle| >= sharp_angle_degrees), and e(S, T) the mean distance of
//    S's points (sampled every `edge_sample_spacing` along S) to the segments of T. Absent
//    where either side has no sharp edge in the hole region.
#pragma once

#include "core/mesh.h"
#include "core/statistics.h"
#include "metrics/normal_cone.h"
#include "metrics/surface_distance.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace holebench {

namespace embree {
class TriangleScene;
}

/// Chamfer-L1 and Chamfer-L2 from the two directions' summaries (distance_summary: the
/// mean and RMS intervals of each direction, clamped by what holds for true values), with
/// their intervals. So Chamfer-L1 <= the larger direction's mean and Chamfer-L2 <= its RMS^2.
struct ChamferDistance {
  BoundedValue l1;  ///< model units
  BoundedValue l2;  ///< model units squared
};
ChamferDistance chamfer_distance(const DistanceSummary& a_to_b, const DistanceSummary& b_to_a);

struct SampledAgreementOptions {
  std::size_t samples = 10'000;    ///< points over the sampled (unshared) area
  std::vector<double> thresholds;  ///< tau, model units
  NormalConeOptions normal_cone;   ///< tolerance of the normal cone (model units)
};

/// How much of surface A lies near surface B: per threshold the area share of A within it,
/// and the area-weighted mean |cosine| of A's normal with B's normal cone.
struct SampledAgreement {
  std::vector<double> within_fraction;  ///< per options.thresholds
  double abs_cosine_mean = 0.0;
  double area = 0.0;          ///< of A
  double sampled_area = 0.0;  ///< of A's faces not shared with B (the rest counts exactly)
  std::size_t samples = 0;    ///< points taken (0 when nothing needed sampling)
  /// The 99 % sampling error of each within_fraction (1.29 / sqrt(N) times the sampled share).
  double fraction_error = 0.0;
};

/// The points an agreement sampled and what B's normal cone answered at each: another
/// agreement against the same scene with the same options that takes the same points (bit for
/// bit, the same normals) takes these answers instead of asking again. The whole model's
/// sampled area is often the hole region's (the repair's unshared faces are its patch).
struct SampledAnswers {
  std::vector<Point> points;
  std::vector<Point> normals;
  std::vector<NormalConeAngle> cones;
};

/// A's faces as the sampled metrics take them: A's area and the area of its faces on B
/// (each summed over the faces with area in index order), and the other faces with area, in
/// index order, with the running sum of their areas (the samples are drawn from them).
/// A tally may continue another (`before`, see continued_tally()): its faces and running
/// sums then come after those of `before`, and its three sums include them.
struct SampledFaces {
  double area = 0.0;
  double shared_area = 0.0;
  double unshared_area = 0.0;
  std::vector<int> faces;
  std::vector<double> cumulative;
  const SampledFaces* before = nullptr;  ///< not owned; it must outlive this tally

  /// The faces of `before` and its own, in order.
  std::size_t size() const { return (before ? before->size() : 0) + faces.size(); }
  int face(std::size_t i) const;
  double running_sum(std::size_t i) const;
};

/// An empty continuation of `before`: its sums, no faces of its own yet. tally_faces() over
/// the faces after `before`'s then gives the tally over all of them, sum for sum, without a
/// copy of `before`'s faces (a repair that appends a patch to the input: the case's tally
/// of the input, continued over the patch).
SampledFaces continued_tally(const SampledFaces& before);

/// The tally of A's faces from their areas (face_areas(a)) and `b_face_of_a` (optional: by
/// face of A, the same face in B or -1).
SampledFaces sampled_faces(const std::vector<double>& face_areas,
                           const std::vector<int>* b_face_of_a);
/// The tally continued over faces `first`, `first` + 1, ... (`face_areas[i]`: the area of
/// face `first` + i), where `tally` holds the faces before them: the same sums, in the same
/// order, as sampled_faces() over every face.
void tally_faces(const std::vector<double>& face_areas, const std::vector<int>* b_face_of_a,
                 std::size_t first, SampledFaces& tally);

/// A against B's scene. `b_face_of_a` (optional): by face of A, the same face in B or -1
/// (shared_faces.h); shared faces count as within every threshold with |cosine| 1.
/// `known` (optional): answers of an agreement against `b_scene` with these options, taken
/// where its points are these; `answers` (optional) receives this agreement's own.
/// `known_faces` (optional): sampled_faces() of A against B where the caller has it
/// (case_evaluation.h), taken instead of a pass over A's faces.
/// Deterministic: the same meshes give the same numbers, with or without `known`.
SampledAgreement sampled_agreement(const Mesh& a, const embree::TriangleScene& b_scene,
                                   const SampledAgreementOptions& options,
                                   const std::vector<int>* b_face_of_a = nullptr,
                                   const SampledAnswers* known = nullptr,
                                   SampledAnswers* answers = nullptr,
                                   const SampledFaces* known_faces = nullptr);

/// Two parts of A sampled apart (each by sampled_agreement() over its own faces, with its own
/// tally) as one agreement of A: each fraction and the mean |cosine| the parts' area-weighted
/// mean, the samples and areas their sums, the sampling error
/// sqrt((a1 e1)^2 + (a2 e2)^2) / (a1 + a2) (stratified sampling: at most the error of one
/// sample of either count over both). A part with no area leaves the other as it is.
SampledAgreement combined_agreement(const SampledAgreement& first, const SampledAgreement& second);

/// The points `sampled_agreement` takes on A (faces skipped where `skip` says so): `count`
/// points spread by area, and the face each lies on.
struct AreaSamples {
  std::vector<Point> points;
  std::vector<int> faces;
  std::vector<Point> normals;  ///< unit normal of each point's face
};
AreaSamples area_samples(const Mesh& a, std::size_t count, const std::vector<bool>* skip = nullptr);

/// The points sampled_agreement() takes on A with `tally` (A's sampled_faces()) and `count`
/// samples, with their faces and normals: none where A has no unshared area.
AreaSamples tally_samples(const Mesh& a, std::size_t count, const SampledFaces& tally);

/// F-score from precision and recall (0 where both are 0).
double f_score(double precision, double recall);

struct EdgeChamferOptions {
  double sharp_angle_degrees = 30.0;  ///< an edge with |dihedral| at least this is sharp
  double edge_sample_spacing = 1e-3;  ///< model units
};

/// The edge Chamfer distance of the repair's sharp edges around its new faces and the complete
/// model's around `removed_faces` (see the header comment); nothing where either has none.
/// `repaired_new_faces` (optional): new_face_indices(repaired) where the caller has them.
std::optional<double> edge_chamfer_distance(const Mesh& complete,
                                            const std::vector<int>& removed_faces,
                                            const Mesh& repaired,
                                            const EdgeChamferOptions& options = {},
                                            const std::vector<int>* repaired_new_faces = nullptr);

}  // namespace holebench
