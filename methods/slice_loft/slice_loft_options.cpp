// SliceLoftMethod::options: every setting of SliceLoftOptions, as records report them.
#include "methods/slice_loft/slice_loft.h"

namespace holebench {

namespace {

using namespace slice_loft;

MethodOptions options_of(const HoleIdentificationOptions& o) {
  return MethodOptions()
      .add("influence_margin_rel_box", o.influence_margin_rel_box)
      .add("min_influence_margin_edges", o.min_influence_margin_edges);
}

MethodOptions options_of(const BoundarySegmentationOptions& o) {
  return MethodOptions()
      .add("min_threshold_degrees", o.min_threshold_degrees)
      .add("max_threshold_degrees", o.max_threshold_degrees)
      .add("min_segment_edges", o.min_segment_edges)
      .add("min_region_faces", o.min_region_faces);
}

MethodOptions options_of(const MissingFeatureOptions& o) {
  return MethodOptions()
      .add("segmentation", options_of(o.segmentation))
      .add("baseline_edges", o.baseline_edges)
      .add("step_edges", o.step_edges)
      .add("max_turn_degrees", o.max_turn_degrees)
      .add("through_edge_cosine", o.through_edge_cosine)
      .add("reject_far_corner", o.reject_far_corner)
      .add("corner_tolerance_rel_box", o.corner_tolerance_rel_box);
}

const char* name_of(SlicingDirection direction) {
  switch (direction) {
    case SlicingDirection::LongerBoxEdge:
      return "longer_box_edge";
    case SlicingDirection::MajorAxis:
      return "major_axis";
  }
  return "unknown";
}

const char* name_of(SectionExtent extent) {
  switch (extent) {
    case SectionExtent::HoleBoundary:
      return "hole_boundary";
    case SectionExtent::InfluencingArea:
      return "influencing_area";
  }
  return "unknown";
}

const char* name_of(GapTracing tracing) {
  switch (tracing) {
    case GapTracing::OneEnd:
      return "one_end";
    case GapTracing::BothEnds:
      return "both_ends";
  }
  return "unknown";
}

MethodOptions options_of(const CompositeSurfaceOptions& o) {
  return MethodOptions()
      .add("direction", name_of(o.direction))
      .add("extent", name_of(o.extent))
      .add("tracing", name_of(o.tracing))
      .add("slices", o.slices)
      .add("max_slice_spacing_edges", o.max_slice_spacing_edges)
      .add("extra_slices", o.extra_slices)
      .add("baseline_edges", o.baseline_edges)
      .add("step_edges", o.step_edges)
      .add("max_turn_degrees", o.max_turn_degrees)
      .add("section_sample_edges", o.section_sample_edges);
}

MethodOptions options_of(const TessellationOptions& o) {
  return MethodOptions()
      .add("spacing_edges", o.spacing_edges)
      .add("clearance", o.clearance)
      .add("direct", o.direct)
      .add("feature_snap_edges", o.feature_snap_edges)
      .add("max_chord_splits", o.max_chord_splits)
      .add("developed_disc", o.developed_disc)
      .add("plane_first", o.plane_first);
}

}  // namespace

MethodOptions SliceLoftMethod::options() const {
  return MethodOptions()
      .add("identification", options_of(options_.identification))
      .add("segmentation", options_of(options_.segmentation))
      .add("features", options_of(options_.features))
      .add("surface", options_of(options_.surface))
      .add("tessellation", options_of(options_.tessellation));
}

}  // namespace holebench
