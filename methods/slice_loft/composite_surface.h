// Step IV of the slice paper (section 4.4): the hole split into portions (one per segment,
// bounded by the segment and the missing edges); per portion, the influencing triangles of
// its region (and the islands') sliced by planes advanced along the longer edge of the
// portion's box; section curves traced with curvature continuity from the slice points on
// the boundary (hole to island to hole); the sections lofted into a smooth patch
// (lofted_surface.h). Adjacent
// patches share the missing edges' points, which stitches them into the composite surface.
#pragma once

#include "methods/slice_loft/hole_structures.h"
#include "methods/slice_loft/lofted_surface.h"

#include <string>
#include <vector>

namespace holebench::slice_loft {

/// A vertex of a portion's boundary: an original vertex, or a point of a missing feature.
struct BoundaryNode {
  VertexHandle vertex;  ///< valid for a vertex of the hole or island boundary
  int feature = -1;     ///< else an index into MissingFeatures::points
  Point position;
};

/// The part of a hole that lies in one region.
struct Portion {
  int region = kNoRegion;              ///< kNoRegion: every influencing triangle is sliced
  std::vector<BoundaryNode> boundary;  ///< in the hole boundary's direction
  std::vector<std::vector<BoundaryNode>> islands;
  std::vector<std::vector<Point>> missing_edges;  ///< the feature paths it is bounded by
};

/// Whether `hole_portions` splits the hole into one portion per segment (a multi-segment hole
/// whose missing features were rebuilt, one edge per segment end); otherwise the whole hole
/// is one portion.
bool decomposed_by_features(const Hole& hole, const MissingFeatures& features);

/// The portions of a hole: one per segment when features were found, else the whole hole.
std::vector<Portion> hole_portions(const Mesh& mesh, const std::vector<Contour>& contours,
                                   const Hole& hole, const MissingFeatures& features,
                                   const std::vector<int>& face_region);

/// The direction the slicing plane advances in: the paper's longer edge of the portion's
/// bounding box (a model axis; the default), or the major axis of the portion's boundary in
/// its plane (the project's option: it closes more holes, docs/slice_loft.md).
enum class SlicingDirection { LongerBoxEdge, MajorAxis };

/// What a section curve spans. The paper's (section 4.4): "from a slice point on the
/// hole-boundary ... to the other end of the slice on the boundary (either original or
/// regenerated boundary)", through the islands' slices, with partial slices ending on a
/// missing edge (figure 12a). The project's option: every slice piece of the portion's region
/// inside the influencing area, both ends extended beyond it, so that the loft interpolates
/// the surrounding surface as well as the traced gap.
enum class SectionExtent { HoleBoundary, InfluencingArea };

/// How a gap of a section is traced. The paper's: from one end, "from a slice point on the
/// hole-boundary" towards the other, which it meets (the trace is bent onto it); the project's
/// option: from both ends and blended (the paper's own remedy at a cone's apex, figure 24).
enum class GapTracing { OneEnd, BothEnds };

struct CompositeSurfaceOptions {
  SlicingDirection direction = SlicingDirection::LongerBoxEdge;
  SectionExtent extent = SectionExtent::HoleBoundary;
  GapTracing tracing = GapTracing::OneEnd;
  /// Slices across the longer edge of the portion's box (the paper's offset as a count) ...
  int slices = 10;
  /// ... but at most this many mean boundary-edge lengths apart.
  double max_slice_spacing_edges = 1.0;
  /// Slices beyond each end of the portion (the project's option, with
  /// SectionExtent::InfluencingArea; the paper slices the portion only).
  int extra_slices = 0;
  double baseline_edges = 2.0;  ///< spacing of the points a trace takes curvature from
  double step_edges = 0.25;     ///< tracing step along a section
  double max_turn_degrees = 20.0;
  /// Arc-length spacing of the grid the sections are lofted through (mean edge lengths).
  double section_sample_edges = 0.5;
};

/// One section curve: the slice of the mesh plus the curves traced across the gaps, in
/// order along the section (a polyline in the plane dot(p - origin, d) = u).
struct Section {
  double u = 0.0;
  std::vector<Point> points;
  std::vector<Point> traced;  ///< the discrete points generated in the gaps (3D)
};

/// A portion's patch: the frame it was sliced in (d the slicing direction, n the mean normal,
/// e = n x d), its sections, and the surface lofted through them, S(u, s) with s the arc
/// length along the sections (lofted_surface.h).
struct LoftedPatch {
  Point origin, d, e, n;
  std::vector<Section> sections;
  LoftedSurface surface;
  bool ok = false;
  std::string error;

  double u_of(const Point& p) const { return OpenMesh::dot(p - origin, d); }
  double w_of(const Point& p) const { return OpenMesh::dot(p - origin, e); }
  /// The surface's parameters (u, s) of a point near it: trimming works in this domain.
  std::array<double, 2> parameters(const Point& p) const { return surface.parameters(p); }
  Point evaluate(double u, double s) const { return surface.evaluate(u, s); }
  /// The surface point over (u, w) of the portion's plane (the sections are graphs over w
  /// where this is used).
  Point point_over_plane(double u, double w) const {
    return surface.point_with_coordinate(u, e, w);
  }
};

LoftedPatch loft_portion(const Mesh& mesh, const Hole& hole, const Portion& portion,
                         const std::vector<int>& face_region,
                         const CompositeSurfaceOptions& options = {});

}  // namespace holebench::slice_loft
