#include "methods/slice_loft/slice_loft.h"

#include "core/stopwatch.h"
#include "methods/common/patch_intersections.h"
#include "methods/slice_loft/pinched_portions.h"

#include <algorithm>
#include <chrono>
#include <sstream>

namespace holebench {

namespace slice_loft {
const char* to_string(HoleType type) {
  switch (type) {
    case HoleType::SingleSegment:
      return "single-segment";
    case HoleType::MultiSegmentOrdinary:
      return "multi-segment";
    case HoleType::MultiSegmentCorner:
      return "multi-segment corner";
  }
  return "?";
}
}  // namespace slice_loft

namespace {

using namespace slice_loft;
using Clock = std::chrono::steady_clock;

// HoleReport::fallback when the paper's decomposition (one portion per segment, bounded by the
// missing features, each lofted in its region) does not produce the patch and the whole hole
// is filled as one portion without features, slicing every influencing triangle.
constexpr const char* kOnePortionWithoutFeatures = "one_portion_without_features";
struct PhaseClock {
  double identification = 0, segmentation = 0, features = 0, surface = 0, sewing = 0;
};

// The phase names, which the layers name as their steps.
constexpr const char* kStepIdentification = "I holes and islands (4.1)";
constexpr const char* kStepSegmentation = "II segmentation of the hole boundary (4.2)";
constexpr const char* kStepFeatures = "III missing features (4.3, eqs. 1-3)";
constexpr const char* kStepSurface = "IV composite surface (4.4)";
constexpr const char* kStepSewing = "V-VI trimming, faceting and sewing (4.5-4.6)";

// Layers of step II: each segment of the hole boundary as a polyline.
void add_segment_layer(std::vector<MethodLayer>& layers, const Mesh& holed, const Hole& hole) {
  MethodLayer& layer = layer_named(layers, "segments", kStepSegmentation, LayerKind::Polylines);
  for (const auto& segment : hole.segments) {
    std::vector<Point> line;
    for (const auto v : segment.vertices)
      line.push_back(holed.point(v));
    layer.polylines.push_back(std::move(line));
  }
}

// Layers of step III: the missing edges as traced (eqs. 1-3) and the missing corner.
void add_feature_layers(std::vector<MethodLayer>& layers, const MissingFeatures& features) {
  // (Each layer is filled before the next is looked up: adding one may move the others.)
  MethodLayer& edges = layer_named(layers, "missing_edges", kStepFeatures, LayerKind::Polylines);
  for (const auto& edge : features.edges)
    edges.polylines.push_back(edge.trace);
  MethodLayer& corner = layer_named(layers, "missing_corner", kStepFeatures, LayerKind::Points);
  if (features.corner >= 0)
    corner.points.push_back(features.points[features.corner]);
}

// The lofted surface S(u, s) over its sections' offsets and its common arc-length grid, as
// triangles (two per grid cell).
void add_surface_samples(MethodLayer& layer, const LoftedSurface& surface) {
  const auto& us = surface.section_u();
  const auto& ss = surface.s_grid();
  if (us.size() < 2 || ss.size() < 2)
    return;
  const int base = static_cast<int>(layer.surface.points.size());
  for (double u : us) {
    for (double s : ss)
      layer.surface.points.push_back(surface.evaluate(u, s));
  }
  const int columns = static_cast<int>(ss.size());
  for (int k = 0; k + 1 < static_cast<int>(us.size()); ++k) {
    for (int j = 0; j + 1 < columns; ++j) {
      const int a = base + k * columns + j, b = a + 1, c = a + columns, d = c + 1;
      layer.surface.triangles.push_back({a, b, d});
      layer.surface.triangles.push_back({a, d, c});
    }
  }
}

// Layers of step IV: the slices (each section of the mesh with its traced gaps), the section
// curves traced across the hole, and the lofted surface.
void add_surface_layers(std::vector<MethodLayer>& layers, const std::vector<LoftedPatch>& patches) {
  // (Each layer is filled before the next is looked up: adding one may move the others.)
  MethodLayer& slices = layer_named(layers, "slices", kStepSurface, LayerKind::Polylines);
  for (const auto& patch : patches) {
    for (const auto& section : patch.sections)
      slices.polylines.push_back(section.points);
  }
  MethodLayer& traced = layer_named(layers, "section_curves", kStepSurface, LayerKind::Points);
  for (const auto& patch : patches) {
    for (const auto& section : patch.sections)
      traced.points.insert(traced.points.end(), section.traced.begin(), section.traced.end());
  }
  MethodLayer& lofted = layer_named(layers, "lofted_surface", kStepSurface, LayerKind::Surface);
  for (const auto& patch : patches) {
    if (patch.ok)
      add_surface_samples(lofted, patch.surface);
  }
}

// The layer of steps V-VI: the trimmed, faceted patch (the repair's new faces).
void add_patch_layer(std::vector<MethodLayer>& layers, const Mesh& repaired) {
  append_new_faces(layer_named(layers, "trimmed_patch", kStepSewing, LayerKind::Surface), repaired);
}

// Steps IV-VI for one decomposition of a hole. Empty string on success.
std::string fill(Mesh& mesh, const Mesh& holed, const HolesAndIslands& found, const Hole& hole,
                 const MissingFeatures& features, const std::vector<int>& face_region,
                 const SliceLoftOptions& options, PhaseClock& clock, SewingResult& sewn,
                 bool use_regions, std::string& remark, std::vector<MethodLayer>* layers) {
  auto start = Clock::now();
  std::vector<Portion> portions = hole_portions(holed, found.contours, hole, features, face_region);
  // The hole's and islands' boundary, and the missing-feature points that lie on it.
  std::vector<HalfedgeHandle> boundary = hole.boundary;
  std::vector<VertexHandle> boundary_vertices = found.contours[hole.contour].vertices;
  for (int island : hole.islands) {
    const Contour& contour = found.contours[island];
    boundary.insert(boundary.end(), contour.loop.halfedges.begin(), contour.loop.halfedges.end());
    boundary_vertices.insert(boundary_vertices.end(), contour.vertices.begin(),
                             contour.vertices.end());
  }
  const std::vector<VertexHandle> on_boundary =
      feature_points_on_boundary(holed, boundary_vertices, features,
                                 options.tessellation.feature_snap_edges * hole.mean_edge_length);
  for (auto& portion : portions) {
    if (!use_regions)
      portion.region = kNoRegion;
    snap_feature_nodes(holed, on_boundary, portion.boundary);
  }
  std::vector<LoftedPatch> patches;
  for (const auto& portion : portions) {
    patches.push_back(loft_portion(holed, hole, portion, face_region, options.surface));
    if (!patches.back().ok) {
      if (layers)
        add_surface_layers(*layers, patches);
      clock.surface += seconds_since(start);
      return "composite surface: " + patches.back().error;
    }
  }
  if (layers)
    add_surface_layers(*layers, patches);
  clock.surface += seconds_since(start);
  start = Clock::now();
  // Each portion trimmed on its own patch, split where its boundary is pinched.
  std::vector<Portion> pieces;
  std::vector<PatchTessellation> tessellations;
  for (std::size_t p = 0; p < portions.size(); ++p) {
    for (Portion& piece : split_pinched_portion(portions[p], patches[p])) {
      tessellations.push_back(tessellate_trimmed_patch(
          holed, piece, patches[p], hole.mean_edge_length, options.tessellation));
      pieces.push_back(std::move(piece));
      if (!tessellations.back().ok) {
        clock.sewing += seconds_since(start);
        return "trimming: " + tessellations.back().error;
      }
    }
  }
  // Loops trimmed in the second domain tried (the boundary folds in the first).
  const TrimmingDomain second_domain =
      options.tessellation.plane_first ? TrimmingDomain::Surface : TrimmingDomain::PortionPlane;
  std::size_t in_second = 0, on_disc = 0, chords = 0;
  for (const auto& t : tessellations) {
    in_second += t.domain == second_domain ? 1 : 0;
    on_disc += t.domain == TrimmingDomain::DevelopedDisc ? 1 : 0;
    chords += t.chords_split;
  }
  std::vector<std::string> remarks;
  const auto snapped = std::count_if(on_boundary.begin(), on_boundary.end(),
                                     [](VertexHandle v) { return v.is_valid(); });
  if (snapped > 0) {
    remarks.push_back(std::to_string(snapped) +
                      " missing-feature point(s) on the boundary (the edge runs along it)");
  }
  if (pieces.size() != portions.size()) {
    remarks.push_back("pinched boundary: " + std::to_string(portions.size()) +
                      " portion(s) trimmed as " + std::to_string(pieces.size()) + " loops");
  }
  if (in_second > 0) {
    remarks.push_back(std::to_string(in_second) + " of " + std::to_string(pieces.size()) +
                      (options.tessellation.plane_first
                           ? " loop(s) trimmed on the surface (the boundary folds in the "
                             "portion's plane)"
                           : " loop(s) trimmed in the portion's plane (the boundary folds on "
                             "the surface)"));
  }
  if (on_disc > 0) {
    remarks.push_back(std::to_string(on_disc) + " of " + std::to_string(pieces.size()) +
                      " loop(s) trimmed on the developed disc (the boundary folds on the "
                      "surface too)");
  }
  if (chords > 0)
    remarks.push_back("chords split " + std::to_string(chords));
  for (const auto& r : remarks)
    remark += (remark.empty() ? "" : "; ") + r;
  sewn = sew_patches(mesh, pieces, tessellations, features, boundary);
  clock.sewing += seconds_since(start);
  return sewn.ok ? std::string() : "sewing: " + sewn.error;
}

}  // namespace

MethodResult run_slice_loft(const Mesh& holed, const SliceLoftOptions& options,
                            bool record_layers) {
  MethodResult result;
  result.repaired = holed;
  PhaseClock clock;

  auto start = Clock::now();
  HolesAndIslands found = identify_holes_and_islands(holed, options.identification);
  clock.identification = seconds_since(start);

  start = Clock::now();
  const std::vector<int> face_region = segment_mesh_regions(holed, options.segmentation);
  clock.segmentation = seconds_since(start);

  std::size_t closed = 0;
  for (std::size_t i = 0; i < found.holes.size(); ++i) {
    const auto hole_start = Clock::now();
    Hole& hole = found.holes[i];
    HoleReport report;
    report.hole_index = static_cast<int>(i);
    report.loop_size = hole.boundary.size();
    report.centroid = loop_centroid(holed, found.contours[hole.contour].loop);
    std::ostringstream note;

    start = Clock::now();
    segment_hole_boundary(holed, face_region, hole, options.segmentation);
    clock.segmentation += seconds_since(start);
    if (record_layers)
      add_segment_layer(result.layers, holed, hole);
    note << to_string(hole.type) << " hole, " << hole.segments.size() << " segment(s), "
         << hole.islands.size() << " island(s)";
    if (hole.orphan_island)
      note << ", an island contour no hole claimed (filled as a hole)";

    start = Clock::now();
    MissingFeatures features;
    if (hole.segments.size() >= 2) {
      MissingFeatureOptions feature_options = options.features;
      feature_options.segmentation = options.segmentation;
      features = reconstruct_missing_features(holed, hole, feature_options);
    }
    clock.features += seconds_since(start);
    if (record_layers)
      add_feature_layers(result.layers, features);
    if (!features.edges.empty()) {
      note << "; " << (features.through_edge ? 1 : features.edges.size()) << " missing edge(s)"
           << (features.corner >= 0 ? " and a missing corner" : "")
           << (features.straight ? " (joined straight: the feature lines end at the hole)" : "");
    } else if (!features.note.empty()) {
      note << "; missing features not rebuilt: " << features.note;
    }

    // A multi-segment hole without its missing features is filled as one portion slicing
    // every influencing triangle: the same stand-in as the fallback below.
    if (hole.segments.size() >= 2 && !decomposed_by_features(hole, features))
      report.fallback = kOnePortionWithoutFeatures;

    SewingResult sewn;
    std::string remark;
    // The step IV layers of the attempt that made the patch (or of the last one tried).
    std::vector<MethodLayer> attempt;
    const std::size_t first_new_face = result.repaired.n_faces();
    std::string error = fill(result.repaired, holed, found, hole, features, face_region, options,
                             clock, sewn, true, remark, record_layers ? &attempt : nullptr);
    if (!error.empty()) {
      // Fall back: the whole hole as one portion, slicing every influencing triangle.
      report.fallback = kOnePortionWithoutFeatures;
      note << "; " << error << "; filled as one portion without features";
      const MissingFeatures none;
      remark.clear();
      attempt.clear();
      error = fill(result.repaired, holed, found, hole, none, face_region, options, clock, sewn,
                   false, remark, record_layers ? &attempt : nullptr);
      if (!error.empty())
        note << "; failed again: " << error;
    }
    if (error.empty() && !remark.empty())
      note << "; " << remark;
    append_layers(result.layers, std::move(attempt));
    report.closed = error.empty();
    report.note = note.str();
    // Section 4.6 expects no self-intersecting facets; the method checks its patch.
    if (report.closed)
      check_patch_intersections(result.repaired, first_new_face, report);
    report.new_faces = sewn.new_faces;
    report.new_vertices = sewn.new_vertices;
    report.seconds = seconds_since(hole_start);
    closed += report.closed ? 1 : 0;
    result.holes.push_back(std::move(report));
  }

  if (record_layers)
    add_patch_layer(result.layers, result.repaired);
  result.phases = {
      {kStepIdentification, clock.identification},
      {kStepSegmentation, clock.segmentation},
      {kStepFeatures, clock.features},
      {kStepSurface, clock.surface},
      {kStepSewing, clock.sewing},
  };
  const std::size_t n = found.holes.size();
  result.status = closed == n   ? MethodStatus::Ok
                  : closed == 0 ? MethodStatus::Failed
                                : MethodStatus::Partial;
  if (closed != n)
    result.message = std::to_string(n - closed) + " of " + std::to_string(n) + " holes left open";
  return result;
}

}  // namespace holebench
