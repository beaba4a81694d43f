// CrestFeatureMethod::options: every setting of CrestFeatureOptions, as records report them.
#include "methods/crest_feature/crest_feature.h"

namespace holebench {

namespace {

using namespace crest_feature;

MethodOptions options_of(const CrestLineOptions& o) {
  return MethodOptions()
      .add("jet_degree", o.jet_degree)
      .add("min_rings", o.min_rings)
      .add("max_rings", o.max_rings)
      .add("min_fit_points", o.min_fit_points)
      .add("min_mean_curvature_times_edge", o.min_mean_curvature_times_edge)
      .add("min_segments", o.min_segments)
      .add("band_rings", o.band_rings)
      .add("sharp_crease_angle_degrees", o.sharp_crease_angle_degrees)
      .add("sharp_crease_bend_degrees", o.sharp_crease_bend_degrees)
      .add("sharp_crease_clearance_edges", o.sharp_crease_clearance_edges);
}

MethodOptions options_of(const HoleIdentificationOptions& o) {
  return MethodOptions().add("attach_islands", o.attach_islands);
}

MethodOptions options_of(const FeaturePointOptions& o) {
  return MethodOptions()
      .add("reach_edges", o.reach_edges)
      .add("ray_tolerance_edges", o.ray_tolerance_edges)
      .add("tangent_radius_edges", o.tangent_radius_edges)
      .add("merge_edges", o.merge_edges)
      .add("adopt_crest_line_edges", o.adopt_crest_line_edges)
      .add("pair_max_angle_degrees", o.pair_max_angle_degrees)
      .add("corner_max_angle_degrees", o.corner_max_angle_degrees)
      .add("on_boundary_edges", o.on_boundary_edges)
      .add("edge_snap_fraction", o.edge_snap_fraction);
}

const char* name_of(ControlPoints control_points) {
  switch (control_points) {
    case ControlPoints::CrestPoints:
      return "crest_points";
    case ControlPoints::TangentLine:
      return "tangent_line";
  }
  return "unknown";
}

MethodOptions options_of(const InterpolationOptions& o) {
  return MethodOptions()
      .add("control_points", name_of(o.control_points))
      .add("min_segments", o.min_segments);
}

MethodOptions options_of(const PlanaritySplitOptions& o) {
  return MethodOptions()
      .add("enabled", o.enabled)
      .add("max_depth", o.max_depth)
      .add("max_chords_tried", o.max_chords_tried);
}

MethodOptions options_of(const HoleFillingOptions& o) {
  return MethodOptions()
      .add("refine_and_fair", o.refine_and_fair)
      .add("density_control_factor", o.density_control_factor)
      .add("polyline_fallback", o.polyline_fallback)
      .add("triangulate_hole_fallback", o.triangulate_hole_fallback)
      .add("planarity_split", options_of(o.planarity_split))
      .add("split_taken_chords", o.split_taken_chords);
}

}  // namespace

MethodOptions CrestFeatureMethod::options() const {
  return MethodOptions()
      .add("crest_lines", options_of(options_.crest_lines))
      .add("identification", options_of(options_.identification))
      .add("feature_points", options_of(options_.feature_points))
      .add("interpolation", options_of(options_.interpolation))
      .add("filling", options_of(options_.filling));
}

}  // namespace holebench
