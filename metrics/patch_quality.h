// The metrics of a patch that need no ground truth, for real holes (generators/real_holes.h):
// how the patch meets the surface around it, how smooth it is inside, and the shape of its
// triangles. The patch is the repaired mesh's new faces (Provenance::New).
#pragma once

#include "core/mesh.h"

#include <optional>

namespace holebench {

struct PatchQuality {
  /// Edges between a new face and an original one (the hole's boundary, once filled): the
  /// angle between the two faces' normals, in degrees; mean over the edges and max. Empty
  /// where the patch touches no original face.
  std::optional<double> boundary_normal_jump_mean_deg, boundary_normal_jump_max_deg;
  /// Edges between two new faces: the angle between their normals (0: flat), mean and max.
  std::optional<double> dihedral_mean_deg, dihedral_max_deg;
  /// Per new face, 4 sqrt(3) area / (a^2 + b^2 + c^2): 1 for an equilateral triangle, 0 for a
  /// degenerate one; min over the faces and mean. Empty without new faces.
  std::optional<double> triangle_quality_min, triangle_quality_mean;
};

/// The patch quality of `repaired`'s new faces.
PatchQuality patch_quality(const Mesh& repaired);

}  // namespace holebench
