#include "methods/brep_guidance/brep_guidance.h"

#include "core/geometry.h"
#include "core/stopwatch.h"
#include "methods/brep_guidance/brep_faces.h"
#include "methods/brep_guidance/exact_closing.h"
#include "methods/brep_guidance/guidance_arrow.h"
#include "methods/brep_guidance/hole_classification.h"
#include "methods/brep_guidance/hole_detection.h"

#include <chrono>

namespace holebench {

namespace {
using Clock = std::chrono::steady_clock;
using namespace brep_guidance;

// The layers of detection and guidance for one hole: the hole's runs, one polyline per face
// f_i it crosses (Algorithm 1); its transitions T_i and, for k = 3, the planes' intersection
// S; and its guidance arrow (equations 3-5), from P along r for distance d.
void add_hole_layers(std::vector<MethodLayer>& layers, const Mesh& mesh, const Hole& hole,
                     const std::optional<GuidanceArrow>& arrow, double d) {
  MethodLayer& faces =
      layer_named(layers, "faces", "detection (algorithm 1)", LayerKind::Polylines);
  for (const auto& run : hole.runs) {
    std::vector<Point> line;
    for (const auto h : run)
      line.push_back(mesh.point(mesh.from_vertex_handle(h)));
    if (!run.empty())
      line.push_back(mesh.point(mesh.to_vertex_handle(run.back())));
    faces.polylines.push_back(std::move(line));
  }
  MethodLayer& transitions =
      layer_named(layers, "transitions", "detection (algorithm 1)", LayerKind::Points);
  for (const auto& t : hole.transitions)
    transitions.points.push_back(t.position);
  if (hole.S)
    transitions.points.push_back(*hole.S);
  MethodLayer& arrows =
      layer_named(layers, "arrows", "guidance (equations 3-5)", LayerKind::Polylines);
  if (arrow)
    arrows.polylines.push_back({arrow->position, arrow->position + arrow->direction * d});
}

}  // namespace

MethodResult run_brep_guidance(const Mesh& holed, const MethodParameters& parameters, User& user,
                               const BrepGuidanceOptions& options) {
  MethodResult result;
  result.repaired = holed;
  const double diagonal = bounding_box_diagonal(holed);
  const double structure_size = parameters.structure_size > 0.0
                                    ? parameters.structure_size
                                    : options.default_structure_size_rel_diag * diagonal;
  const double d = options.arrow_distance_rel_diag * diagonal;

  auto start = Clock::now();
  const BrepFaces faces = extract_brep_faces(holed, options.segmentation, options.faces);
  result.phases.push_back(
      {faces.from_input ? "faces (input regions)" : "faces (planar segmentation)",
       seconds_since(start)});

  start = Clock::now();
  const std::vector<Hole> holes = detect_holes(holed, faces, options.dependence_tolerance);
  result.phases.push_back({"detection (algorithm 1)", seconds_since(start)});

  ClassificationOptions classification_options;
  classification_options.structure_size = structure_size;
  classification_options.figure_3_rule = options.figure_3_rule;
  double classify_seconds = 0.0, close_seconds = 0.0, guide_seconds = 0.0;
  std::size_t failed = 0;
  std::size_t without_arrow = 0;  // guided holes whose arrow is undefined
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const Hole& hole = holes[i];
    const auto hole_start = Clock::now();
    HoleReport report;
    report.hole_index = static_cast<int>(i);
    report.loop_size = hole.halfedges.size();
    report.centroid = hole.centroid;

    start = Clock::now();
    const Classification c = classify_hole(holed, faces, hole, classification_options);
    report.classification = to_labels(hole, c, structure_size);
    classify_seconds += seconds_since(start);

    bool guide = c.decision == Decision::Guide;
    if (!guide) {
      // Cases a and b: the hole can be closed automatically; does the user agree?
      ClosingProposal proposal;
      proposal.hole_index = report.hole_index;
      proposal.hole_centroid = hole.centroid;
      proposal.hole_size = c.size;
      if (!user.agree_to_closing(proposal)) {
        guide = true;
        report.note = "closable, but the user disagreed (case b): guided";
      }
    }
    if (!guide) {
      start = Clock::now();
      const ClosingResult closing =
          close_hole_exactly(result.repaired, faces, hole, options.later_closing_attempts);
      close_seconds += seconds_since(start);
      report.closed = closing.closed;
      report.new_faces = closing.new_faces;
      report.new_vertices = closing.new_vertices;
      if (closing.closed && !closing.note.empty())
        report.note = "exact closing: " + closing.note;
      if (!closing.closed) {
        // The paper closes this hole (case a); an arrow stands in for the closing. A hole the
        // user declined (case b) is guided on the paper's own path: no fallback.
        ++failed;
        guide = true;
        report.note = "exact closing failed: " + closing.error + "; guided instead";
        report.fallback = "guided_instead_of_closed";
      }
    }
    if (guide) {
      start = Clock::now();
      const GuidanceArrow arrow = guidance_arrow(holed, faces, hole, c, d);
      if (is_finite(arrow)) {
        report.arrow = arrow;
      } else {
        // Equation 5's fan has no normal where the loop's vector area is zero (a loop that
        // runs around a pin or a bar): the paper's arrow is undefined there.
        report.note += std::string(report.note.empty() ? "" : "; ") +
                       "no guidance arrow: the hole's triangle fan (equation 5) has no normal";
        ++without_arrow;
      }
      guide_seconds += seconds_since(start);
    }
    if (parameters.record_layers)
      add_hole_layers(result.layers, holed, hole, report.arrow, d);
    report.seconds = seconds_since(hole_start);
    result.holes.push_back(std::move(report));
  }
  result.phases.push_back({"classification (figure 3, equations 1-2)", classify_seconds});
  result.phases.push_back({"exact closing", close_seconds});
  result.phases.push_back({"guidance (equations 3-5)", guide_seconds});
  result.status = failed == 0 && without_arrow == 0 ? MethodStatus::Ok : MethodStatus::Partial;
  if (failed > 0)
    result.message = std::to_string(failed) + " closable holes could not be closed";
  if (without_arrow > 0) {
    result.message += std::string(result.message.empty() ? "" : "; ") +
                      std::to_string(without_arrow) + " hole(s) without a guidance arrow";
  }
  return result;
}

}  // namespace holebench
