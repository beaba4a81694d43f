#include "core/coplanar_regions.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <utility>

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

std::vector<int> unite_neighbouring_regions(const Mesh& mesh, int region_count,
                                            const std::function<bool(int, int)>& same) {
  std::set<std::pair<int, int>> neighbours;
  for (auto e : mesh.edges()) {
    if (mesh.is_boundary(e))
      continue;
    const auto h = mesh.halfedge_handle(e, 0);
    const int a = region(mesh, mesh.face_handle(h));
    const int b = region(mesh, mesh.opposite_face_handle(h));
    if (a != b && a >= 0 && b >= 0 && a < region_count && b < region_count)
      neighbours.insert({std::min(a, b), std::max(a, b)});
  }
  std::vector<int> parent(region_count);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [a, b] : neighbours) {
    const int ra = find_root(parent, a), rb = find_root(parent, b);
    if (ra != rb && same(a, b))
      parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<int> group(region_count);
  for (int r = 0; r < region_count; ++r)
    group[r] = find_root(parent, r);
  return group;
}

std::vector<int> coplanar_region_groups(const Mesh& mesh, const std::vector<PlaneFit>& planes,
                                        const std::vector<char>& region_is_planar,
                                        const CoplanarRegionsOptions& options) {
  const int count = static_cast<int>(planes.size());
  const auto planar = [&](int r) {
    return r < static_cast<int>(region_is_planar.size()) && region_is_planar[r];
  };
  return unite_neighbouring_regions(mesh, count, [&](int a, int b) {
    return planar(a) && planar(b) && in_one_plane(planes[a], planes[b], options);
  });
}

}  // namespace holebench
