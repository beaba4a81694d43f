// Method brep_guidance: section 3 of "B-Rep hole closing and user guidance"
// (../shared/papers/brep-hole-closing-and-user-guidance.txt). Every hole is detected
// (Algorithm 1), classified (cardinality, convexity at each transition by figure 3,
// orientation by equations 1 and 2, boundary kinds, size), then either closed exactly
// (inner, k <= 3, smaller than the structure size delta_s, and the user agrees: the paper's
// case a) or given a guidance arrow (equations 3-5: cases b and c).
#pragma once

#include "core/planar_segmentation.h"
#include "methods/brep_guidance/brep_faces.h"
#include "methods/brep_guidance/hole_classification.h"
#include "methods/method.h"

namespace holebench {

struct BrepGuidanceOptions {
  /// delta_s relative to the input's bounding-box diagonal, used when the experiment gives
  /// no structure size (MethodParameters::structure_size = 0).
  double default_structure_size_rel_diag = 0.06;
  /// The arrow's distance d from the hole (equations 3-5), relative to the input's diagonal.
  double arrow_distance_rel_diag = 0.3;
  /// Triple product (k = 3) or cross product (k = 2) of unit normals below which the faces
  /// count as linearly dependent.
  double dependence_tolerance = 1e-3;
  /// How figure 3 reads the convexity at a transition (hole_classification.h).
  brep_guidance::Figure3Rule figure_3_rule = brep_guidance::Figure3Rule::TransitionHalfEdges;
  /// Where the faces come from: the input's B-Rep face ids where it carries them (the
  /// paper's input), or always a segmentation (method id brep_guidance_segmented).
  brep_guidance::FaceSource faces = brep_guidance::FaceSource::InputWhenPresent;
  /// Segmentation used when the input has no region ids (or `faces` asks for it).
  PlanarSegmentationOptions segmentation;
  /// Where figure 4's closing fails, the project's later closing attempts
  /// (exact_closing.h; brep_guidance_plus) before the hole is guided instead; off: the
  /// paper's closing alone.
  bool later_closing_attempts = false;
};

/// Runs the method on `holed`. Never sees ground truth: the structure size is a setting of
/// the experiment, and agreement comes from `user`.
MethodResult run_brep_guidance(const Mesh& holed, const MethodParameters& parameters, User& user,
                               const BrepGuidanceOptions& options = {});

class BrepGuidanceMethod final : public Method {
 public:
  explicit BrepGuidanceMethod(BrepGuidanceOptions options = {}) : options_(options) {}
  /// The variant that segments the input even where it carries B-Rep face ids, to measure
  /// what the segmentation costs against the exact faces.
  static BrepGuidanceOptions segmented() {
    BrepGuidanceOptions options;
    options.faces = brep_guidance::FaceSource::Segmentation;
    return options;
  }
  /// The variant with the project's later closing attempts after figure 4's plan fails.
  static BrepGuidanceOptions plus() {
    BrepGuidanceOptions options;
    options.later_closing_attempts = true;
    return options;
  }
  std::string id() const override {
    if (options_.later_closing_attempts)
      return "brep_guidance_plus";
    return options_.faces == brep_guidance::FaceSource::Segmentation ? "brep_guidance_segmented"
                                                                     : "brep_guidance";
  }
  std::string description() const override {
    if (options_.later_closing_attempts)
      return "brep_guidance with the project's later closing attempts where figure 4's "
             "closing fails (docs/methods.md)";
    if (options_.faces == brep_guidance::FaceSource::Segmentation)
      return "brep_guidance with faces always from planar segmentation, even where the input "
             "carries B-Rep face ids";
    return "B-Rep paper: hole classification, exact closing of small inner holes (k <= 3), "
           "guidance arrows for the rest";
  }
  MethodOptions options() const override;
  MethodResult run(const Mesh& holed, const MethodParameters& parameters,
                   User& user) const override {
    return run_brep_guidance(holed, parameters, user, options_);
  }

 private:
  BrepGuidanceOptions options_;
};

}  // namespace holebench
