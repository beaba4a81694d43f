// Regions that are one plane: a planar face split in two by the B-Rep (a model fused from
// several bodies) or by a segmentation is still one face of the hole taxonomy (CASES.md).
#pragma once

#include "core/mesh.h"
#include "core/plane_fit.h"

#include <functional>
#include <vector>

namespace holebench {

struct CoplanarRegionsOptions {
  /// Two regions are one plane where their fitted planes' normals differ by at most this
  /// angle and each lies within `distance` of the other's plane.
  double angle_radians = 1e-3;
  double distance = 0.0;  ///< absolute; callers pass a fraction of the diagonal
};

/// For each region id 0 .. region_count - 1, the smallest region id of its group: regions that
/// share an edge and for which `same(a, b)` holds (a < b; asked once per neighbouring pair,
/// unless the two are already in one group), closed transitively.
std::vector<int> unite_neighbouring_regions(const Mesh& mesh, int region_count,
                                            const std::function<bool(int, int)>& same);

/// For each region id of `mesh`, the smallest region id of its coplanar group: planar regions
/// (`region_is_planar`, by region id) that share an edge and lie in one plane, closed
/// transitively. A region that is not planar, or has no coplanar neighbour, is its own group.
/// `planes` are the regions' fitted planes (fit_region_planes).
std::vector<int> coplanar_region_groups(const Mesh& mesh, const std::vector<PlaneFit>& planes,
                                        const std::vector<char>& region_is_planar,
                                        const CoplanarRegionsOptions& options);

}  // namespace holebench
