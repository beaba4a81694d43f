#include "metrics/case_evaluation.h"

#include "core/geometry.h"
#include "core/region_segmentation.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/face_subset.h"
#include "metrics/feature_recovery.h"
#include "metrics/hole_matching.h"

namespace holebench {

CaseEvaluation::CaseEvaluation(const Case& c, const EvaluationOptions& options) {
  diagonal_ = bounding_box_diagonal(c.complete);
  const double diagonal = diagonal_;
  if (c.complete.n_faces() > 0 && diagonal > 0.0) {
    complete_scene_ = std::make_unique<embree::TriangleScene>(c.complete);
    const MeanDistanceOptions mean = whole_model_distance_options(options, diagonal).mean;
    // One first pass of the input against the complete model for both of its tables.
    const FirstPass input_pass = first_pass(c.input, c.complete, *complete_scene_);
    shared_faces_of_input_ = std::make_unique<SharedFacesOfInput>(c.input, c.complete);
    input_cell_bounds_ =
        std::make_unique<MeanCellBounds>(c.input, *complete_scene_, input_pass, mean);
    input_hausdorff_bounds_ =
        std::make_unique<HausdorffCellBounds>(c.input, *complete_scene_, input_pass);
    appended_repair_starts_ = std::make_unique<AppendedRepairStarts>(
        c.input, c.complete, input_pass, shared_faces_of_input_->of_input());
    const SharedFaces& input_shared = shared_faces_of_input_->of_input();
    input_sampled_faces_ = sampled_faces(face_areas(c.input), &input_shared.b_face_of_a);
    complete_face_areas_ = face_areas(c.complete);
    complete_sampled_faces_ = sampled_faces(complete_face_areas_, &input_shared.a_face_of_b);
    if (options.literature_metrics && input_sampled_faces_->unshared_area > 0.0) {
      input_agreement_ = sampled_agreement(
          c.input, *complete_scene_, literature_sampling_options(options, diagonal),
          &input_shared.b_face_of_a, nullptr, nullptr, &*input_sampled_faces_);
    }
    if (c.input.n_faces() > 0) {
      input_scene_ = std::make_unique<embree::TriangleScene>(c.input);
      // One first pass of the complete model against the input for both of its tables.
      const FirstPass complete_pass = first_pass(c.complete, c.input, *input_scene_);
      complete_cell_bounds_ =
          std::make_unique<MeanCellBounds>(c.complete, *input_scene_, complete_pass, mean);
      complete_hausdorff_bounds_ =
          std::make_unique<HausdorffCellBounds>(c.complete, *input_scene_, complete_pass);
      if (options.literature_metrics) {
        NormalConeOptions cone;
        cone.tolerance = options.normal_cone_tolerance_rel_diag * diagonal;
        complete_cone_answers_ = std::make_unique<InputConeAnswers>(
            tally_samples(c.complete, options.literature_samples, *complete_sampled_faces_),
            *input_scene_, cone);
        // The hole region's truth (the removed faces) is sampled as each job samples it
        // (every face, literature_metrics.h), its cones asked of the input once here.
        const std::vector<int> removed = removed_faces(c);
        if (!removed.empty()) {
          const Mesh truth = face_subset(c.complete, removed);
          truth_cone_answers_ = std::make_unique<InputConeAnswers>(
              tally_samples(truth, options.hole_literature_samples,
                            sampled_faces(face_areas(truth), nullptr)),
              *input_scene_, cone);
        }
      }
    }
  }
  if (options.self_intersections)
    input_self_intersections_ = holebench::input_self_intersections(c.input);
  input_topology_ = holebench::input_topology(c.input);
  input_loop_centroids_ = holebench::input_loop_centroids(c);
  input_corner_distances_ = holebench::input_corner_distances(c);
  input_face_regions_ =
      segment_regions(c.input, FeatureRecoveryOptions{}.features.segmentation).face_region;
}

CaseEvaluation::~CaseEvaluation() = default;

}  // namespace holebench
