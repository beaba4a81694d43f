#include "methods/crest_feature/crest_feature.h"

#include "core/stopwatch.h"
#include "methods/crest_feature/boundary_edge_split.h"
#include "methods/crest_feature/crest_line_correction.h"
#include "methods/crest_feature/hole_identification.h"
#include "methods/crest_feature/hole_partitioning.h"

#include <fmt/format.h>

#include <chrono>

namespace holebench {
namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

MethodResult run_crest_feature(const Mesh& holed, User& user, const CrestFeatureOptions& options) {
  using namespace crest_feature;
  MethodResult result;
  result.repaired = holed;

  auto start = Clock::now();
  const CrestLines crest = detect_crest_lines(holed, options.crest_lines);
  result.phases.push_back({"crest line detection (3.2)", seconds_since(start)});
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
    closed += report.closed ? 1 : 0;
    report.seconds = seconds_since(hole_start);
    result.holes.push_back(std::move(report));
  }
  result.phases.push_back({"feature points (3.4.1)", feature_seconds});
  result.phases.push_back({"user intervention (3.4.2)", user_seconds});
  result.phases.push_back({"feature line interpolation (3.4.3)", interpolation_seconds});
  result.phases.push_back({"hole partitioning (3.4.4)", partition_seconds});
  result.phases.push_back({"hole filling (3.5)", filling_seconds});
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
