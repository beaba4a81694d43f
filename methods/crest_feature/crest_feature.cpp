#include "methods/crest_feature/crest_feature.h"

#include "core/stopwatch.h"
#include "methods/common/patch_intersections.h"
#include "methods/crest_feature/boundary_edge_split.h"
#include "methods/crest_feature/crest_line_correction.h"
#include "methods/crest_feature/hole_identification.h"
#include "methods/crest_feature/hole_partitioning.h"

#include <fmt/format.h>

#include <chrono>

namespace holebench {
namespace {
using Clock = std::chrono::steady_clock;
using namespace crest_feature;

// The phase names, which the layers name as their steps.
constexpr const char* kStepCrestLines = "crest line detection (3.2)";
constexpr const char* kStepFeaturePoints = "feature points (3.4.1)";
constexpr const char* kStepInterpolation = "feature line interpolation (3.4.3)";
constexpr const char* kStepPartitioning = "hole partitioning (3.4.4)";
constexpr const char* kStepFilling = "hole filling (3.5)";

// The layer of 3.2: every crest line of the input (ridges and ravines).
void add_crest_line_layer(std::vector<MethodLayer>& layers, const CrestLines& crest) {
  MethodLayer& layer = layer_named(layers, "crest_lines", kStepCrestLines, LayerKind::Polylines);
  for (const auto& line : crest.lines)
    layer.polylines.push_back(line.points);
}

// The layers of 3.4.1-3.4.4 for one hole: the feature points used (after the user's review),
// the feature lines (eq. 3) from their feature point or corner to the other, and the
// sub-holes' loops.
void add_hole_layers(std::vector<MethodLayer>& layers, const Mesh& mesh, const Hole& hole,
                     const HoleFeatures& features, const FeatureLines& lines,
                     const HolePartition& partition) {
  MethodLayer& points =
      layer_named(layers, "feature_points", kStepFeaturePoints, LayerKind::Points);
  for (const auto& p : features.points)
    points.points.push_back(p.position);
  MethodLayer& feature_lines =
      layer_named(layers, "feature_lines", kStepInterpolation, LayerKind::Polylines);
  const auto end_point = [&](int loop_index, int corner) {
    return loop_index >= 0 ? mesh.point(hole.vertices[loop_index]) : lines.corners[corner];
  };
  for (const auto& line : lines.lines) {
    std::vector<Point> polyline{end_point(line.from, line.from_corner)};
    polyline.insert(polyline.end(), line.interior.begin(), line.interior.end());
    polyline.push_back(end_point(line.to, line.to_corner));
    feature_lines.polylines.push_back(std::move(polyline));
  }
  MethodLayer& sub_holes =
      layer_named(layers, "sub_holes", kStepPartitioning, LayerKind::Polylines);
  for (const auto& loop : partition.sub_holes) {
    std::vector<Point> polyline;
    for (const Node node : loop) {
      polyline.push_back(node >= 0 ? mesh.point(VertexHandle(node))
                                   : partition.new_points[new_point_index(node)]);
    }
    if (!polyline.empty())
      polyline.push_back(polyline.front());  // closed
    sub_holes.polylines.push_back(std::move(polyline));
  }
}

// The layer of 3.5: the patch (the repair's new faces).
void add_patch_layer(std::vector<MethodLayer>& layers, const Mesh& repaired) {
  append_new_faces(layer_named(layers, "patch", kStepFilling, LayerKind::Surface), repaired);
}

}  // namespace

MethodResult run_crest_feature(const Mesh& holed, User& user, const CrestFeatureOptions& options,
                               bool record_layers) {
  MethodResult result;
  result.repaired = holed;

  auto start = Clock::now();
  const CrestLines crest = detect_crest_lines(holed, options.crest_lines);
  result.phases.push_back({kStepCrestLines, seconds_since(start)});
  if (record_layers)
    add_crest_line_layer(result.layers, crest);
  if (crest.skipped)
    result.message = "crest lines skipped (degenerate principal directions): plain filling";

  start = Clock::now();
  const std::vector<Hole> holes = identify_holes(holed, options.identification);
  result.phases.push_back({"hole identification (3.3)", seconds_since(start)});

  double feature_seconds = 0.0, user_seconds = 0.0, interpolation_seconds = 0.0,
         partition_seconds = 0.0, filling_seconds = 0.0;
  std::size_t closed = 0;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    Hole hole = holes[i];
    const auto hole_start = Clock::now();
    HoleReport report;
    report.hole_index = static_cast<int>(i);
    report.loop_size = hole.vertices.size();
    report.centroid = hole.centroid;

    start = Clock::now();
    HoleFeatures detected = detect_feature_points(holed, hole, crest, options.feature_points);
    // 3.4.1: the points inside boundary edges become vertices of the hole's loop.
    const InsertedFeaturePoints on_edges = insert_feature_points(result.repaired, hole, detected);
    hole = on_edges.hole;
    detected = on_edges.features;
    feature_seconds += seconds_since(start);

    start = Clock::now();
    const int before = user.interventions();
    const HoleFeatures reviewed = review_feature_points(
        result.repaired, hole, static_cast<int>(i), crest, detected, user, options.feature_points);
    const CrestLineCorrection correction =
        review_crest_lines(result.repaired, hole, static_cast<int>(i), reviewed, user);
    const HoleFeatures& features = correction.features;
    user_seconds += seconds_since(start);

    start = Clock::now();
    FeatureLines lines = interpolate_feature_lines(hole, features, options.interpolation, &crest);
    interpolation_seconds += seconds_since(start);

    start = Clock::now();
    HolePartition partition = partition_hole(hole, lines);
    partition_seconds += seconds_since(start);

    start = Clock::now();
    const std::size_t first_new_face = result.repaired.n_faces();
    HoleFillingResult filling = fill_hole(result.repaired, partition, options.filling);
    // Where the user's corner graph (not in the paper) gives sub-holes that cannot be
    // filled or stitched, the hole again with the paper's features alone (pairs and the
    // corner triple), before any stand-in. A failed fill leaves the mesh as it was.
    std::string graph_left_out;
    if (!filling.closed && (!features.more_corners.empty() || !features.corner_links.empty())) {
      HoleFeatures paper_features = features;
      paper_features.more_corners.clear();
      paper_features.corner_links.clear();
      lines = interpolate_feature_lines(hole, paper_features, options.interpolation, &crest);
      partition = partition_hole(hole, lines);
      graph_left_out = "; corner graph left out (" + filling.error + ")";
      filling = fill_hole(result.repaired, partition, options.filling);
    }
    filling_seconds += seconds_since(start);
    if (record_layers)
      add_hole_layers(result.layers, result.repaired, hole, features, lines, partition);

    report.closed = filling.closed;
    report.new_faces = filling.new_faces;
    report.new_vertices = filling.new_vertices;
    // A stitched patch whose sub-holes needed a stand-in for equation 6's projection.
    if (filling.closed)
      report.fallback = sub_hole_fallback(filling.sub_holes);
    std::string fallback;
    if (!filling.closed && options.filling.triangulate_hole_fallback) {
      // Not in the paper: the hole is closed without its feature lines.
      start = Clock::now();
      report.new_faces = fill_hole_without_features(result.repaired, hole.loop.halfedges.front());
      for (const auto& island : hole.islands) {  // each island's loop as a hole of its own
        const auto h = result.repaired.find_halfedge(island[0], island[1]);
        if (h.is_valid() && result.repaired.is_boundary(h))
          report.new_faces += fill_hole_without_features(result.repaired, h);
      }
      filling_seconds += seconds_since(start);
      report.closed = report.new_faces > 0;
      report.fallback = "cgal_triangulate_hole";
      fallback = "; " + filling.error + ": filled by CGAL triangulate_hole without feature lines";
    }
    std::size_t fallbacks = 0;
    for (const auto& s : filling.sub_holes)
      fallbacks += s.ok && !s.fallback.empty() ? 1 : 0;
    report.note = fmt::format(
        "feature points detected {} used {}; pairs {}; corner {}; user interventions {}; "
        "crest lines corrected {}; feature lines {}; sub-holes {}; projection fallbacks {}",
        detected.points.size(), features.points.size(), features.pairs.size(),
        features.corner ? "yes" : "no", user.interventions() - before, correction.corrected,
        lines.lines.size(), partition.sub_holes.size(), fallbacks);
    int planarity_chords = 0;
    for (const auto& s : filling.sub_holes)
      planarity_chords += s.chords;
    if (planarity_chords > 0)
      report.note += fmt::format("; sub-holes cut for equation 6 by {} chord(s)", planarity_chords);
    if (!features.more_corners.empty() || !features.corner_links.empty())
      report.note += fmt::format("; further corners {}; corner links {}",
                                 features.more_corners.size(), features.corner_links.size());
    if (on_edges.inserted > 0)
      report.note +=
          fmt::format("; feature points inserted into boundary edges {}", on_edges.inserted);
    if (filling.split_chords > 0)
      report.note += fmt::format("; chords split {}", filling.split_chords);
    if (!hole.islands.empty())
      report.note += fmt::format("; islands {}", hole.islands.size());
    report.note += graph_left_out;
    for (const auto& d : partition.dropped)
      report.note += "; dropped: " + d;
    report.note += fallback;
    if (!report.closed)
      report.note += "; not filled: " + filling.error;
    // The method's check of its own patch (section 3.5 projects each sub-hole so that its
    // triangulation does not intersect itself).
    if (report.closed)
      check_patch_intersections(result.repaired, first_new_face, report);
    closed += report.closed ? 1 : 0;
    report.seconds = seconds_since(hole_start);
    result.holes.push_back(std::move(report));
  }
  if (record_layers)
    add_patch_layer(result.layers, result.repaired);
  result.phases.push_back({kStepFeaturePoints, feature_seconds});
  result.phases.push_back({"user intervention (3.4.2)", user_seconds});
  result.phases.push_back({kStepInterpolation, interpolation_seconds});
  result.phases.push_back({kStepPartitioning, partition_seconds});
  result.phases.push_back({kStepFilling, filling_seconds});
  result.status = closed == holes.size()          ? MethodStatus::Ok
                  : closed == 0 && !holes.empty() ? MethodStatus::Failed
                                                  : MethodStatus::Partial;
  if (result.status != MethodStatus::Ok) {
    result.message += (result.message.empty() ? "" : "; ") +
                      fmt::format("{} of {} holes left open", holes.size() - closed, holes.size());
  }
  return result;
}

}  // namespace holebench
