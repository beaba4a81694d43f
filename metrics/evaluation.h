// The metrics of one job: pure functions of the case (with its ground truth) and what a
// method returned (core/method_result.h). Metrics never see the method itself. Every metric
// is defined, with its unit and error bound, in docs/metrics.md.
#pragma once

#include "core/case.h"
#include "core/method_result.h"
#include "metrics/literature_metrics.h"
#include "metrics/surface_distance.h"

#include <string>
#include <vector>

namespace holebench {

/// One named number. Names carry their unit: `_rel_diag` is relative to the bounding-box
/// diagonal of the complete model, `_deg` degrees, `_s` seconds, `_count` a count,
/// `_fraction` a fraction in [0, 1]; booleans are 0/1 with `_ok` or `is_` in the name.
/// A metric that does not apply to a job is absent, never a placeholder number.
struct MetricValue {
  std::string name;
  double value = 0.0;
};

struct EvaluationOptions {
  /// Error bound of the Hausdorff distances, relative to the complete model's diagonal.
  double hausdorff_error_bound_rel_diag = 1e-4;
  /// Mean and RMS distances: each is reported with an interval [lower, upper] whose
  /// half-width is at most the larger of this absolute bound (relative to the diagonal) and
  /// `mean_relative_error_bound` times the lower end. Whole model:
  double mean_error_bound_rel_diag = 1e-5;
  /// ... and over the hole region:
  double hole_mean_error_bound_rel_diag = 1e-5;
  /// ... and the relative part of both (0.01: the estimate within 1 % of the truth).
  double mean_relative_error_bound = 0.01;
  /// Work limits of the mean/RMS searches (closest-point queries per direction), whole model
  /// and hole region. Past its budget a search stops as soon as each half-width is within
  /// `mean_coarse_error_bound_rel_diag`; its interval still holds but is wider than the
  /// bounds above, and `distance_converged_ok` (for the hole region also
  /// `hole_distance_converged_ok`) is 0. Under noise the whole model's distance is a rough
  /// field over every face, and its search stops there on most jobs.
  std::size_t mean_query_budget = 2'000;
  std::size_t hole_mean_query_budget = 50'000;
  double mean_coarse_error_bound_rel_diag = 1e-3;
  /// Feature recovery: spacing of the samples on a missing edge, the distance within which
  /// a repaired sharp edge covers a sample, and the radius of "near" (all relative).
  double edge_sample_spacing_rel_diag = 1e-3;
  double edge_tolerance_rel_diag = 5e-3;
  double edge_search_radius_rel_diag = 5e-2;
  /// Normal deviation and normal consistency: the complete model's faces within the nearest
  /// distance plus this (relative) form the normal cone a normal is compared with
  /// (metrics/normal_cone.h).
  double normal_cone_tolerance_rel_diag = 1e-3;
  /// The literature's metrics (metrics/literature_metrics.h): F-score, normal consistency
  /// and the edge Chamfer distance. Points sampled per surface (whole model, hole region),
  /// and the F-score's two thresholds tau (relative; 0.5 % and 1 % of the diagonal).
  bool literature_metrics = true;
  std::size_t literature_samples = 10'000;
  std::size_t hole_literature_samples = 10'000;
  double f_score_tau_small_rel_diag = 0.005;
  double f_score_tau_large_rel_diag = 0.01;
  /// Validity: a new face of at most this area (relative to diagonal^2) is degenerate.
  double degenerate_area_rel_diag2 = 1e-14;
  /// Validity: run CGAL's self-intersection test (the costliest validity check).
  bool self_intersections = true;
  /// Guidance arrows: the camera's full field of view, the spacing of the samples on the
  /// missing surface (relative) and the directions of the best-direction search.
  double arrow_field_of_view_degrees = 60.0;
  double arrow_sample_spacing_rel_diag = 5e-3;
  int arrow_search_directions = 4096;
};

/// The evaluation's own steps, whose wall times Evaluation::phases gives (in this order,
/// each where it ran): the records' `evaluation_phases_s` (docs/results.md), so that a run
/// shows where its evaluation time goes.
namespace evaluation_phases {
/// What a case's evaluations share (metrics/case_evaluation.h), built once in the group's
/// process: the runner counts it in the first job of the group.
constexpr const char* kSharedCaseWork = "shared_case_work";
constexpr const char* kCompleteScene = "complete_scene";  ///< where no shared one is given
/// The input's faces the repair kept, and where it changed the input.
constexpr const char* kKeptFaces = "kept_faces";
constexpr const char* kRepairedScene = "repaired_scene";
/// The patch's mean distance to the complete model (hole region and whole model).
constexpr const char* kPatchMean = "patch_mean_distance";
constexpr const char* kWholeModelDistances = "whole_model_distances";
constexpr const char* kHoleRegionDistances = "hole_region_distances";
constexpr const char* kNewVertexError = "new_vertex_error";
/// The literature's sampled metrics (F-score, normal consistency, edge Chamfer distance).
constexpr const char* kLiteratureMetrics = "literature_metrics";
constexpr const char* kFeatureRecovery = "feature_recovery";
constexpr const char* kPatchQuality = "patch_quality";  ///< real holes only
constexpr const char* kValidity = "validity";
constexpr const char* kClassification = "classification";
constexpr const char* kArrowVisibility = "arrow_visibility";
}  // namespace evaluation_phases

struct Evaluation {
  std::vector<MetricValue> values;
  /// Wall time of each of the evaluation's steps (evaluation_phases), in the order they ran.
  std::vector<PhaseTiming> phases;
  const MetricValue* find(const std::string& name) const;
};

/// The options of the whole model's distances (repaired against complete) for a case whose
/// complete model has this bounding-box diagonal.
SurfaceDistanceOptions whole_model_distance_options(const EvaluationOptions& options,
                                                    double diagonal);

/// The options of the whole model's sampled literature metrics (F-score thresholds, normal
/// cone tolerance, samples) for a case whose complete model has this bounding-box diagonal.
SampledAgreementOptions literature_sampling_options(const EvaluationOptions& options,
                                                    double diagonal);

/// Evaluates `result` (its repaired mesh and hole reports) against the ground truth of `c`.
/// Embree scenes of the complete, repaired and (for arrows) holed model are built once and
/// shared by every metric. Deterministic: the same inputs give the same numbers.
Evaluation evaluate(const Case& c, const MethodResult& result,
                    const EvaluationOptions& options = {});

}  // namespace holebench
