#include "metrics/validity.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>
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

// A face's vertex indices in a canonical cyclic rotation (smallest first), as one key.
struct IndexTriple {
  std::array<int, 3> v;
  bool operator==(const IndexTriple& other) const { return v == other.v; }
};
struct IndexTripleHash {
  std::size_t operator()(const IndexTriple& t) const {
    std::size_t h = 0;
    for (int i : t.v)
      h = h * 1000003u ^ std::hash<int>()(i);
    return h;
  }
};
IndexTriple index_triple(const Mesh& mesh, FaceHandle f) {
  IndexTriple t;
  int k = 0;
  for (auto v : mesh.fv_range(f))
    t.v[k++] = v.idx();
  std::rotate(t.v.begin(), std::min_element(t.v.begin(), t.v.end()), t.v.end());
  return t;
}

struct Box {
  Point lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Point hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};
  void add(const Point& p) {
    lo.minimize(p);
    hi.maximize(p);
  }
  bool meets(const Box& other) const {
    for (int i = 0; i < 3; ++i) {
      if (hi[i] < other.lo[i] || other.hi[i] < lo[i])
        return false;
    }
    return true;
  }
};
Box face_box(const Mesh& mesh, FaceHandle f) {
  Box box;
  for (auto v : mesh.fv_range(f))
    box.add(mesh.point(v));
  return box;
}

}  // namespace

InputSelfIntersections input_self_intersections(const Mesh& input) {
  return {cgal::self_intersecting_pairs(input)};
}

cgal::SelfIntersections self_intersections_from_input(const Mesh& input, const Mesh& repaired,
                                                      const InputSelfIntersections& known_input) {
  // Vertices of the repaired mesh at the input's index and, bit for bit, its point.
  const std::size_t common =
      std::min(input.n_vertices(), static_cast<std::size_t>(repaired.n_vertices()));
  std::vector<char> same_vertex(common, 0);
  for (std::size_t i = 0; i < common; ++i) {
    const VertexHandle v(static_cast<int>(i));
    same_vertex[i] = !repaired.status(v).deleted() && repaired.point(v) == input.point(v);
  }
  const auto on_same_vertices = [&](const IndexTriple& t) {
    for (int i : t.v) {
      if (i < 0 || static_cast<std::size_t>(i) >= common || !same_vertex[i])
        return false;
    }
    return true;
  };
  std::unordered_map<IndexTriple, int, IndexTripleHash> input_face_of;
  input_face_of.reserve(input.n_faces());
  for (auto f : input.faces()) {
    const IndexTriple t = index_triple(input, f);
    if (on_same_vertices(t))
      input_face_of.emplace(t, f.idx());
  }
  // Kept faces (repaired face -> input face, one each) and the others with their box.
  std::vector<int> repaired_face_of_input(input.n_faces(), -1);
  std::vector<char> kept(repaired.n_faces(), 0);
  std::vector<int> others;
  Box others_box;
  for (auto f : repaired.faces()) {
    const auto it = input_face_of.find(index_triple(repaired, f));
    if (it != input_face_of.end() && repaired_face_of_input[it->second] < 0) {
      repaired_face_of_input[it->second] = f.idx();
      kept[f.idx()] = 1;
      continue;
    }
    others.push_back(f.idx());
    for (auto v : repaired.fv_range(f))
      others_box.add(repaired.point(v));
  }
  // The pairs with a face that is not kept: among those faces and the kept ones nearby.
  std::vector<FacePair> pairs;
  if (!others.empty()) {
    std::vector<int> tested = others;
    for (auto f : repaired.faces()) {
      if (kept[f.idx()] && face_box(repaired, f).meets(others_box))
        tested.push_back(f.idx());
    }
    for (const FacePair& p : cgal::self_intersecting_pairs(repaired, tested)) {
      if (!(kept[p.first] && kept[p.second]))
        pairs.push_back(p);
    }
  }
  // The pairs of two kept faces: the input's.
  for (const auto& [a, b] : known_input.pairs) {
    const int f = repaired_face_of_input[a], g = repaired_face_of_input[b];
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

Validity validity(const Mesh& input, const Mesh& repaired, const ValidityOptions& options,
                  const InputSelfIntersections* known_input) {
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
    cgal::SelfIntersections pairs;
    if (known_input) {
      pairs = self_intersections_from_input(input, repaired, *known_input);
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
