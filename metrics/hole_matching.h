// Which ground-truth hole a method's hole report is about.
//
// Rule: where the case has one ground-truth hole per boundary loop of its input (and more
// than one), holes[i] describes the i-th loop of find_boundary_loops (the generators'
// convention) and a report is matched to the loop whose centroid is nearest its centroid.
// Otherwise a report is matched to the ground-truth hole whose removed faces (triangles of the
// complete model) come closest to the report's centroid (the mean of its loop's vertices);
// the distance is the exact point-to-triangle distance, ties go to the lower hole index.
// Every report is matched when the case has at least one hole; several reports may match
// the same hole (a method that splits a hole).
#pragma once

#include "core/case.h"
#include "core/method_result.h"

#include <vector>

namespace holebench {

struct HoleMatch {
  int truth = -1;         ///< index into Case::holes, -1 when the case has no hole
  double distance = 0.0;  ///< from the report's centroid to that hole's removed faces
};

/// One match per report, in the order of `reports`.
std::vector<HoleMatch> match_holes(const Case& c, const std::vector<HoleReport>& reports);

/// The centroids of the input's boundary loops, in find_boundary_loops' order: what
/// match_holes needs of the input, the same for every method (metrics/case_evaluation.h
/// keeps them per case).
std::vector<Point> input_loop_centroids(const Case& c);

/// match_holes with the input's loop centroids given (input_loop_centroids(c)).
std::vector<HoleMatch> match_holes(const Case& c, const std::vector<HoleReport>& reports,
                                   const std::vector<Point>& loop_centroids);

/// The distance from `p` to the nearest removed face of `hole` (infinity if it has none).
double distance_to_removed_faces(const Case& c, const HoleTruth& hole, const Point& p);

}  // namespace holebench
