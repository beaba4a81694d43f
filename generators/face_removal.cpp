#include "generators/face_removal.h"

#include "core/geometry.h"
#include "core/labels_summary.h"
#include "core/plane_fit.h"
#include "core/polygon.h"
#include "generators/hole_punch.h"
#include "generators/missing_sharp_edges.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace holebench::generators {
namespace {

/// A transition's two faces must meet at a dihedral angle of at least this (radians): a
/// tangent or coplanar border has no convexity.
constexpr double kMinTransitionAngle = M_PI / 180.0;
/// A removed face lies in a loop face's plane if all its vertices are this close (relative to
/// the diagonal); between this and kFarFromPlane the orientation is ambiguous.
constexpr double kInPlane = 1e-6;
constexpr double kFarFromPlane = 1e-4;

// The faces' adjacency and wires, read once per model from the mesh, whose regions are the
// B-Rep faces and whose region borders are the B-Rep edges.
struct Topology {
  const AnalysedModel& model;
  const Mesh& mesh;
  int regions = 0;
  std::vector<std::vector<HalfedgeHandle>> border;  ///< per region: its side of its borders
  std::vector<std::set<int>> neighbours;
  std::vector<PlaneFit> planes;
  std::vector<int> wire_of;              ///< per halfedge of a border: its wire
  std::vector<char> wire_is_outer;       ///< per wire
  std::vector<char> wires_known;         ///< per region: one outer wire, wires never touch
  std::vector<std::vector<int>> points;  ///< per region: its vertices

  explicit Topology(const AnalysedModel& m) : model(m), mesh(m.mesh) {
    for (auto f : mesh.faces())
      regions = std::max(regions, region(mesh, f) + 1);
    border.resize(regions);
    neighbours.resize(regions);
    points.resize(regions);
    planes = fit_region_planes(mesh);
    planes.resize(regions);
    wire_of.assign(mesh.n_halfedges(), -1);
    wires_known.assign(regions, 0);
    std::vector<std::set<int>> vertex_sets(regions);
    for (auto h : mesh.halfedges()) {
      const auto f = mesh.face_handle(h);
      const auto g = mesh.opposite_face_handle(h);
      if (!f.is_valid() || !g.is_valid())
        continue;
      const int a = region(mesh, f), b = region(mesh, g);
      if (a == b)
        continue;
      border[a].push_back(h);
      neighbours[a].insert(b);
    }
    for (auto f : mesh.faces()) {
      for (auto v : mesh.fv_range(f))
        vertex_sets[region(mesh, f)].insert(v.idx());
    }
    for (int r = 0; r < regions; ++r) {
      points[r].assign(vertex_sets[r].begin(), vertex_sets[r].end());
      find_wires(r);
    }
  }

  // Chains the region's border into wires; the outer one runs counter-clockwise about the
  // face's normal (the face on its left).
  void find_wires(int r) {
    if (r >= static_cast<int>(model.region_is_planar.size()) || !model.region_is_planar[r] ||
        !planes[r].valid)
      return;
    std::unordered_map<int, HalfedgeHandle> leaving;
    for (auto h : border[r]) {
      if (!leaving.emplace(mesh.from_vertex_handle(h).idx(), h).second)
        return;  // the face's wires touch at a vertex
    }
    int outer = 0;
    for (auto start : border[r]) {
      if (wire_of[start.idx()] >= 0)
        continue;
      const int wire = static_cast<int>(wire_is_outer.size());
      Point twice_area(0, 0, 0);
      for (HalfedgeHandle h = start;;) {
        wire_of[h.idx()] = wire;
        twice_area += OpenMesh::cross(mesh.point(mesh.from_vertex_handle(h)),
                                      mesh.point(mesh.to_vertex_handle(h)));
        const auto next = leaving.find(mesh.to_vertex_handle(h).idx());
        if (next == leaving.end())
          return;
        h = next->second;
        if (h == start)
          break;
      }
      const bool is_outer = OpenMesh::dot(twice_area, planes[r].plane.normal) > 0.0;
      wire_is_outer.push_back(is_outer);
      outer += is_outer;
    }
    wires_known[r] = outer == 1;
  }
};

// The hole left by removing `faces`: its loop and labels (without size and decision), or the
// reason the family does not keep it.
struct Removal {
  std::vector<HalfedgeHandle> loop;  ///< removed-side halfedges: the holed mesh's boundary
  HoleLabels labels;
  std::string reason;  ///< empty if kept
};

Removal analyse_removal(const Topology& t, const std::vector<int>& faces) {
  const Mesh& mesh = t.mesh;
  Removal result;
  auto removed = [&](int r) { return std::find(faces.begin(), faces.end(), r) != faces.end(); };
  auto fail = [&](std::string reason) {
    result.reason = std::move(reason);
    return result;
  };
  // The hole's halfedges, the removed face on their left as find_boundary_loops gives them.
  std::unordered_map<int, HalfedgeHandle> leaving;
  HalfedgeHandle first;
  std::size_t count = 0;
  std::map<int, int> hole_edges_of_kept_triangle;
  for (int r : faces) {
    for (auto h : t.border[r]) {
      if (removed(region(mesh, mesh.opposite_face_handle(h))))
        continue;
      if (!leaving.emplace(mesh.from_vertex_handle(h).idx(), h).second)
        return fail("the hole's boundary touches itself at a vertex");
      if (!first.is_valid() || h.idx() < first.idx())
        first = h;
      ++count;
      if (++hole_edges_of_kept_triangle[mesh.opposite_face_handle(h).idx()] == 3)
        return fail("a kept triangle would hang by no edge");
    }
  }
  if (count == 0)
    return fail("the faces are a whole component");
  for (HalfedgeHandle h = first;;) {
    result.loop.push_back(h);
    const auto next = leaving.find(mesh.to_vertex_handle(h).idx());
    if (next == leaving.end())
      return fail("the hole's boundary is not closed");
    h = next->second;
    if (h == first)
      break;
  }
  if (result.loop.size() != count)
    return fail("the hole has more than one boundary loop");

  // The visits: runs of one kept face along the loop, merged across the start.
  const std::size_t n = result.loop.size();
  auto kept_region = [&](std::size_t i) {
    return region(mesh, mesh.opposite_face_handle(result.loop[i % n]));
  };
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < n; ++i) {
    if (kept_region(i) != kept_region(i + n - 1))
      starts.push_back(i);
  }
  if (starts.empty())
    starts.push_back(0);
  HoleLabels& labels = result.labels;
  labels.k = static_cast<int>(starts.size());
  if (labels.k > 3)
    return fail(fmt::format("the loop runs along {} faces (more than 3)", labels.k));
  for (auto s : starts)
    labels.regions.push_back(kept_region(s));
  for (int r : labels.regions) {
    if (r >= static_cast<int>(t.model.region_is_planar.size()) || !t.model.region_is_planar[r])
      return fail(fmt::format("face {} along the loop is not planar", r));
  }
  // Transitions: the vertex where visit i + 1 starts; only the two faces may meet there, along
  // an edge whose dihedral angle gives the convexity.
  if (labels.k > 1) {
    for (std::size_t i = 0; i < starts.size(); ++i) {
      const std::size_t next = (i + 1) % starts.size();
      const auto v = mesh.from_vertex_handle(result.loop[starts[next]]);
      const int from = labels.regions[i], to = labels.regions[next];
      std::optional<double> angle;
      for (auto h : mesh.voh_range(v)) {
        const int a = region(mesh, mesh.face_handle(h));
        if (!removed(a) && a != from && a != to)
          return fail(fmt::format("a third face ({}) meets a transition", a));
        const int b = region(mesh, mesh.opposite_face_handle(h));
        if ((a == from && b == to) || (a == to && b == from))
          angle = signed_dihedral_angle(mesh, mesh.edge_handle(h));
      }
      if (!angle)
        return fail("no edge between the faces at a transition");
      if (std::abs(*angle) < kMinTransitionAngle)
        return fail("two faces meet tangentially or coplanar at a transition");
      labels.transitions.push_back(*angle > 0.0 ? Convexity::Convex : Convexity::Reflex);
    }
  }
  // Orientation: inner iff every removed face lies in the plane of a face along the loop
  // (enlarging those faces restores the model).
  const double diagonal = t.model.diagonal;
  bool inner = true;
  for (int r : faces) {
    double best = HUGE_VAL;
    for (int l : labels.regions) {
      double farthest = 0.0;
      for (int v : t.points[r]) {
        farthest = std::max(
            farthest,
            std::abs(t.planes[l].plane.signed_distance(mesh.point(mesh.vertex_handle(v)))));
      }
      best = std::min(best, farthest);
    }
    if (best > kInPlane * diagonal && best < kFarFromPlane * diagonal)
      return fail(fmt::format("face {} lies almost in a loop face's plane", r));
    inner = inner && best <= kInPlane * diagonal;
  }
  labels.orientation = inner ? Orientation::Inner : Orientation::Outer;
  if (!inner) {
    for (auto s : starts) {
      const auto h = mesh.opposite_halfedge_handle(result.loop[s]);
      const int r = region(mesh, mesh.face_handle(h));
      if (!t.wires_known[r] || t.wire_of[h.idx()] < 0)
        return fail(fmt::format("the wires of face {} are not simple", r));
      labels.boundary_kinds.push_back(t.wire_is_outer[t.wire_of[h.idx()]] ? BoundaryKind::Outer
                                                                          : BoundaryKind::Inner);
    }
    // CASES.md calls a k = 1 loop on a face's inner wire inner by definition, its geometry
    // (the missing faces leave the face's plane) outer: not a combination of the taxonomy
    // (docs/cases.md), so left out.
    if (labels.k == 1 && labels.boundary_kinds[0] == BoundaryKind::Inner)
      return fail("a k = 1 loop on a face's inner wire with the missing faces off its plane");
  }
  if (labels.k == 3) {
    const Point& a = t.planes[labels.regions[0]].plane.normal;
    const Point& b = t.planes[labels.regions[1]].plane.normal;
    const Point& c = t.planes[labels.regions[2]].plane.normal;
    labels.linearly_dependent_faces = std::abs(OpenMesh::dot(OpenMesh::cross(a, b), c)) < 1e-6;
  }
  if (std::count(labels.boundary_kinds.begin(), labels.boundary_kinds.end(), BoundaryKind::Inner) >=
      2)
    labels.known_weak_spot = "multiple_inner_boundaries";
  else if (labels.k == 2 && labels.transitions[0] != labels.transitions[1])
    labels.known_weak_spot = "twisted_face";
  return result;
}

// Connected sets of 1 to kMaxRemovedFaces faces, each once, ascending.
std::vector<std::vector<int>> connected_face_sets(const Topology& t) {
  std::set<std::vector<int>> sets;
  for (int a = 0; a < t.regions; ++a) {
    if (t.border[a].empty())
      continue;
    sets.insert({a});
    for (int b : t.neighbours[a]) {
      if (b < a)
        continue;
      sets.insert({a, b});
      std::set<int> third(t.neighbours[a].begin(), t.neighbours[a].end());
      third.insert(t.neighbours[b].begin(), t.neighbours[b].end());
      for (int c : third) {
        if (c == a || c == b)
          continue;
        std::vector<int> set{a, b, c};
        std::sort(set.begin(), set.end());
        sets.insert(set);
      }
    }
  }
  std::vector<std::vector<int>> ordered(sets.begin(), sets.end());
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const auto& x, const auto& y) { return x.size() < y.size(); });
  return ordered;
}

std::vector<Point> loop_points_of(const Mesh& mesh, const std::vector<HalfedgeHandle>& loop) {
  std::vector<Point> points;
  for (auto h : loop)
    points.push_back(mesh.point(mesh.from_vertex_handle(h)));
  return points;
}

}  // namespace

std::vector<FaceRemoval> all_face_removals(const AnalysedModel& model) {
  static_assert(kMaxRemovedFaces == 3, "connected_face_sets enumerates up to three faces");
  const Topology topology(model);
  std::vector<FaceRemoval> removals;
  for (const auto& faces : connected_face_sets(topology)) {
    const Removal removal = analyse_removal(topology, faces);
    if (!removal.reason.empty())
      continue;
    removals.push_back(
        {faces, combo_of(removal.labels), removal.labels.k, removal.labels.orientation});
  }
  return removals;
}

std::vector<FaceRemoval> listed_face_removals(const AnalysedModel& model) {
  const auto all = all_face_removals(model);
  std::map<std::string, std::vector<std::size_t>> by_combo;
  for (std::size_t i = 0; i < all.size(); ++i)
    by_combo[all[i].combo].push_back(i);
  std::vector<std::size_t> chosen;
  for (std::size_t round = 0; chosen.size() < static_cast<std::size_t>(kMaxFaceRemovalCases);
       ++round) {
    bool any = false;
    for (const auto& [combo, indices] : by_combo) {
      if (round >= indices.size() ||
          chosen.size() >= static_cast<std::size_t>(kMaxFaceRemovalCases))
        continue;
      chosen.push_back(indices[round]);
      any = true;
    }
    if (!any)
      break;
  }
  std::sort(chosen.begin(), chosen.end());
  std::vector<FaceRemoval> listed;
  for (auto i : chosen)
    listed.push_back(all[i]);
  return listed;
}

std::string face_set_name(const std::vector<int>& faces) {
  std::string name;
  for (int f : faces)
    name += (name.empty() ? "" : "-") + std::to_string(f);
  return name;
}

std::optional<std::vector<int>> parse_face_set_name(const std::string& name) {
  std::vector<int> faces;
  std::size_t start = 0;
  while (true) {
    const auto dash = name.find('-', start);
    const std::string part = name.substr(start, dash - start);
    if (part.empty() || part.size() > 9 ||
        !std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; }) ||
        (part.size() > 1 && part[0] == '0'))
      return std::nullopt;
    faces.push_back(std::stoi(part));
    if (faces.size() > 1 && faces[faces.size() - 2] >= faces.back())
      return std::nullopt;
    if (dash == std::string::npos)
      break;
    start = dash + 1;
  }
  if (faces.size() > static_cast<std::size_t>(kMaxRemovedFaces))
    return std::nullopt;
  return faces;
}

Case make_face_removal_case(const AnalysedModel& model, const std::vector<int>& faces,
                            double structure_size_rel_diag) {
  if (!model.regions_are_brep_faces)
    throw std::invalid_argument(model.name + ": face removal needs a B-Rep model");
  const Topology topology(model);
  const std::string what = model.name + ", faces " + face_set_name(faces);
  for (int r : faces) {
    if (r < 0 || r >= topology.regions || topology.border[r].empty())
      throw std::invalid_argument(fmt::format("{}: no face {}", what, r));
  }
  // Each face adjacent to another: with at most 3 faces, the set is connected.
  for (std::size_t i = 0; i < faces.size() && faces.size() > 1; ++i) {
    bool adjacent = false;
    for (std::size_t j = 0; j < faces.size(); ++j)
      adjacent = adjacent || (j != i && topology.neighbours[faces[i]].count(faces[j]));
    if (!adjacent)
      throw std::invalid_argument(what + ": the faces are not adjacent");
  }
  Removal removal = analyse_removal(topology, faces);
  if (!removal.reason.empty())
    throw std::invalid_argument(what + ": " + removal.reason);

  const Mesh& mesh = model.mesh;
  std::vector<int> triangles;
  std::vector<char> removed(mesh.n_faces(), 0);
  for (auto f : mesh.faces()) {
    if (std::find(faces.begin(), faces.end(), region(mesh, f)) != faces.end()) {
      triangles.push_back(f.idx());
      removed[f.idx()] = 1;
    }
  }
  PunchResult punched = punch_faces(mesh, triangles);
  if (punched.removed_faces != triangles)
    throw std::logic_error(what + ": the kept faces are not manifold");

  HoleLabels& labels = removal.labels;
  const auto points = loop_points_of(mesh, removal.loop);
  labels.size = diameter(points);
  if (labels.orientation == Orientation::Inner && labels.k == 2) {
    // The largest distance to the line where the two faces' planes meet.
    const Plane& p = topology.planes[labels.regions[0]].plane;
    const Plane& q = topology.planes[labels.regions[1]].plane;
    const double c = OpenMesh::dot(p.normal, q.normal);
    const double hp = OpenMesh::dot(p.normal, p.point), hq = OpenMesh::dot(q.normal, q.point);
    const Point on_line =
        p.normal * ((hp - hq * c) / (1.0 - c * c)) + q.normal * ((hq - hp * c) / (1.0 - c * c));
    Point axis = OpenMesh::cross(p.normal, q.normal);
    axis /= axis.norm();
    labels.size = 0.0;
    for (const Point& x : points) {
      const Point d = x - on_line;
      labels.size = std::max(labels.size, (d - axis * OpenMesh::dot(d, axis)).norm());
    }
  } else if (labels.orientation == Orientation::Inner && labels.k == 3 &&
             !labels.linearly_dependent_faces) {
    // The distance to the corner where the three faces' planes meet.
    const Plane& a = topology.planes[labels.regions[0]].plane;
    const Plane& b = topology.planes[labels.regions[1]].plane;
    const Plane& c = topology.planes[labels.regions[2]].plane;
    const Point corner = (OpenMesh::cross(b.normal, c.normal) * OpenMesh::dot(a.normal, a.point) +
                          OpenMesh::cross(c.normal, a.normal) * OpenMesh::dot(b.normal, b.point) +
                          OpenMesh::cross(a.normal, b.normal) * OpenMesh::dot(c.normal, c.point)) /
                         OpenMesh::dot(a.normal, OpenMesh::cross(b.normal, c.normal));
    labels.size = 0.0;
    for (const Point& x : points)
      labels.size = std::max(labels.size, (x - corner).norm());
  }
  labels.structure_size = structure_size_rel_diag * model.diagonal;
  const bool closable = labels.orientation == Orientation::Inner && labels.k <= 3 &&
                        !labels.linearly_dependent_faces && labels.size < labels.structure_size;
  labels.expected_decision = closable ? Decision::CloseAutomatically : Decision::Guide;

  Case c;
  c.complete = mesh;
  c.kind = fmt::format("faces_k{}_{}", labels.k,
                       labels.orientation == Orientation::Inner ? "inner" : "outer");
  HoleTruth truth;
  truth.target = "faces";
  truth.removed_faces = punched.removed_faces;
  truth.missing_edges = missing_sharp_edges(mesh, removed, FeatureChainEdges{model.features});
  truth.missing_corners = missing_corners(mesh, removed, model.features);
  truth.labels = std::move(labels);
  c.holes.push_back(std::move(truth));
  c.input = std::move(punched.holed);
  return c;
}

}  // namespace holebench::generators
