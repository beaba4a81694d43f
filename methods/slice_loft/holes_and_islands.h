// Step I of the slice paper (section 4.1): contours found and classified hole or island by
// developing each onto its plane of maximum span (4.1.1, 4.1.2), islands clustered to
// their hole, and the influencing area of each hole.
#pragma once

#include "methods/slice_loft/hole_structures.h"

#include <vector>

namespace holebench::slice_loft {

struct HoleIdentificationOptions {
  /// The hole's box is enlarged on every side by this fraction of its diagonal (paper: 10 %).
  double influence_margin_rel_box = 0.1;
  /// ... but by at least this many mean boundary-edge lengths, so that small holes in a
  /// mesh of comparable edge length still have slices to trace from (the project's option,
  /// 3 in the variant slice_loft_plus; 0, the paper's box alone, by default).
  double min_influence_margin_edges = 0.0;
};

struct HolesAndIslands {
  std::vector<Contour> contours;
  std::vector<Hole> holes;  ///< one per hole contour, islands attached
};

/// 4.1.1 and 4.1.2: develops the contour onto a reference circle on its plane of maximum
/// span, develops a triangle incident on the reference edge, and classifies the contour an
/// island when the developed triangle's centroid lies inside the developed contour.
bool is_island(const Mesh& mesh, const Contour& contour);

/// Every contour of `mesh`, classified; every hole with its islands, box and influencing
/// area. An island that no hole claims is returned as a hole of its own (`orphan_island`).
HolesAndIslands identify_holes_and_islands(const Mesh& mesh,
                                           const HoleIdentificationOptions& options = {});

}  // namespace holebench::slice_loft
