// Section 3.3 of the B-Rep paper, user guidance: an arrow (P, r), ||r|| = 1, that tells a
// depth-camera user where to look to capture a hole.
//  - equation 3, inner holes with k <= 3: r = -sum n_i / ||sum n_i||, P = Ps - d r (k = 1),
//    1/2 (T_1 + T_2) - d r (k = 2), 1/3 (T_1 + T_2 + T_3) - d r (k = 3);
//  - equation 4, outer holes with k <= 3: r = sum a_i n_i / ||sum n_i||, a_i = +1 where the
//    hole is part of face i's inner boundary, -1 where of its outer boundary;
//  - equation 5, k > 3: M = 1/k sum T_i, Delta_i = (M - T_i) x v_ij, j = (i + 1) mod k,
//    r = -sum Delta_i / ||sum Delta_i||.
#pragma once

#include "core/method_result.h"
#include "methods/brep_guidance/brep_faces.h"
#include "methods/brep_guidance/hole_classification.h"
#include "methods/brep_guidance/hole_detection.h"

namespace holebench::brep_guidance {

/// Equation 3: the arrow for an inner hole with k <= 3, `d` from the hole.
GuidanceArrow inner_hole_arrow(const BrepFaces& faces, const Hole& hole, double d);

/// Equation 4 with the boundary kinds a_i. The paper divides by ||sum n_i||, which has unit
/// length only when every a_i is the same; r is normalised here, as ||r|| = 1 requires. The
/// paper gives no position for outer holes; P is placed as in equation 3.
GuidanceArrow outer_hole_arrow(const BrepFaces& faces, const Hole& hole,
                               const std::vector<BoundaryKind>& boundary_kinds, double d);

/// Equation 5 for k > 3 (and wherever a k <= 3 hole's direction is undefined because its
/// normals cancel). "M ... can be used as the position": P = M - d r, so that the arrow, like
/// the others, stands d away from the hole and points at it.
GuidanceArrow fan_arrow(const Mesh& mesh, const Hole& hole, double d);

/// The arrow the paper prescribes for a classified hole.
GuidanceArrow guidance_arrow(const Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                             const Classification& classification, double d);

}  // namespace holebench::brep_guidance
