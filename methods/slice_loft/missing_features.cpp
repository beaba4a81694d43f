#include "methods/slice_loft/missing_features.h"

#include "methods/slice_loft/discrete_curvature.h"

#include <cmath>
#include <limits>

namespace holebench::slice_loft {
namespace {

// The region-boundary chain from `start` along `first`, as points, about `length` long.
std::vector<Point> region_boundary_chain(const Mesh& mesh, VertexHandle start,
                                         OpenMesh::EdgeHandle first, double length,
                                         const BoundarySegmentationOptions& options) {
  std::vector<Point> chain{mesh.point(start)};
  VertexHandle previous = start;
  auto h = mesh.halfedge_handle(first, 0);
  VertexHandle current =
      mesh.from_vertex_handle(h) == start ? mesh.to_vertex_handle(h) : mesh.from_vertex_handle(h);
  double walked = 0.0;
  for (int guard = 0; guard < 64; ++guard) {
    chain.push_back(mesh.point(current));
    walked += (mesh.point(current) - mesh.point(previous)).norm();
    if (walked >= length)
      break;
    const Point direction = (mesh.point(current) - mesh.point(previous)).normalized();
    VertexHandle next;
    double best = 0.5;  // continue only roughly straight on
    for (auto oh : mesh.voh_range(current)) {
      const VertexHandle to = oh.to();
      if (to == previous || !is_region_boundary_edge(mesh, oh.edge(), options))
        continue;
      const double c =
          OpenMesh::dot(direction, (mesh.point(to) - mesh.point(current)).normalized());
      if (c > best) {
        best = c;
        next = to;
      }
    }
    if (!next.is_valid())
      break;
    previous = current;
    current = next;
  }
  return chain;
}

bool inside_box(const BoundingBox& box, const Point& p, double tolerance) {
  for (int k = 0; k < 3; ++k) {
    if (p[k] < box.min[k] - tolerance || p[k] > box.max[k] + tolerance)
      return false;
  }
  return true;
}

// Closest points of two polylines (brute force over segment pairs, by sampling each segment
// of one against the other polyline: the polylines are short).
std::pair<Point, Point> mutually_closest_points(const std::vector<Point>& a,
                                                const std::vector<Point>& b) {
  double best = std::numeric_limits<double>::max();
  std::pair<Point, Point> result{a.front(), b.front()};
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    for (int k = 0; k <= 8; ++k) {
      const Point p = a[i] + (a[i + 1] - a[i]) * (k / 8.0);
      const Point q = point_at_arc_length(b, closest_arc_length(b, p));
      const double d = (p - q).norm();
      if (d < best) {
        best = d;
        result = {p, q};
      }
    }
  }
  return result;
}

}  // namespace

MissingFeatures reconstruct_missing_features(const Mesh& mesh, Hole& hole,
                                             const MissingFeatureOptions& options) {
  MissingFeatures features;
  const std::size_t m = hole.segments.size();
  if (m < 2)
    return features;
  const double edge = hole.mean_edge_length;
  const double baseline = options.baseline_edges * edge;
  const double box_tolerance = 0.5 * edge;
  TraceOptions trace;
  trace.step = options.step_edges * edge;
  trace.max_turn_rad = options.max_turn_degrees * M_PI / 180.0;
  trace.max_steps = static_cast<int>(std::ceil(3.0 * hole.box.diagonal() / trace.step)) + 4;

  // Trace from each segment end (the start vertex of segment i) into the hole.
  for (std::size_t i = 0; i < m; ++i) {
    const Segment& segment = hole.segments[i];
    if (!segment.start_region_edge.is_valid()) {
      features.note = "no region-boundary edge at a segment end";
      features.edges.clear();
      return features;
    }
    const auto chain = region_boundary_chain(mesh, segment.start, segment.start_region_edge,
                                             2.5 * baseline, options.segmentation);
    const BackPoints back = back_points(chain, baseline);
    if (!back.valid) {
      features.note = "a region-boundary edge too short to trace from";
      features.edges.clear();
      return features;
    }
    MissingEdge missing;
    missing.end_index = static_cast<int>(i);
    missing.trace = trace_curvature_continuous(
        back.q2, back.q1, back.q0, trace,
        [&](const Point& p) { return !inside_box(hole.box, p, box_tolerance); });
    if (missing.trace.size() < 2) {
      // The region edge leads out of the hole at once: not a missing edge of this hole.
      features.note = "a traced missing edge leaves the hole's box at once";
      features.edges.clear();
      return features;
    }
    features.edges.push_back(std::move(missing));
  }

  auto start_direction = [&](const MissingEdge& e) {
    return (e.trace[1] - e.trace[0]).normalized();
  };
  if (m == 2 && OpenMesh::dot(start_direction(features.edges[0]),
                              start_direction(features.edges[1])) < options.through_edge_cosine) {
    // One missing edge through the hole: traced from both ends and blended.
    features.through_edge = true;
    // Both traces must head into the gap between the two ends. Where the region-boundary
    // edges at the ends lead away from it (the feature line ends at the hole: nothing to take
    // its curvature from), the edge is joined with zero curvature, a straight line.
    const std::vector<Point>& trace_a = features.edges[0].trace;
    const std::vector<Point>& trace_b = features.edges[1].trace;
    const Point a = trace_a.front(), b = trace_b.front();
    std::vector<Point> from_a = trace_a, from_b = trace_b;
    if (OpenMesh::dot(start_direction(features.edges[0]), b - a) <= 0.0 ||
        OpenMesh::dot(start_direction(features.edges[1]), a - b) <= 0.0) {
      from_a = {a, b};
      from_b = {b, a};
      features.straight = true;
    }
    for (const Point& p : bridge(from_a, from_b, edge)) {
      features.points.push_back(p);
      features.edges[0].points.push_back(static_cast<int>(features.points.size()) - 1);
    }
    // edges[1] runs the other way over the same points.
    features.edges[1].points.assign(features.edges[0].points.rbegin(),
                                    features.edges[0].points.rend());
  } else {
    // The corner (section 4.3): "the closest point on each extracted missing edge to the other
    // extracted edges", averaged over every pair of edges.
    Point corner(0, 0, 0);
    int count = 0;
    for (std::size_t i = 0; i < m; ++i) {
      for (std::size_t j = i + 1; j < m; ++j) {
        const auto [p, q] =
            mutually_closest_points(features.edges[i].trace, features.edges[j].trace);
        corner += p + q;
        count += 2;
      }
    }
    corner /= static_cast<double>(count);
    const double tolerance = options.corner_tolerance_rel_box * hole.box.diagonal();
    for (const auto& e : features.edges) {
      if (options.reject_far_corner && distance_to_polyline(e.trace, corner) > tolerance) {
        features.note = "the missing edges do not meet at one corner";
        features.edges.clear();
        return features;
      }
    }
    if (!inside_box(hole.box, corner, tolerance)) {
      features.note = "the missing corner lies outside the hole";
      features.edges.clear();
      return features;
    }
    features.points.push_back(corner);
    features.corner = 0;
    // Each edge re-interpolated to end at the corner.
    for (auto& e : features.edges) {
      for (const Point& p : bend_to(e.trace, corner, edge)) {
        features.points.push_back(p);
        e.points.push_back(static_cast<int>(features.points.size()) - 1);
      }
      e.points.push_back(features.corner);
    }
  }
  for (std::size_t i = 0; i < m; ++i) {
    hole.segments[i].missing_curve_at_start = static_cast<int>(i);
    hole.segments[i].missing_curve_at_end = static_cast<int>((i + 1) % m);
  }
  return features;
}

}  // namespace holebench::slice_loft
