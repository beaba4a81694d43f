#include "metrics/feature_recovery.h"

#include "core/distances.h"
#include "core/geometry.h"
#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace holebench {
namespace {

std::vector<Point> sample_polyline(const std::vector<Point>& polyline, double spacing) {
  std::vector<Point> samples;
  if (polyline.empty())
    return samples;
  samples.push_back(polyline.front());
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Point& a = polyline[i];
    const Point& b = polyline[i + 1];
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
    for (int s = 1; s <= steps; ++s)
      samples.push_back(a + (b - a) * (static_cast<double>(s) / steps));
  }
  return samples;
}

struct Segment {
  Point a, b;
};

// The distance from `corner` to the nearest vertex of `mesh` from index `first` on.
double nearest_vertex_distance(const Mesh& mesh, const Point& corner, std::size_t first) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = first; i < mesh.n_vertices(); ++i) {
    const VertexHandle v(static_cast<int>(i));
    if (!mesh.status(v).deleted())
      best = std::min(best, (mesh.point(v) - corner).norm());
  }
  return best;
}

}  // namespace

std::vector<double> input_corner_distances(const Case& c) {
  std::vector<double> distances;
  for (const auto& hole : c.holes) {
    for (const Point& corner : hole.missing_corners)
      distances.push_back(nearest_vertex_distance(c.input, corner, 0));
  }
  return distances;
}

FeatureRecovery feature_recovery(const Case& c, const Mesh& repaired,
                                 const embree::TriangleScene& complete_scene,
                                 const FeatureRecoveryOptions& options,
                                 const std::vector<double>* input_corner_distances) {
  FeatureRecovery result;

  // The input's vertices (where known) and the repair's own after them: the minimum is the
  // same as over all the repair's vertices.
  std::size_t corner = 0;
  for (const auto& hole : c.holes) {
    for (const Point& point : hole.missing_corners) {
      result.corner_errors.push_back(
          input_corner_distances
              ? std::min((*input_corner_distances)[corner],
                         nearest_vertex_distance(repaired, point, c.input.n_vertices()))
              : nearest_vertex_distance(repaired, point, 0));
      ++corner;
    }
  }

  bool any_missing_edge = false;
  for (const auto& hole : c.holes)
    any_missing_edge = any_missing_edge || !hole.missing_edges.empty();
  if (any_missing_edge) {
    const FeatureAnalysis analysis = analyse_features(repaired, options.features);
    std::vector<Segment> sharp;
    for (auto e : repaired.edges()) {
      if (analysis.edge_is_sharp[e.idx()])
        sharp.push_back({repaired.point(e.v0()), repaired.point(e.v1())});
    }
    for (const auto& hole : c.holes) {
      for (const auto& polyline : hole.missing_edges) {
        MissingEdgeRecovery edge;
        const auto samples = sample_polyline(polyline, options.edge_sample_spacing);
        // Only sharp edges that can be within the search radius of the polyline.
        BoundingBox box{polyline.front(), polyline.front()};
        for (const Point& p : polyline) {
          box.min.minimize(p);
          box.max.maximize(p);
        }
        const Point margin(options.edge_search_radius, options.edge_search_radius,
                           options.edge_search_radius);
        std::vector<Segment> near;
        for (const auto& s : sharp) {
          Point lo = s.a, hi = s.a;
          lo.minimize(s.b);
          hi.maximize(s.b);
          bool overlaps = true;
          for (int k = 0; k < 3; ++k)
            overlaps =
                overlaps && lo[k] <= box.max[k] + margin[k] && hi[k] >= box.min[k] - margin[k];
          if (overlaps)
            near.push_back(s);
        }
        std::size_t covered = 0;
        bool all_near = !samples.empty();
        double farthest = 0.0;
        for (const Point& p : samples) {
          double best = std::numeric_limits<double>::infinity();
          for (const auto& s : near)
            best = std::min(best, point_segment_distance(p, s.a, s.b));
          if (best <= options.edge_tolerance)
            ++covered;
          if (best <= options.edge_search_radius)
            farthest = std::max(farthest, best);
          else
            all_near = false;
        }
        edge.covered_fraction =
            samples.empty() ? 0.0 : static_cast<double>(covered) / samples.size();
        edge.present = edge.covered_fraction >= 0.5;
        if (all_near)
          edge.distance = farthest;
        result.edges.push_back(edge);
      }
    }
  }

  double area_sum = 0.0, weighted = 0.0, largest = 0.0;
  for (auto f : repaired.faces()) {
    if (!is_new(repaired, f))
      continue;
    const double area = face_area(repaired, f);
    if (!(area > 0.0))
      continue;
    const double angle = normal_cone_angle(complete_scene, face_centroid(repaired, f),
                                           face_normal(repaired, f), options.normal_cone)
                             .smallest_deg;
    area_sum += area;
    weighted += area * angle;
    largest = std::max(largest, angle);
  }
  if (area_sum > 0.0) {
    result.normal_deviation_mean_deg = weighted / area_sum;
    result.normal_deviation_max_deg = largest;
  }
  return result;
}

}  // namespace holebench
