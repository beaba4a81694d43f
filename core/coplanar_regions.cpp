#include "core/coplanar_regions.h"

#include <cmath>
#include <numeric>

namespace holebench {
namespace {

int find_root(std::vector<int>& parent, int r) {
  while (parent[r] != r) {
    parent[r] = parent[parent[r]];
    r = parent[r];
  }
  return r;
}

bool in_one_plane(const PlaneFit& a, const PlaneFit& b, const CoplanarRegionsOptions& options) {
  if (!a.valid || !b.valid)
    return false;
  const double cosine = OpenMesh::dot(a.plane.normal, b.plane.normal);
  return cosine >= std::cos(options.angle_radians) &&
         std::abs(a.plane.signed_distance(b.plane.point)) <= options.distance &&
         std::abs(b.plane.signed_distance(a.plane.point)) <= options.distance;
}

}  // namespace

std::vector<int> coplanar_region_groups(const Mesh& mesh, const std::vector<PlaneFit>& planes,
                                        const std::vector<char>& region_is_planar,
                                        const CoplanarRegionsOptions& options) {
  const int count = static_cast<int>(planes.size());
  std::vector<int> parent(count);
  std::iota(parent.begin(), parent.end(), 0);
  const auto planar = [&](int r) {
    return r >= 0 && r < count && r < static_cast<int>(region_is_planar.size()) &&
           region_is_planar[r];
  };
  for (auto e : mesh.edges()) {
    if (mesh.is_boundary(e))
      continue;
    const auto h = mesh.halfedge_handle(e, 0);
    const int a = region(mesh, mesh.face_handle(h));
    const int b = region(mesh, mesh.opposite_face_handle(h));
    if (a == b || !planar(a) || !planar(b))
      continue;
    const int ra = find_root(parent, a), rb = find_root(parent, b);
    if (ra != rb && in_one_plane(planes[a], planes[b], options))
      parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<int> group(count);
  for (int r = 0; r < count; ++r)
    group[r] = find_root(parent, r);
  return group;
}

}  // namespace holebench
