#include "metrics/hole_matching.h"

#include "core/boundary_loops.h"
#include "core/distances.h"
#include "metrics/embree/triangle_scene.h"

#include <limits>

namespace holebench {

double distance_to_removed_faces(const Case& c, const HoleTruth& hole, const Point& p) {
  double best = std::numeric_limits<double>::infinity();
  for (int index : hole.removed_faces) {
    Point t[3];
    int k = 0;
    for (auto v : c.complete.fv_range(c.complete.face_handle(index)))
      t[k++] = c.complete.point(v);
    const Point q = closest_point_on_triangle(p, t[0], t[1], t[2]);
    best = std::min(best, (q - p).norm());
  }
  return best;
}

std::vector<Point> input_loop_centroids(const Case& c) {
  std::vector<Point> centroids;
  for (const auto& loop : find_boundary_loops(c.input))
    centroids.push_back(loop_centroid(c.input, loop));
  return centroids;
}

std::vector<HoleMatch> match_holes(const Case& c, const std::vector<HoleReport>& reports) {
  return match_holes(c, reports, input_loop_centroids(c));
}

std::vector<HoleMatch> match_holes(const Case& c, const std::vector<HoleReport>& reports,
                                   const std::vector<Point>& centroids) {
  std::vector<HoleMatch> matches;
  // With one ground-truth hole per boundary loop of the input, holes[i] describes the i-th
  // loop (the generators' convention, docs/cases.md): a report is matched to the loop whose
  // centroid is nearest its own, which is exact for a method that reports its loop's centroid
  // and robust where several holes share removed faces' neighbourhoods.
  if (centroids.size() == c.holes.size() && centroids.size() > 1) {
    for (const auto& report : reports) {
      HoleMatch match;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t h = 0; h < centroids.size(); ++h) {
        const double d = (centroids[h] - report.centroid).norm();
        if (d < best) {
          best = d;
          match.truth = static_cast<int>(h);
        }
      }
      match.distance = distance_to_removed_faces(c, c.holes[match.truth], report.centroid);
      matches.push_back(match);
    }
    return matches;
  }
  for (const auto& report : reports) {
    HoleMatch match;
    match.distance = std::numeric_limits<double>::infinity();
    for (std::size_t h = 0; h < c.holes.size(); ++h) {
      const double distance = distance_to_removed_faces(c, c.holes[h], report.centroid);
      if (distance < match.distance) {
        match.distance = distance;
        match.truth = static_cast<int>(h);
      }
    }
    if (match.truth < 0)
      match.distance = 0.0;
    matches.push_back(match);
  }
  return matches;
}

}  // namespace holebench
