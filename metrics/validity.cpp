#include "metrics/validity.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace holebench {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::array<Point, 3> face_points(const Mesh& mesh, FaceHandle f) {
  std::array<Point, 3> t;
  int k = 0;
  for (auto v : mesh.fv_range(f))
    t[k++] = mesh.point(v);
  return t;
}

// The triangle's points in a canonical cyclic rotation (smallest point first), so that two
// faces with the same points in the same cyclic order compare equal.
std::array<std::array<double, 3>, 3> canonical(const std::array<Point, 3>& t) {
  std::array<std::array<double, 3>, 3> p;
  for (int i = 0; i < 3; ++i)
    p[i] = {t[i][0], t[i][1], t[i][2]};
  const int first = static_cast<int>(std::min_element(p.begin(), p.end()) - p.begin());
  std::rotate(p.begin(), p.begin() + first, p.end());
  return p;
}

double smallest_angle_degrees(const std::array<Point, 3>& t) {
  double smallest = 180.0;
  for (int i = 0; i < 3; ++i) {
    const Point u = t[(i + 1) % 3] - t[i];
    const Point w = t[(i + 2) % 3] - t[i];
    const double nu = u.norm(), nw = w.norm();
    if (!(nu > 0.0) || !(nw > 0.0))
      return 0.0;
    const double c = std::clamp(OpenMesh::dot(u, w) / (nu * nw), -1.0, 1.0);
    smallest = std::min(smallest, std::acos(c) * 180.0 / kPi);
  }
  return smallest;
}

}  // namespace

Validity validity(const Mesh& input, const Mesh& repaired, const ValidityOptions& options) {
  Validity result;
  result.open_boundary_loops = find_boundary_loops(repaired).size();

  for (auto v : repaired.vertices()) {
    if (!repaired.is_manifold(v))
      ++result.non_manifold_vertices;
  }

  std::map<std::pair<int, int>, int> directed_uses;
  for (auto f : repaired.faces()) {
    std::array<int, 3> ids;
    int k = 0;
    for (auto v : repaired.fv_range(f))
      ids[k++] = v.idx();
    for (int i = 0; i < 3; ++i) {
      if (++directed_uses[{ids[i], ids[(i + 1) % 3]}] == 2)
        ++result.orientation_conflicts;
    }
  }

  if (options.self_intersections) {
    const auto pairs = cgal::self_intersections(repaired);
    result.self_intersections_tested = true;
    result.self_intersections = pairs.pairs;
    result.patch_self_intersections = pairs.patch_pairs;
  }

  for (auto f : repaired.faces()) {
    if (!is_new(repaired, f))
      continue;
    const auto t = face_points(repaired, f);
    if (face_area(repaired, f) <= options.degenerate_area ||
        smallest_angle_degrees(t) < options.min_angle_degrees)
      ++result.new_degenerate_faces;
  }

  std::set<std::array<std::array<double, 3>, 3>> repaired_faces;
  for (auto f : repaired.faces())
    repaired_faces.insert(canonical(face_points(repaired, f)));
  for (auto f : input.faces()) {
    bool near_hole = false;
    for (auto v : input.fv_range(f))
      near_hole = near_hole || input.is_boundary(v);
    if (near_hole)
      continue;
    if (!repaired_faces.count(canonical(face_points(input, f))))
      ++result.original_faces_changed;
  }
  return result;
}

}  // namespace holebench
