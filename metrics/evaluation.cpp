#include "metrics/evaluation.h"

#include "metrics/case_evaluation.h"

#include "core/geometry.h"
#include "core/stopwatch.h"
#include "metrics/classification_accuracy.h"
#include "metrics/embree/arrow_visibility.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/face_subset.h"
#include "metrics/feature_recovery.h"
#include "metrics/hole_matching.h"
#include "metrics/kept_faces.h"
#include "metrics/literature_metrics.h"
#include "metrics/mean_search.h"
#include "metrics/metric_names.h"
#include "metrics/patch_quality.h"
#include "metrics/shared_faces.h"
#include "metrics/surface_distance.h"
#include "metrics/validity.h"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>

namespace holebench {

SurfaceDistanceOptions whole_model_distance_options(const EvaluationOptions& options,
                                                    double diagonal) {
  SurfaceDistanceOptions whole;
  whole.hausdorff.error_bound = options.hausdorff_error_bound_rel_diag * diagonal;
  whole.mean.error_bound = options.mean_error_bound_rel_diag * diagonal;
  whole.mean.relative_error_bound = options.mean_relative_error_bound;
  whole.mean.query_budget = options.mean_query_budget;
  whole.mean.coarse_error_bound = options.mean_coarse_error_bound_rel_diag * diagonal;
  return whole;
}

SampledAgreementOptions literature_sampling_options(const EvaluationOptions& options,
                                                    double diagonal) {
  SampledAgreementOptions sampling;
  sampling.thresholds = {options.f_score_tau_small_rel_diag * diagonal,
                         options.f_score_tau_large_rel_diag * diagonal};
  sampling.normal_cone.tolerance = options.normal_cone_tolerance_rel_diag * diagonal;
  sampling.samples = options.literature_samples;
  return sampling;
}

const MetricValue* Evaluation::find(const std::string& name) const {
  for (const auto& value : values) {
    if (value.name == name)
      return &value;
  }
  return nullptr;
}

namespace {

using namespace metric_names;

class Recorder {
 public:
  explicit Recorder(std::vector<MetricValue>& values) : values_(values) {}
  void add(const std::string& name, double value) { values_.push_back({name, value}); }
  void add_flag(const char* name, bool value) { values_.push_back({name, value ? 1.0 : 0.0}); }
  void add_count(const char* name, std::size_t value) {
    values_.push_back({name, static_cast<double>(value)});
  }

 private:
  std::vector<MetricValue>& values_;
};

// The evaluation's phases: each lap is the wall time since the one before (or the start).
class PhaseLaps {
 public:
  explicit PhaseLaps(std::vector<PhaseTiming>& phases)
      : phases_(phases), start_(SteadyClock::now()) {}
  void lap(const char* phase) {
    const auto now = SteadyClock::now();
    phases_.push_back({phase, std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  std::vector<PhaseTiming>& phases_;
  SteadyClock::time_point start_;
};

double fraction(std::size_t part, std::size_t whole) {
  return static_cast<double>(part) / static_cast<double>(whole);
}

// A distance with its interval: the value and, where the search gives them, its bounds.
void add_interval(Recorder& out, const IntervalNames& names, const DistanceInterval& d,
                  double diagonal) {
  out.add(names.value, d.value / diagonal);
  out.add(names.lower, d.lower / diagonal);
  out.add(names.upper, d.upper / diagonal);
}

// The whole model's mean and Hausdorff searches' first bounds from what the case's jobs share:
// the repair's kept faces against the complete model are the input's; the complete model
// against the repair is the complete model against the input away from the repair's changes.
struct SharedFirstBounds {
  FirstBounds repaired_to_complete;
  FirstBounds complete_to_repaired;
  /// The faces the repair shares with the complete model, from the input's
  /// (SharedFacesOfInput), where the repair keeps the input so.
  std::optional<SharedFaces> repaired_shared_faces;
  /// Where the searches of a repair that appends to the input start (with the repair's kept
  /// faces), or null.
  const AppendedRepairStarts* appended_starts = nullptr;
  const KeptFaces* kept = nullptr;
};
SharedFirstBounds shared_first_bounds(const Case& c, const MethodResult& result,
                                      const CaseEvaluation* shared, const KeptFaces* kept) {
  SharedFirstBounds first;
  if (!shared)
    return first;
  first.repaired_to_complete.bounds = shared->input_cell_bounds();
  first.repaired_to_complete.hausdorff = shared->input_hausdorff_bounds();
  if (kept && kept->order_kept) {
    first.complete_to_repaired.bounds = shared->complete_cell_bounds();
    first.complete_to_repaired.hausdorff = shared->complete_hausdorff_bounds();
    first.complete_to_repaired.change.b0_face_of_b = &kept->input_face_of_repaired;
    first.complete_to_repaired.change.b_face_of_b0 = &kept->repaired_face_of_input;
    first.complete_to_repaired.change.changed = changed_faces_box(c.input, result.repaired, *kept);
  }
  if (kept && shared->shared_faces_of_input())
    first.repaired_shared_faces =
        shared->shared_faces_of_input()->of_repair(result.repaired, *kept);
  first.appended_starts = shared->appended_repair_starts();
  first.kept = kept;
  return first;
}

// The hole region's searches: the whole model's, with the hole's own mean error bound and
// query budget.
SurfaceDistanceOptions hole_region_options(const EvaluationOptions& options,
                                           const SurfaceDistanceOptions& whole, double diagonal) {
  SurfaceDistanceOptions hole = whole;
  hole.mean.error_bound = options.hole_mean_error_bound_rel_diag * diagonal;
  hole.mean.query_budget = options.hole_mean_query_budget;
  return hole;
}

// The patch (the repair's new faces, where the case has holes) and its mean distance to the
// complete model; the search records its steps in `steps` for the whole model's search.
struct PatchMean {
  std::optional<Mesh> patch;
  std::optional<DirectedMeanDistance> mean;
};
PatchMean patch_mean(const Mesh& repaired, const std::vector<int>& new_faces, bool case_has_holes,
                     const embree::TriangleScene& complete_scene,
                     const MeanDistanceOptions& options, MeanSearchSteps& steps) {
  PatchMean result;
  const std::vector<int> patch_faces = case_has_holes ? new_faces : std::vector<int>{};
  if (patch_faces.empty())
    return result;
  result.patch.emplace(face_subset(repaired, patch_faces));
  result.mean = directed_mean_distance(*result.patch, complete_scene, options, {}, nullptr, &steps);
  return result;
}

// The hole region: the removed faces of the complete model (the truth) against the repaired
// mesh, and the patch against the complete model (the larger of the two directions).
struct HoleRegionDistance {
  DistanceSummary summary;
  bool converged = true;
  Mesh truth;                         ///< the removed faces of the complete model
  DistanceSummary truth_to_repaired;  ///< each direction alone, for the Chamfer distances
  std::optional<DistanceSummary> patch_to_complete;
};
HoleRegionDistance hole_region_distance(const Case& c, const std::vector<int>& removed,
                                        const PatchMean& patch,
                                        const embree::TriangleScene& complete_scene,
                                        const embree::TriangleScene& repaired_scene,
                                        const SurfaceDistanceOptions& options) {
  HoleRegionDistance hole;
  hole.truth = face_subset(c.complete, removed);
  const auto truth_to_repaired_h =
      directed_hausdorff(hole.truth, repaired_scene, options.hausdorff);
  const auto truth_to_repaired_m = directed_mean_distance(hole.truth, repaired_scene, options.mean);
  hole.truth_to_repaired = distance_summary(truth_to_repaired_h, truth_to_repaired_m);
  hole.summary = hole.truth_to_repaired;
  hole.converged = truth_to_repaired_h.converged && truth_to_repaired_m.converged;
  if (patch.patch) {
    const auto h = directed_hausdorff(*patch.patch, complete_scene, options.hausdorff);
    const DirectedMeanDistance& m = *patch.mean;
    hole.patch_to_complete = distance_summary(h, m);
    hole.summary = max_of(hole.summary, *hole.patch_to_complete);
    hole.converged = hole.converged && h.converged && m.converged;
  }
  return hole;
}

// Chamfer-L1 (a length) and Chamfer-L2 (a squared length) with their intervals.
void add_chamfer(Recorder& out, const IntervalNames& l1_names, const IntervalNames& l2_names,
                 const ChamferDistance& chamfer, double diagonal) {
  add_interval(out, l1_names, {chamfer.l1.lower, chamfer.l1.value, chamfer.l1.upper}, diagonal);
  add_interval(out, l2_names, {chamfer.l2.lower, chamfer.l2.value, chamfer.l2.upper},
               diagonal * diagonal);
}

// The slice paper's Table 2 error: the mean distance of the new vertices from the complete
// model (exact closest points).
void add_new_vertex_error(const Mesh& repaired, const embree::TriangleScene& complete_scene,
                          double diagonal, Recorder& out) {
  double sum = 0.0;
  std::size_t count = 0;
  for (int v : new_vertex_indices(repaired)) {
    sum += complete_scene.closest_point(repaired.point(VertexHandle(v))).distance;
    ++count;
  }
  if (count > 0)
    out.add(kNewVertexMeanErrorRelDiag, sum / count / diagonal);
}

// What the literature's sampled metrics take from the distances: the faces the repair shares
// with the complete model (found by the whole-model search), the hole region's truth and the
// patch (where the case has holes).
struct RegionMeshes {
  SharedFaces shared;  ///< a = the repaired mesh, b = the complete model
  std::optional<Mesh> truth;
  std::optional<Mesh> patch;
};

RegionMeshes add_distances(const Case& c, const MethodResult& result,
                           const std::vector<int>& new_faces, const EvaluationOptions& options,
                           double diagonal, const embree::TriangleScene& complete_scene,
                           const embree::TriangleScene& repaired_scene, SharedFirstBounds& first,
                           Recorder& out, PhaseLaps& laps) {
  const Mesh& repaired = result.repaired;
  const SurfaceDistanceOptions whole = whole_model_distance_options(options, diagonal);
  const SurfaceDistanceOptions hole_options = hole_region_options(options, whole, diagonal);
  const std::vector<int> removed = removed_faces(c);

  // The patch's mean search against the complete model comes first: the whole model's search
  // of the repair against the complete model takes the steps it recorded for the cells they
  // share, the patch's (MeanSearchSteps: the same numbers, computed once).
  MeanSearchSteps patch_steps;
  PatchMean patch = patch_mean(repaired, new_faces, !removed.empty(), complete_scene,
                               hole_options.mean, patch_steps);
  laps.lap(evaluation_phases::kPatchMean);
  FirstBounds repaired_to_complete = first.repaired_to_complete;
  repaired_to_complete.steps = &patch_steps;
  // Where the repair appends to the input, both searches start from the case's first passes
  // (appended_repair_starts.h: the same starts, without a pass over the model).
  std::optional<SearchStart> repaired_start, complete_start;
  if (first.appended_starts && first.kept && first.repaired_shared_faces) {
    repaired_start = first.appended_starts->repaired_to_complete(
        repaired, *first.kept, *first.repaired_shared_faces, complete_scene);
    complete_start = first.appended_starts->complete_to_repaired(
        c.complete, repaired, *first.kept, *first.repaired_shared_faces, repaired_scene,
        earlier_vertex_answers(c.complete, &first.complete_to_repaired));
  }
  SurfaceDistance d = surface_distance(
      repaired, repaired_scene, c.complete, complete_scene, whole, &repaired_to_complete,
      &first.complete_to_repaired, std::move(first.repaired_shared_faces),
      repaired_start ? &*repaired_start : nullptr, complete_start ? &*complete_start : nullptr);
  laps.lap(evaluation_phases::kWholeModelDistances);
  const DistanceSummary model = d.summary();
  out.add(kHausdorffRelDiag, model.hausdorff.lower / diagonal);
  out.add(kHausdorffUpperRelDiag, model.hausdorff.upper / diagonal);
  add_interval(out, kMeanDistance, model.mean, diagonal);
  add_interval(out, kRmsDistance, model.rms, diagonal);
  add_chamfer(out, kChamferL1, kChamferL2,
              chamfer_distance(distance_summary(d.hausdorff.a_to_b, d.a_to_b),
                               distance_summary(d.hausdorff.b_to_a, d.b_to_a)),
              diagonal);

  RegionMeshes regions;
  regions.shared = std::move(d.shared);
  bool converged = d.converged();
  if (!removed.empty()) {
    HoleRegionDistance hole =
        hole_region_distance(c, removed, patch, complete_scene, repaired_scene, hole_options);
    converged = converged && hole.converged;
    out.add_flag(kHoleDistanceConvergedOk, hole.converged);
    out.add(kHoleHausdorffRelDiag, hole.summary.hausdorff.lower / diagonal);
    out.add(kHoleHausdorffUpperRelDiag, hole.summary.hausdorff.upper / diagonal);
    add_interval(out, kHoleMeanDistance, hole.summary.mean, diagonal);
    add_interval(out, kHoleRmsDistance, hole.summary.rms, diagonal);
    if (c.truth_surrounds_a_real_hole) {
      out.add(kRingHausdorffRelDiag, hole.truth_to_repaired.hausdorff.lower / diagonal);
      out.add(kRingHausdorffUpperRelDiag, hole.truth_to_repaired.hausdorff.upper / diagonal);
      add_interval(out, kRingMeanDistance, hole.truth_to_repaired.mean, diagonal);
    }
    if (hole.patch_to_complete) {
      add_chamfer(out, kHoleChamferL1, kHoleChamferL2,
                  chamfer_distance(*hole.patch_to_complete, hole.truth_to_repaired), diagonal);
    }
    regions.truth = std::move(hole.truth);
    regions.patch = std::move(patch.patch);
    laps.lap(evaluation_phases::kHoleRegionDistances);
  }
  out.add_flag(kDistanceConvergedOk, converged);
  add_new_vertex_error(repaired, complete_scene, diagonal, out);
  laps.lap(evaluation_phases::kNewVertexError);
  return regions;
}

// F-score at the two thresholds and normal consistency of a repair R against a truth C:
// precision and a(R, C) from R's samples against C, recall and a(C, R) from C's against R.
void add_agreement(Recorder& out, const char* f_small, const char* f_large, const char* consistency,
                   const SampledAgreement& precision, const SampledAgreement& recall) {
  out.add(f_small, f_score(precision.within_fraction[0], recall.within_fraction[0]));
  out.add(f_large, f_score(precision.within_fraction[1], recall.within_fraction[1]));
  out.add(consistency, 0.5 * (precision.abs_cosine_mean + recall.abs_cosine_mean));
}

// face_area() of faces [first, end) of `mesh` (zero for a deleted face), at the cost of
// those faces: face_areas() of a range.
std::vector<double> areas_of_faces(const Mesh& mesh, std::size_t first, std::size_t end) {
  std::vector<double> areas(end - first, 0.0);
  for (std::size_t f = first; f < end; ++f) {
    const FaceHandle face(static_cast<int>(f));
    if (!mesh.status(face).deleted())
      areas[f - first] = face_area(mesh, face);
  }
  return areas;
}

// The sampled metrics' tallies of a repair that appends to the input and of the complete
// model against it, from the case's (the same sums and faces as sampled_faces()): the input's
// continued over the new faces; the complete model's against the input where no new face is
// one of its faces, else made anew from its areas.
struct KnownSampledFaces {
  std::optional<SampledFaces> repaired;
  std::optional<SampledFaces> complete_made;
  const SampledFaces* complete_known = nullptr;  // the case's, where no new face changes it
  // The complete model's tally: made here or the case's (a pointer into this struct is
  // taken only here, so that a copy of it never points into the one it was copied from).
  const SampledFaces* complete() const { return complete_made ? &*complete_made : complete_known; }
};
KnownSampledFaces known_sampled_faces(const Case& c, const Mesh& repaired,
                                      const SharedFaces& shared, const CaseEvaluation* known,
                                      const KeptFaces* kept) {
  KnownSampledFaces tallies;
  if (!known || !known->input_sampled_faces() || !kept || !kept->appends_to_input() ||
      repaired.n_faces() < c.input.n_faces())
    return tallies;
  const std::size_t first = c.input.n_faces();
  const std::vector<double> new_areas = areas_of_faces(repaired, first, repaired.n_faces());
  bool new_face_on_complete = false;
  for (std::size_t f = first; f < repaired.n_faces(); ++f)
    new_face_on_complete = new_face_on_complete || shared.b_face_of_a[f] >= 0;
  tallies.repaired = continued_tally(*known->input_sampled_faces());
  tally_faces(new_areas, &shared.b_face_of_a, first, *tallies.repaired);
  if (new_face_on_complete) {
    tallies.complete_made = sampled_faces(known->complete_face_areas(), &shared.a_face_of_b);
  } else {
    tallies.complete_known = known->complete_sampled_faces();
  }
  return tallies;
}

// The tally (literature_metrics.h, SampledFaces) of faces [first, end) of `mesh`, deleted
// faces left out, against the faces `b_face_of_a` marks shared.
SampledFaces tally_of_faces(const Mesh& mesh, std::size_t first, std::size_t end,
                            const std::vector<int>& b_face_of_a) {
  SampledFaces tally;
  tally_faces(areas_of_faces(mesh, first, end), &b_face_of_a, first, tally);
  return tally;
}

// The repair's samples against the complete model (precision and a(R, C)). Where the repair
// appends to the input and the input has faces off the complete model (noise), its input
// faces and its new faces are sampled apart, `samples` points each, and the two agreements
// weighed by their areas (combined_agreement): the input's part is the same for every
// method's repair, so the case computes it once (CaseEvaluation::input_agreement), and the
// new faces' samples are the hole region's patch samples where no new face lies on the
// complete model (`patch_answers`). Else one sampling of the repair's unshared faces.
SampledAgreement repaired_agreement(const Case& c, const Mesh& repaired,
                                    const embree::TriangleScene& complete_scene,
                                    const SampledAgreementOptions& sampling,
                                    const SharedFaces& shared, const KnownSampledFaces& tallies,
                                    const SampledAnswers& patch_answers,
                                    const CaseEvaluation* known, const KeptFaces* kept) {
  const std::size_t first = c.input.n_faces();
  std::optional<KeptFaces> own_kept;
  if (!kept && !known) {
    own_kept = kept_faces(c.input, repaired);
    kept = &*own_kept;
  }
  if (kept && kept->appends_to_input() && repaired.n_faces() >= first) {
    std::optional<SampledAgreement> input_part;
    if (known && known->input_sampled_faces()) {
      if (const SampledAgreement* case_part = known->input_agreement())
        input_part = *case_part;
    } else {
      const SampledFaces input_tally = tally_of_faces(repaired, 0, first, shared.b_face_of_a);
      if (input_tally.unshared_area > 0.0)
        input_part = sampled_agreement(repaired, complete_scene, sampling, &shared.b_face_of_a,
                                       nullptr, nullptr, &input_tally);
    }
    if (input_part) {
      const SampledFaces patch_tally =
          tally_of_faces(repaired, first, repaired.n_faces(), shared.b_face_of_a);
      return combined_agreement(
          *input_part, sampled_agreement(repaired, complete_scene, sampling, &shared.b_face_of_a,
                                         &patch_answers, nullptr, &patch_tally));
    }
  }
  return sampled_agreement(repaired, complete_scene, sampling, &shared.b_face_of_a, &patch_answers,
                           nullptr, tallies.repaired ? &*tallies.repaired : nullptr);
}

void add_literature_metrics(const Case& c, const MethodResult& result,
                            const std::vector<int>& new_faces, const EvaluationOptions& options,
                            double diagonal, const embree::TriangleScene& complete_scene,
                            const embree::TriangleScene& repaired_scene,
                            const RegionMeshes& regions, const CaseEvaluation* known,
                            const KeptFaces* kept, Recorder& out) {
  const SampledAgreementOptions sampling = literature_sampling_options(options, diagonal);
  // The hole region first: where the whole model's unshared faces are the hole region's (no
  // noise, a patch of new faces), the whole model's samples are its samples, and their
  // answers are taken from it (SampledAnswers: the same numbers). The truth's samples against
  // a repair whose scene is the input's plus its patch take the case's answers against the
  // input with the patch's added (input_cone_answers.h).
  std::optional<std::pair<SampledAgreement, SampledAgreement>> hole;
  SampledAnswers patch_answers, truth_answers;
  if (regions.truth && regions.patch) {
    SampledAgreementOptions hole_sampling = sampling;
    hole_sampling.samples = options.hole_literature_samples;
    const InputConeAnswers* truth_cones = known ? known->truth_cone_answers() : nullptr;
    std::optional<SampledAnswers> truth_known;
    if (truth_cones && repaired_scene.base_part() == &truth_cones->input_scene())
      truth_known = truth_cones->with_patch(repaired_scene.added_part());
    hole.emplace(sampled_agreement(*regions.patch, complete_scene, hole_sampling, nullptr, nullptr,
                                   &patch_answers),
                 sampled_agreement(*regions.truth, repaired_scene, hole_sampling, nullptr,
                                   truth_known ? &*truth_known : nullptr, &truth_answers));
  }
  // Faces the two models share exactly count exactly (distance 0, the same normal).
  const SharedFaces& shared = regions.shared;
  const KnownSampledFaces tallies = known_sampled_faces(c, result.repaired, shared, known, kept);
  // The complete model's samples against the repair: where they are the case's samples and
  // the repair's scene is the input's plus its patch, the case's answers against the input
  // with the patch's added (input_cone_answers.h: the same numbers), unless the hole region
  // answered them already.
  const SampledAnswers* complete_answers = &truth_answers;
  SampledAnswers with_patch;
  const InputConeAnswers* input_cones = known ? known->complete_cone_answers() : nullptr;
  if (input_cones && tallies.complete() == known->complete_sampled_faces() &&
      repaired_scene.base_part() == &input_cones->input_scene() &&
      truth_answers.points != input_cones->points()) {
    with_patch = input_cones->with_patch(repaired_scene.added_part());
    complete_answers = &with_patch;
  }
  add_agreement(out, kFScore0p5PctFraction, kFScore1PctFraction, kNormalConsistencyFraction,
                repaired_agreement(c, result.repaired, complete_scene, sampling, shared, tallies,
                                   patch_answers, known, kept),
                sampled_agreement(c.complete, repaired_scene, sampling, &shared.a_face_of_b,
                                  complete_answers, nullptr, tallies.complete()));
  if (hole) {
    add_agreement(out, kHoleFScore0p5PctFraction, kHoleFScore1PctFraction,
                  kHoleNormalConsistencyFraction, hole->first, hole->second);
  }
  EdgeChamferOptions edge_options;
  edge_options.edge_sample_spacing = options.edge_sample_spacing_rel_diag * diagonal;
  if (const auto edge = edge_chamfer_distance(c.complete, removed_faces(c), result.repaired,
                                              edge_options, &new_faces))
    out.add(kHoleEdgeChamferRelDiag, *edge / diagonal);
}

void add_feature_recovery(const Case& c, const MethodResult& result,
                          const EvaluationOptions& options, double diagonal,
                          const embree::TriangleScene& complete_scene,
                          const FeatureRecoveryShortcuts& shortcuts, Recorder& out) {
  FeatureRecoveryOptions feature_options;
  feature_options.edge_sample_spacing = options.edge_sample_spacing_rel_diag * diagonal;
  feature_options.edge_tolerance = options.edge_tolerance_rel_diag * diagonal;
  feature_options.edge_search_radius = options.edge_search_radius_rel_diag * diagonal;
  feature_options.normal_cone.tolerance = options.normal_cone_tolerance_rel_diag * diagonal;
  const FeatureRecovery f =
      feature_recovery(c, result.repaired, complete_scene, feature_options, shortcuts);
  if (!f.corner_errors.empty()) {
    double sum = 0.0, largest = 0.0;
    for (double e : f.corner_errors) {
      sum += e;
      largest = std::max(largest, e);
    }
    out.add(kMissingCornerErrorMeanRelDiag, sum / f.corner_errors.size() / diagonal);
    out.add(kMissingCornerErrorMaxRelDiag, largest / diagonal);
  }
  if (!f.edges.empty()) {
    std::size_t present = 0;
    double covered = 0.0, largest = 0.0;
    bool any_distance = false;
    for (const auto& e : f.edges) {
      present += e.present;
      covered += e.covered_fraction;
      if (e.distance) {
        any_distance = true;
        largest = std::max(largest, *e.distance);
      }
    }
    out.add(kMissingEdgePresentFraction, fraction(present, f.edges.size()));
    out.add(kMissingEdgeCoveredFraction, covered / f.edges.size());
    if (any_distance)
      out.add(kMissingEdgeDistanceMaxRelDiag, largest / diagonal);
  }
  if (f.normal_deviation_mean_deg) {
    out.add(kPatchNormalDeviationMeanDeg, *f.normal_deviation_mean_deg);
    out.add(kPatchNormalDeviationMaxDeg, *f.normal_deviation_max_deg);
  }
}

// A valid repair: every hole closed (by the method's reports and by the output having no
// boundary), manifold, consistently oriented, no self-intersection with a new face, the input
// away from the holes unchanged. Recorded only where self-intersections were tested.
bool valid_repair(const MethodResult& result, const Validity& v) {
  const bool holes_closed = std::all_of(result.holes.begin(), result.holes.end(),
                                        [](const HoleReport& h) { return h.closed; });
  return holes_closed && v.open_boundary_loops == 0 && v.non_manifold_vertices == 0 &&
         v.orientation_conflicts == 0 && v.patch_self_intersections == 0 &&
         v.original_faces_changed == 0;
}

void add_validity(const Case& c, const MethodResult& result, const std::vector<int>& new_faces,
                  const EvaluationOptions& options, double diagonal, const CaseEvaluation* shared,
                  const KeptFaces* kept, const embree::TriangleScene* repaired_scene,
                  Recorder& out) {
  ValidityOptions validity_options;
  validity_options.degenerate_area = options.degenerate_area_rel_diag2 * diagonal * diagonal;
  validity_options.self_intersections = options.self_intersections;
  ValidityShortcuts known;
  known.input_pairs = shared ? shared->input_self_intersections() : nullptr;
  known.kept_of_input = kept;
  known.topology = shared ? &shared->input_topology() : nullptr;
  known.repaired_scene = repaired_scene;
  known.new_faces = &new_faces;
  const Validity v = validity(c.input, result.repaired, validity_options, known);
  out.add_count(kOpenBoundaryLoopsCount, v.open_boundary_loops);
  out.add_flag(kIsClosed, v.open_boundary_loops == 0);
  out.add_count(kNonManifoldVerticesCount, v.non_manifold_vertices);
  out.add_flag(kIsManifold, v.non_manifold_vertices == 0);
  out.add_flag(kIsConsistentlyOriented, v.orientation_conflicts == 0);
  if (v.self_intersections_tested) {
    out.add_count(kSelfIntersectionsCount, v.self_intersections);
    out.add_count(kPatchSelfIntersectionsCount, v.patch_self_intersections);
  }
  out.add_count(kNewFacesCount, new_faces.size());
  out.add_count(kInputFacesCount, c.input.n_faces());
  out.add_count(kNewDegenerateFacesCount, v.new_degenerate_faces);
  out.add_count(kOriginalFacesChangedCount, v.original_faces_changed);
  out.add_flag(kOriginalFacesUnchangedOk, v.original_faces_changed == 0);
  if (v.self_intersections_tested)
    out.add_flag(kValidRepairOk, valid_repair(result, v));
}

void add_classification(const Case& c, const MethodResult& result,
                        const std::vector<HoleMatch>& matches, Recorder& out) {
  const ClassificationAccuracy a = classification_accuracy(c, result, matches);
  if (a.compared == 0)
    return;
  out.add(kClassificationKCorrectFraction, fraction(a.k_correct, a.compared));
  if (a.orientation_compared > 0)
    out.add(kClassificationOrientationCorrectFraction,
            fraction(a.orientation_correct, a.orientation_compared));
  out.add(kClassificationConvexityCorrectFraction, fraction(a.convexity_correct, a.compared));
  if (a.boundary_kind_compared > 0)
    out.add(kClassificationBoundaryKindCorrectFraction,
            fraction(a.boundary_kind_correct, a.boundary_kind_compared));
  out.add(kClassificationDecisionCorrectFraction, fraction(a.decision_correct, a.compared));
  out.add(kClassificationAllCorrectFraction, fraction(a.all_correct, a.compared));
  out.add(kDecisionHandledFraction, fraction(a.decision_handled, a.compared));
}

void add_arrows(const Case& c, const MethodResult& result, const std::vector<HoleMatch>& matches,
                const EvaluationOptions& options, double diagonal,
                const embree::TriangleScene& complete_scene, Recorder& out) {
  embree::ArrowVisibilityOptions arrow_options;
  arrow_options.field_of_view_degrees = options.arrow_field_of_view_degrees;
  arrow_options.sample_spacing = options.arrow_sample_spacing_rel_diag * diagonal;
  arrow_options.search_directions = options.arrow_search_directions;
  arrow_options.surface_tolerance = 1e-7 * diagonal;
  std::unique_ptr<embree::TriangleScene> holed_scene;
  std::size_t arrows = 0, outside = 0, shaft_free = 0, undefined = 0;
  double visible = 0.0, best = 0.0, error = 0.0;
  for (std::size_t i = 0; i < result.holes.size(); ++i) {
    const auto& report = result.holes[i];
    if (!report.arrow || matches[i].truth < 0)
      continue;
    if (!is_finite(*report.arrow)) {
      ++undefined;  // no ray can be cast along it; counted, not measured
      continue;
    }
    const auto& truth = c.holes[matches[i].truth];
    const auto samples = embree::sample_faces(c.complete, truth.removed_faces, arrow_options);
    if (samples.points.empty())
      continue;
    if (!holed_scene)
      holed_scene = std::make_unique<embree::TriangleScene>(c.input);
    const auto q =
        embree::arrow_quality(*report.arrow, samples, complete_scene, *holed_scene, arrow_options);
    ++arrows;
    outside += q.position_outside;
    shaft_free += q.shaft_free;
    visible += q.visible_fraction;
    best += q.best_visible_fraction;
    error += q.direction_error_deg;
  }
  if (undefined > 0)
    out.add_count(kArrowsUndefinedCount, undefined);
  if (arrows == 0)
    return;
  out.add_count(kArrowsCount, arrows);
  out.add_flag(kArrowPositionOutsideOk, outside == arrows);
  out.add_flag(kArrowShaftFreeOk, shaft_free == arrows);
  out.add(kArrowVisibleFraction, visible / arrows);
  out.add(kArrowBestVisibleFraction, best / arrows);
  out.add(kArrowDirectionErrorDeg, error / arrows);
}

// The share of the reported holes that a stand-in handled instead of the method's own path
// (HoleReport::fallback); absent when the method reported no hole.
void add_fallbacks(const MethodResult& result, Recorder& out) {
  if (result.holes.empty())
    return;
  const auto fallbacks = std::count_if(result.holes.begin(), result.holes.end(),
                                       [](const HoleReport& h) { return !h.fallback.empty(); });
  out.add(kFallbackHolesFraction,
          fraction(static_cast<std::size_t>(fallbacks), result.holes.size()));
  const auto defects = std::count_if(result.holes.begin(), result.holes.end(),
                                     [](const HoleReport& h) { return !h.defect.empty(); });
  out.add(kDefectHolesFraction, fraction(static_cast<std::size_t>(defects), result.holes.size()));
}

// The repair's scene: where it keeps every input face in the input's order, the case's scene
// of the input and a scene of the rest (the patch), at the patch's cost; else its own. The
// answers are the same either way (triangle_scene.h).
std::unique_ptr<embree::TriangleScene> repaired_scene_of(const Mesh& repaired,
                                                         const CaseEvaluation* shared,
                                                         const KeptFaces* kept) {
  if (shared && kept && shared->input_scene() && kept->order_kept &&
      kept->every_input_face_kept()) {
    return std::make_unique<embree::TriangleScene>(
        *shared->input_scene(), kept->repaired_face_of_input, kept->input_face_of_repaired,
        repaired, kept->repaired_faces_not_kept);
  }
  return std::make_unique<embree::TriangleScene>(repaired);
}

// A real hole's metrics (no ground truth): the patch's quality, the validity, the fallbacks.
void add_no_truth_metrics(const Case& c, const MethodResult& result,
                          const EvaluationOptions& options, double diagonal, Recorder& out,
                          PhaseLaps& laps) {
  const PatchQuality q = patch_quality(result.repaired);
  const auto add = [&out](const char* name, const std::optional<double>& value) {
    if (value)
      out.add(name, *value);
  };
  add(kPatchBoundaryNormalJumpMeanDeg, q.boundary_normal_jump_mean_deg);
  add(kPatchBoundaryNormalJumpMaxDeg, q.boundary_normal_jump_max_deg);
  add(kPatchDihedralMeanDeg, q.dihedral_mean_deg);
  add(kPatchDihedralMaxDeg, q.dihedral_max_deg);
  add(kPatchTriangleQualityMinFraction, q.triangle_quality_min);
  add(kPatchTriangleQualityMeanFraction, q.triangle_quality_mean);
  laps.lap(evaluation_phases::kPatchQuality);
  add_validity(c, result, new_face_indices(result.repaired), options, diagonal, nullptr, nullptr,
               nullptr, out);
  laps.lap(evaluation_phases::kValidity);
  add_fallbacks(result, out);
}

// The metrics, with what the case's jobs share given (`shared`) or made here.
Evaluation evaluate_with(const Case& c, const MethodResult& result,
                         const EvaluationOptions& options, const CaseEvaluation* shared) {
  const embree::TriangleScene* shared_complete_scene = shared ? shared->complete_scene() : nullptr;
  Evaluation evaluation;
  Recorder out(evaluation.values);
  PhaseLaps laps(evaluation.phases);
  const double diagonal = shared ? shared->diagonal() : bounding_box_diagonal(c.complete);
  if (!(diagonal > 0.0) || c.complete.n_faces() == 0)
    return evaluation;  // no ground truth to measure against
  if (!c.has_ground_truth) {
    add_no_truth_metrics(c, result, options, diagonal, out, laps);
    return evaluation;
  }
  std::unique_ptr<embree::TriangleScene> own_complete_scene;
  if (!shared_complete_scene) {
    own_complete_scene = std::make_unique<embree::TriangleScene>(c.complete);
    laps.lap(evaluation_phases::kCompleteScene);
  }
  const embree::TriangleScene& complete_scene =
      shared_complete_scene ? *shared_complete_scene : *own_complete_scene;
  // The input's faces the repair kept, where the case's jobs share what is known of them.
  std::optional<KeptFaces> kept;
  SharedFirstBounds first;
  if (shared) {
    kept = kept_faces(c.input, result.repaired);
    first = shared_first_bounds(c, result, shared, &*kept);
    laps.lap(evaluation_phases::kKeptFaces);
  }
  // The repair's new faces, found once for the patch, the edges around it and the counts.
  const std::vector<int> new_faces = new_face_indices(result.repaired);
  std::unique_ptr<embree::TriangleScene> repaired_scene_owner;
  if (result.repaired.n_faces() > 0) {
    repaired_scene_owner = repaired_scene_of(result.repaired, shared, kept ? &*kept : nullptr);
    const embree::TriangleScene& repaired_scene = *repaired_scene_owner;
    laps.lap(evaluation_phases::kRepairedScene);
    const RegionMeshes regions = add_distances(c, result, new_faces, options, diagonal,
                                               complete_scene, repaired_scene, first, out, laps);
    if (options.literature_metrics) {
      add_literature_metrics(c, result, new_faces, options, diagonal, complete_scene,
                             repaired_scene, regions, shared, kept ? &*kept : nullptr, out);
      laps.lap(evaluation_phases::kLiteratureMetrics);
    }
    // What the case knows of the input, where the repair kept it (feature_recovery.h).
    FeatureRecoveryShortcuts shortcuts;
    shortcuts.new_faces = &new_faces;
    if (shared && kept) {
      if (kept->input_vertices_kept)
        shortcuts.input_corner_distances = &shared->input_corner_distances();
      shortcuts.input_face_regions = &shared->input_face_regions();
      shortcuts.kept = &*kept;
      shortcuts.repaired_scene = &repaired_scene;
    }
    add_feature_recovery(c, result, options, diagonal, complete_scene, shortcuts, out);
    laps.lap(evaluation_phases::kFeatureRecovery);
  }
  add_validity(c, result, new_faces, options, diagonal, shared, kept ? &*kept : nullptr,
               shared ? repaired_scene_owner.get() : nullptr, out);
  laps.lap(evaluation_phases::kValidity);
  // The reports' holes, matched once for the classification and the arrows.
  const std::vector<HoleMatch> matches =
      shared ? match_holes(c, result.holes, shared->input_loop_centroids())
             : match_holes(c, result.holes);
  add_classification(c, result, matches, out);
  laps.lap(evaluation_phases::kClassification);
  add_arrows(c, result, matches, options, diagonal, complete_scene, out);
  laps.lap(evaluation_phases::kArrowVisibility);
  add_fallbacks(result, out);  // a count of the hole reports: no time worth a phase
  return evaluation;
}

}  // namespace

Evaluation evaluate(const Case& c, const MethodResult& result, const EvaluationOptions& options) {
  return evaluate_with(c, result, options, nullptr);
}

Evaluation evaluate(const Case& c, const MethodResult& result, const EvaluationOptions& options,
                    const CaseEvaluation& shared) {
  return evaluate_with(c, result, options, &shared);
}

}  // namespace holebench
