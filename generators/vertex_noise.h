// Vertex noise as in the slice paper (section 5): "percentage deviation of each mesh vertex
// with respect to a reference dimension", the reference being 1 % of the bounding-box
// diagonal.
#pragma once

#include "core/mesh.h"

#include <cstdint>

namespace holebench::generators {

struct NoiseOptions {
  double percent = 0.0;           ///< deviation, in % of the reference length (0, 5, 25, ...)
  double reference_length = 0.0;  ///< 1 % of the complete model's bounding-box diagonal
  std::uint64_t seed = 0;
};

/// The reference length of the slice paper: 1 % of the bounding-box diagonal.
double noise_reference_length(const Mesh& complete);

/// Moves every vertex of `mesh` by exactly percent / 100 * reference_length in a direction
/// uniform on the sphere. The paper leaves the distribution open; a fixed magnitude makes
/// the level mean what it says (every vertex deviates by that much). Vertices are visited
/// in index order, so the same seed gives the same bits. Nothing happens at 0 %.
void add_vertex_noise(Mesh& mesh, const NoiseOptions& options);

}  // namespace holebench::generators
