// A CAD-like solid: an axis-aligned box whose six faces are six regions, each
// tessellated as a regular grid of right triangles fine enough to punch holes into.
#pragma once

#include "core/mesh.h"

namespace holebench::generators {

struct BoxOptions {
  Point size{2.0, 1.5, 1.0};  ///< edge lengths along x, y, z; the box spans [0, size]
  double cell = 0.0625;       ///< target grid spacing; each edge gets ceil(length / cell) cells
};

/// The closed box, outward oriented, regions 0..5 for the faces -x, +x, -y, +y, -z, +z.
/// Every element is `Provenance::Original`. Deterministic.
Mesh make_box(const BoxOptions& options = {});

}  // namespace holebench::generators
