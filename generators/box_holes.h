// The walking skeleton's cases: one hole in a face interior (k = 1), one across a convex
// edge (k = 2) and one at a convex corner (k = 3) of the box solid.
#pragma once

#include "core/case.h"

#include <string>

namespace holebench::generators {

enum class BoxHoleTarget { FaceInterior, Edge, Corner };

struct BoxHoleOptions {
  BoxHoleTarget target = BoxHoleTarget::FaceInterior;
  double radius = 0.3;          ///< hole radius (model units; the box diagonal is ~2.69)
  double structure_size = 0.5;  ///< delta_s of the B-Rep paper: decides close vs. guide
};

/// The complete box, the holed box and the hole's ground truth, labels included.
Case make_box_hole_case(const BoxHoleOptions& options);

const char* to_string(BoxHoleTarget target);

}  // namespace holebench::generators
