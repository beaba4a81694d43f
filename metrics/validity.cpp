#include "metrics/validity.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/face_subset.h"
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

// The kept faces of `repaired` that may meet a face inside `box`, in index order: where a scene
// is given, those within the sphere about the box whose own box meets it (a kept face that
// meets a face inside the box has a point in the box, so within that sphere: no intersecting
// pair is lost), else every kept face whose box meets it, from a pass over every face.
std::vector<int> kept_faces_meeting(const Mesh& repaired, const KeptFaces& kept,
                                    const GrowingBox& box, const embree::TriangleScene* scene) {
  const auto is_kept = [&](int f) { return kept.input_face_of_repaired[f] >= 0; };
  std::vector<int> meeting;
  if (scene) {
    for (int f : scene->faces_within(box.centre(), box.enclosing_radius())) {
      if (is_kept(f) && !repaired.status(FaceHandle(f)).deleted() &&
          face_box(repaired, FaceHandle(f)).meets(box))
        meeting.push_back(f);
    }
    std::sort(meeting.begin(), meeting.end());
    meeting.erase(std::unique(meeting.begin(), meeting.end()), meeting.end());
    return meeting;
  }
  for (auto f : repaired.faces()) {
    if (is_kept(f.idx()) && face_box(repaired, f).meets(box))
      meeting.push_back(f.idx());
  }
  return meeting;
}

}  // namespace

InputSelfIntersections input_self_intersections(const Mesh& input) {
  return {cgal::self_intersecting_pairs(input)};
}

cgal::SelfIntersections self_intersections_from_input(const Mesh& repaired,
                                                      const InputSelfIntersections& known_input,
                                                      const KeptFaces& kept_of_input,
                                                      const embree::TriangleScene* repaired_scene) {
  const auto is_kept = [&](int f) { return kept_of_input.input_face_of_repaired[f] >= 0; };
  std::vector<int> others;
  GrowingBox others_box;
  for (int f : kept_of_input.repaired_faces_not_kept) {
    const FaceHandle face(f);
    if (repaired.status(face).deleted())
      continue;
    others.push_back(f);
    for (auto v : repaired.fv_range(face))
      others_box.add(repaired.point(v));
  }
  // The pairs with a face that is not kept: among those faces and the kept ones nearby.
  std::vector<FacePair> pairs;
  if (!others.empty()) {
    std::vector<int> tested = others;
    const std::vector<int> near =
        kept_faces_meeting(repaired, kept_of_input, others_box, repaired_scene);
    tested.insert(tested.end(), near.begin(), near.end());
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
                  const ValidityShortcuts& known) {
  const KeptFaces* kept_of_input = known.kept_of_input;
  Validity result;
  std::optional<TopologyCounts> counts;
  if (known.topology && kept_of_input)
    counts = topology_from_input(input, repaired, *known.topology, *kept_of_input);
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
    if (known.input_pairs) {
      pairs = kept_of_input ? self_intersections_from_input(repaired, *known.input_pairs,
                                                            *kept_of_input, known.repaired_scene)
                            : self_intersections_from_input(input, repaired, *known.input_pairs);
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

  std::vector<int> found_new_faces;
  for (int index : new_face_indices(repaired, known.new_faces, found_new_faces)) {
    const FaceHandle f(index);
    const auto t = face_corners(repaired, f);
    if (face_area(repaired, f) <= options.degenerate_area ||
        smallest_angle_degrees(t) < options.min_angle_degrees)
      ++result.new_degenerate_faces;
  }

  // An input face away from the holes that the repair kept is unchanged (the same points in
  // the same order); the others are looked up among the repaired faces by their points.
  std::vector<int> not_kept;
  const auto add_if_away_from_holes = [&](FaceHandle f) {
    bool near_hole = false;
    for (auto v : input.fv_range(f))
      near_hole = near_hole || input.is_boundary(v);
    if (!near_hole)
      not_kept.push_back(f.idx());
  };
  if (kept_of_input) {
    for (int f : kept_of_input->input_faces_not_kept) {
      if (!input.status(FaceHandle(f)).deleted())
        add_if_away_from_holes(FaceHandle(f));
    }
  } else {
    for (auto f : input.faces())
      add_if_away_from_holes(f);
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
