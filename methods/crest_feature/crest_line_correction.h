// The user's correction of crest lines (crest-line paper, section 3.4.2, figures 2 and 9c):
// once the feature points, pairs and corner triple are settled, the user sees the crest
// lines' directions where they enter the hole and may replace any of them. A replaced
// direction becomes the feature point's tangent, so it sets the Catmull-Rom control points
// P0 and P3 (equation 3) and a corner's meeting point (3.4.3).
#pragma once

#include "methods/crest_feature/feature_points.h"
#include "methods/crest_feature/hole_identification.h"
#include "methods/user.h"

namespace holebench::crest_feature {

struct CrestLineCorrection {
  HoleFeatures features;  ///< the input's, with the corrected tangents
  int corrected = 0;      ///< feature points whose direction the user replaced
};

/// 3.4.2: asks `user` about the crest lines' directions at the feature points of `features`
/// and takes its answer. A replaced direction (non-zero, finite, differing from the tangent)
/// is normalised and taken as it is (the user answers with directions into the hole, as the
/// proposal's are), and the feature point no
/// longer follows its detected crest line (`crest_line` = -1: P0 and P3 are then on the
/// corrected tangent line whatever InterpolationOptions::control_points says). An answer of
/// the wrong size is ignored.
CrestLineCorrection review_crest_lines(const Mesh& mesh, const Hole& hole, int hole_index,
                                       const HoleFeatures& features, User& user);

}  // namespace holebench::crest_feature
