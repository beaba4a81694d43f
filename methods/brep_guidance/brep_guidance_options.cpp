// BrepGuidanceMethod::options: every setting of BrepGuidanceOptions, as records report them.
#include "methods/brep_guidance/brep_guidance.h"

namespace holebench {

namespace {

using namespace brep_guidance;

const char* name_of(Figure3Rule rule) {
  switch (rule) {
    case Figure3Rule::TransitionHalfEdges:
      return "transition_half_edges";
    case Figure3Rule::NearestHoleVertices:
      return "nearest_hole_vertices";
  }
  return "unknown";
}

const char* name_of(FaceSource source) {
  switch (source) {
    case FaceSource::InputWhenPresent:
      return "input_when_present";
    case FaceSource::Segmentation:
      return "segmentation";
  }
  return "unknown";
}

MethodOptions options_of(const PlanarSegmentationOptions& o) {
  return MethodOptions()
      .add("max_normal_angle_degrees", o.max_normal_angle_degrees)
      .add("residual_factor", o.residual_factor)
      .add("min_tolerance_rel_diag", o.min_tolerance_rel_diag)
      .add("min_region_faces", o.min_region_faces);
}

}  // namespace

MethodOptions BrepGuidanceMethod::options() const {
  return MethodOptions()
      .add("default_structure_size_rel_diag", options_.default_structure_size_rel_diag)
      .add("arrow_distance_rel_diag", options_.arrow_distance_rel_diag)
      .add("dependence_tolerance", options_.dependence_tolerance)
      .add("figure_3_rule", name_of(options_.figure_3_rule))
      .add("faces", name_of(options_.faces))
      .add("segmentation", options_of(options_.segmentation))
      .add("later_closing_attempts", options_.later_closing_attempts);
}

}  // namespace holebench
