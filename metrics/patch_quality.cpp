#include "metrics/patch_quality.h"

#include "core/geometry.h"

#include <algorithm>
#include <cmath>

namespace holebench {
namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

// The angle between the normals of the two faces at `e` (0: coplanar), in degrees.
double normal_angle_deg(const Mesh& mesh, EdgeHandle e) {
  return std::abs(signed_dihedral_angle(mesh, e)) * kDegreesPerRadian;
}

double triangle_quality(const Mesh& mesh, FaceHandle f) {
  const auto p = face_corners(mesh, f);
  const double squares =
      (p[1] - p[0]).sqrnorm() + (p[2] - p[1]).sqrnorm() + (p[0] - p[2]).sqrnorm();
  return squares > 0.0 ? 4.0 * std::sqrt(3.0) * face_area(mesh, f) / squares : 0.0;
}

struct Summary {
  double sum = 0.0, max = 0.0, min = 1e300;
  std::size_t count = 0;
  void add(double value) {
    sum += value;
    max = std::max(max, value);
    min = std::min(min, value);
    ++count;
  }
};

}  // namespace

PatchQuality patch_quality(const Mesh& repaired) {
  Summary jump, dihedral, quality;
  for (auto e : repaired.edges()) {
    if (repaired.is_boundary(e))
      continue;
    const FaceHandle a = repaired.face_handle(repaired.halfedge_handle(e, 0));
    const FaceHandle b = repaired.face_handle(repaired.halfedge_handle(e, 1));
    const bool a_new = is_new(repaired, a), b_new = is_new(repaired, b);
    if (a_new && b_new)
      dihedral.add(normal_angle_deg(repaired, e));
    else if (a_new || b_new)
      jump.add(normal_angle_deg(repaired, e));
  }
  for (auto f : repaired.faces()) {
    if (is_new(repaired, f))
      quality.add(triangle_quality(repaired, f));
  }
  PatchQuality result;
  if (jump.count > 0) {
    result.boundary_normal_jump_mean_deg = jump.sum / static_cast<double>(jump.count);
    result.boundary_normal_jump_max_deg = jump.max;
  }
  if (dihedral.count > 0) {
    result.dihedral_mean_deg = dihedral.sum / static_cast<double>(dihedral.count);
    result.dihedral_max_deg = dihedral.max;
  }
  if (quality.count > 0) {
    result.triangle_quality_min = quality.min;
    result.triangle_quality_mean = quality.sum / static_cast<double>(quality.count);
  }
  return result;
}

}  // namespace holebench
