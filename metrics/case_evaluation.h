// What the evaluations of one case share, whatever the method: built once per case instance
// (the runner builds it beside the case, in the process its jobs are forked from) and read
// by evaluate() for every method's result. It changes no number: evaluate() with it gives
// the same metrics as without it, in less time.
#pragma once

#include "core/case.h"
#include "metrics/appended_repair_starts.h"
#include "metrics/evaluation.h"
#include "metrics/input_cone_answers.h"
#include "metrics/input_topology.h"
#include "metrics/literature_metrics.h"
#include "metrics/surface_distance.h"
#include "metrics/validity.h"

#include <memory>
#include <optional>
#include <vector>

namespace holebench {

namespace embree {
class TriangleScene;
}

class CaseEvaluation {
 public:
  /// Builds the complete model's Embree scene; the first bounds of the whole model's mean
  /// searches (surface_distance.h, MeanCellBounds): of the input's faces against the
  /// complete model (the faces a repair keeps need none of their own) and of the complete
  /// model's faces against the input (a repair is the input away from its new faces); the
  /// same two tables for the Hausdorff searches (hausdorff_distance.h, HausdorffCellBounds);
  /// where the searches of a repair that appends to the input start
  /// (appended_repair_starts.h) and the faces' areas; the normal cones at the complete
  /// model's and the hole region's truth's literature samples against the input
  /// (input_cone_answers.h); where `options` test self-intersections, the input's own
  /// intersecting pairs (validity.h); and the input's topology, loop centroids and nearest
  /// vertices to the missing corners, so that each job's validity, hole matching and corner
  /// errors look at its changes only.
  CaseEvaluation(const Case& c, const EvaluationOptions& options);
  ~CaseEvaluation();
  CaseEvaluation(const CaseEvaluation&) = delete;
  CaseEvaluation& operator=(const CaseEvaluation&) = delete;

  /// The complete model's bounding-box diagonal (every length is relative to it).
  double diagonal() const { return diagonal_; }
  /// The complete model's scene, or nullptr where the case has no complete model.
  const embree::TriangleScene* complete_scene() const { return complete_scene_.get(); }
  /// The input's scene, or nullptr where the case has no complete model or no input faces.
  const embree::TriangleScene* input_scene() const { return input_scene_.get(); }
  /// The faces the input shares with the complete model, and what matching a repair's own
  /// faces needs (shared_faces.h), or nullptr where the case has no complete model.
  const SharedFacesOfInput* shared_faces_of_input() const { return shared_faces_of_input_.get(); }
  /// The input's faces' first bounds against the complete model, or nullptr.
  const MeanCellBounds* input_cell_bounds() const { return input_cell_bounds_.get(); }
  /// The complete model's faces' first bounds against the input, or nullptr.
  const MeanCellBounds* complete_cell_bounds() const { return complete_cell_bounds_.get(); }
  /// Where the whole model's searches of a repair that appends to the input start, or
  /// nullptr where the case has no complete model.
  const AppendedRepairStarts* appended_repair_starts() const {
    return appended_repair_starts_.get();
  }
  /// The sampled metrics' tallies (literature_metrics.h, SampledFaces) of the input against
  /// the complete model and of the complete model against the input, and the complete
  /// model's face areas (face_areas()), or nullptr where the case has no complete model.
  const SampledFaces* input_sampled_faces() const {
    return input_sampled_faces_ ? &*input_sampled_faces_ : nullptr;
  }
  const SampledFaces* complete_sampled_faces() const {
    return complete_sampled_faces_ ? &*complete_sampled_faces_ : nullptr;
  }
  const std::vector<double>& complete_face_areas() const { return complete_face_areas_; }
  /// The input's literature samples against the complete model: sampled_agreement() over the
  /// input's faces off the complete model, as the whole model's metrics sample a repair that
  /// appends to the input (evaluation.cpp, repaired_agreement), or nullptr where the case has
  /// no complete model, no literature metrics or no input face off the complete model.
  const SampledAgreement* input_agreement() const {
    return input_agreement_ ? &*input_agreement_ : nullptr;
  }
  /// The normal cones at the complete model's literature samples (the points its tally
  /// gives) against the input (input_cone_answers.h), or nullptr where the case has no
  /// complete model, no input faces or no literature metrics.
  const InputConeAnswers* complete_cone_answers() const { return complete_cone_answers_.get(); }
  /// The same at the hole region's truth's samples (the removed faces, sampled as the hole
  /// region's literature metrics sample them), or nullptr where the case has no removed
  /// faces either.
  const InputConeAnswers* truth_cone_answers() const { return truth_cone_answers_.get(); }
  /// The input's faces' first Hausdorff bounds against the complete model, or nullptr.
  const HausdorffCellBounds* input_hausdorff_bounds() const {
    return input_hausdorff_bounds_.get();
  }
  /// The complete model's faces' first Hausdorff bounds against the input, or nullptr.
  const HausdorffCellBounds* complete_hausdorff_bounds() const {
    return complete_hausdorff_bounds_.get();
  }
  /// The input's own intersecting pairs, or nullptr where they were not computed.
  const InputSelfIntersections* input_self_intersections() const {
    return input_self_intersections_ ? &*input_self_intersections_ : nullptr;
  }
  /// The input's boundary loops, non-manifold vertices and orientation conflicts.
  const InputTopology& input_topology() const { return input_topology_; }
  /// The centroids of the input's boundary loops (hole_matching.h).
  const std::vector<Point>& input_loop_centroids() const { return input_loop_centroids_; }
  /// The input's regions by face (segment_regions with the feature recovery's options), for
  /// the repair's sharp edges near the missing ones (feature_recovery.h).
  const std::vector<int>& input_face_regions() const { return input_face_regions_; }
  /// Per missing corner, the distance to the nearest input vertex (feature_recovery.h).
  const std::vector<double>& input_corner_distances() const { return input_corner_distances_; }

 private:
  double diagonal_ = 0.0;
  std::unique_ptr<embree::TriangleScene> complete_scene_;
  std::unique_ptr<embree::TriangleScene> input_scene_;
  std::unique_ptr<SharedFacesOfInput> shared_faces_of_input_;
  std::unique_ptr<MeanCellBounds> input_cell_bounds_;
  std::unique_ptr<MeanCellBounds> complete_cell_bounds_;
  std::unique_ptr<HausdorffCellBounds> input_hausdorff_bounds_;
  std::unique_ptr<HausdorffCellBounds> complete_hausdorff_bounds_;
  std::unique_ptr<AppendedRepairStarts> appended_repair_starts_;
  std::optional<SampledFaces> input_sampled_faces_;
  std::optional<SampledFaces> complete_sampled_faces_;
  std::optional<SampledAgreement> input_agreement_;
  std::unique_ptr<InputConeAnswers> complete_cone_answers_;
  std::unique_ptr<InputConeAnswers> truth_cone_answers_;
  std::vector<double> complete_face_areas_;
  std::optional<InputSelfIntersections> input_self_intersections_;
  InputTopology input_topology_;
  std::vector<Point> input_loop_centroids_;
  std::vector<double> input_corner_distances_;
  std::vector<int> input_face_regions_;
};

/// evaluate() with what the case's evaluations share; `shared` must have been built from the
/// same case and options. The same metrics as evaluate(c, result, options).
Evaluation evaluate(const Case& c, const MethodResult& result, const EvaluationOptions& options,
                    const CaseEvaluation& shared);

}  // namespace holebench
