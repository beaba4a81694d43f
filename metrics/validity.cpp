#include "metrics/validity.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "metrics/growing_box.h"
#include "metrics/kept_faces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace holebench {
namespace {

constexpr double kPi = 3.14159265358979323846;

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

GrowingBox face_box(const Mesh& mesh, FaceHandle f) {
  GrowingBox box;
  for (auto v : mesh.fv_range(f))
    box.add(mesh.point(v));
  return box;
}

}  // namespace

InputSelfIntersections input_self_intersections(const Mesh& input) {
  return {cgal::self_intersecting_pairs(input)};
}

cgal::SelfIntersections self_intersections_from_input(const Mesh& repaired,
                                                      const InputSelfIntersections& known_input,
                                                      const KeptFaces& kept_of_input) {
  const auto is_kept = [&](int f) { return kept_of_input.input_face_of_repaired[f] >= 0; };
  std::vector<int> others;
  GrowingBox others_box;
  for (auto f : repaired.faces()) {
    if (is_kept(f.idx()))
      continue;
    others.push_back(f.idx());
    for (auto v : repaired.fv_range(f))
      others_box.add(repaired.point(v));
  }
  // The pairs with a face that is not kept: among those faces and the kept ones nearby.
  std::vector<FacePair> pairs;
  if (!others.empty()) {
    std::vector<int> tested = others;
    for (auto f : repaired.faces()) {
      if (is_kept(f.idx()) && face_box(repaired, f).meets(others_box))
        tested.push_back(f.idx());
    }
    for (const FacePair& p : cgal::self_intersecting_pairs(repaired, tested)) {
      if (!(is_kept(p.first) && is_kept(p.second)))
        pairs.push_back(p);
    }
  }
  // The pairs of two kept faces: the input's.
  for (const auto& [a, b] : known_input.pairs) {
    const int f = kept_of_input.repaired_face_of_input[a];
    const int g = kept_of_input.repaired_face_of_input[b];
    if (f >= 0 && g >= 0)
      pairs.push_back(std::minmax(f, g));
  }
  cgal::SelfIntersections result;
  result.pairs = pairs.size();
  for (const auto& [f, g] : pairs) {
    if (is_new(repaired, FaceHandle(f)) || is_new(repaired, FaceHandle(g)))
      ++result.patch_pairs;
  }
  return result;
}

cgal::SelfIntersections self_intersections_from_input(const Mesh& input, const Mesh& repaired,
                                                      const InputSelfIntersections& known_input) {
  return self_intersections_from_input(repaired, known_input, kept_faces(input, repaired));
}

Validity validity(const Mesh& input, const Mesh& repaired, const ValidityOptions& options,
                  const InputSelfIntersections* known_input, const KeptFaces* kept_of_input,
                  const InputTopology* topology) {
  Validity result;
  std::optional<TopologyCounts> counts;
  if (topology && kept_of_input)
    counts = topology_from_input(input, repaired, *topology, *kept_of_input);
  if (counts) {
    result.open_boundary_loops = counts->open_boundary_loops;
    result.non_manifold_vertices = counts->non_manifold_vertices;
    result.orientation_conflicts = counts->orientation_conflicts;
  } else {
    result.open_boundary_loops = find_boundary_loops(repaired).size();
    for (auto v : repaired.vertices()) {
      if (!repaired.is_manifold(v))
        ++result.non_manifold_vertices;
    }
    result.orientation_conflicts = conflicting_edges(repaired).size();
  }

  if (options.self_intersections) {
    cgal::SelfIntersections pairs;
    if (known_input) {
      pairs = kept_of_input ? self_intersections_from_input(repaired, *known_input, *kept_of_input)
                            : self_intersections_from_input(input, repaired, *known_input);
    } else {
      for (const auto& [f, g] : cgal::self_intersecting_pairs(repaired)) {
        ++pairs.pairs;
        if (is_new(repaired, FaceHandle(f)) || is_new(repaired, FaceHandle(g)))
          ++pairs.patch_pairs;
      }
    }
    result.self_intersections_tested = true;
    result.self_intersections = pairs.pairs;
    result.patch_self_intersections = pairs.patch_pairs;
  }

  for (auto f : repaired.faces()) {
    if (!is_new(repaired, f))
      continue;
    const auto t = face_corners(repaired, f);
    if (face_area(repaired, f) <= options.degenerate_area ||
        smallest_angle_degrees(t) < options.min_angle_degrees)
      ++result.new_degenerate_faces;
  }

  // An input face away from the holes that the repair kept is unchanged (the same points in
  // the same order); the others are looked up among the repaired faces by their points.
  std::vector<int> not_kept;
  for (auto f : input.faces()) {
    if (kept_of_input && kept_of_input->repaired_face_of_input[f.idx()] >= 0)
      continue;
    bool near_hole = false;
    for (auto v : input.fv_range(f))
      near_hole = near_hole || input.is_boundary(v);
    if (!near_hole)
      not_kept.push_back(f.idx());
  }
  if (!not_kept.empty()) {
    std::set<std::array<std::array<double, 3>, 3>> repaired_faces;
    for (auto f : repaired.faces())
      repaired_faces.insert(canonical(face_corners(repaired, f)));
    for (int f : not_kept) {
      if (!repaired_faces.count(canonical(face_corners(input, input.face_handle(f)))))
        ++result.original_faces_changed;
    }
  }
  return result;
}

}  // namespace holebench
