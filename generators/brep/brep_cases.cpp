#include "generators/brep/brep_cases.h"

#include "core/boundary_loops.h"
#include "core/distances.h"
#include "generators/brep/brep_hole_loops.h"
#include "generators/brep/brep_models.h"
#include "generators/brep/polyhedron.h"
#include "generators/hole_punch.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <variant>

namespace holebench::generators {
namespace {

using namespace brep;

constexpr double kStructureSize = 1.0;  ///< delta_s of every B-Rep case (model units)
constexpr double kBallSpacing = 0.2;    ///< tessellation of the models holes are punched in
/// Tessellation of the whole-face removal models, before they are scaled (unit models are
/// about 10 across).
constexpr double kRemovalSpacing = 0.5;
/// Whole-face removal cases are scaled so that the hole's largest diameter is this many
/// structure sizes.
constexpr double kSmallScale = 0.5;
constexpr double kLargeScale = 2.0;

enum class Target { Face, Edge, Vertex };

/// A hole punched by a ball around a face-interior point, an edge point or a vertex.
struct BallSpec {
  std::function<Polyhedron()> model;
  Point center;
  Target target = Target::Face;
  double small_radius = 0.25;
  double large_radius = 1.5;
};

/// A hole left by removing whole faces (given by a point inside each).
struct RemovalSpec {
  std::function<Polyhedron()> model;
  std::vector<Point> faces;
  bool keep = false;  ///< true: `faces` are kept and every other face is removed
};

struct Recipe {
  std::string stem;  ///< the id without "/small" or "/large"
  std::string kind;
  std::string target;  ///< HoleTruth::target
  std::string combo;   ///< expected label combination (see combo_of); checked on generation
  std::string weak_spot;
  std::string description;
  std::variant<BallSpec, RemovalSpec> spec;
};

// ---- labels as text ---------------------------------------------------------------

const char* name(Convexity c) {
  return c == Convexity::Convex ? "convex" : "reflex";
}
const char* name(BoundaryKind b) {
  return b == BoundaryKind::Inner ? "inner" : "outer";
}

template <typename T>
std::string sorted_join(const std::vector<T>& values) {
  std::vector<std::string> names;
  for (const auto& v : values)
    names.push_back(name(v));
  std::sort(names.begin(), names.end());
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : "-") + n;
  return out;
}

// The combination a recipe claims: "k<k>/<orientation>[/<convexities>][/<kinds>]", with the
// convexities and kinds as sorted multisets; for k = 2 a single word when both transitions
// agree.
std::string combo_of(const HoleLabels& labels) {
  std::string combo =
      fmt::format("k{}/{}", labels.k, labels.orientation == Orientation::Inner ? "inner" : "outer");
  if (labels.k == 2 && labels.transitions[0] == labels.transitions[1])
    combo += std::string("/") + name(labels.transitions[0]);
  else if (labels.k >= 2)
    combo += "/" + sorted_join(labels.transitions);
  if (!labels.boundary_kinds.empty())
    combo += "/" + sorted_join(labels.boundary_kinds);
  return combo;
}

// ---- geometry helpers ---------------------------------------------------------------

bool in_face(const PlanarFace& face, const Point& p) {
  const Point n = face_normal(face);
  if (std::abs(OpenMesh::dot(p - face.outer[0], n)) > 1e-9)
    return false;
  int drop = 0;
  for (int a = 1; a < 3; ++a) {
    if (std::abs(n[a]) > std::abs(n[drop]))
      drop = a;
  }
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  bool in = false;
  for (int l = 0; l < face.loop_count(); ++l) {
    const auto& loop = face.loop(l);
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
      const Point& a = loop[i];
      const Point& b = loop[j];
      if ((a[v] > p[v]) != (b[v] > p[v]) &&
          p[u] < (b[u] - a[u]) * (p[v] - a[v]) / (b[v] - a[v]) + a[u])
        in = !in;
    }
  }
  return in;
}

int face_containing(const Polyhedron& polyhedron, const Point& p) {
  int found = -1;
  for (int f = 0; f < static_cast<int>(polyhedron.faces.size()); ++f) {
    if (!in_face(polyhedron.faces[f], p))
      continue;
    if (found >= 0)
      throw std::logic_error("brep case: a face point lies in two faces");
    found = f;
  }
  if (found < 0)
    throw std::logic_error(fmt::format("brep case: no face at ({}, {}, {})", p[0], p[1], p[2]));
  return found;
}

double diameter(const std::vector<Point>& points) {
  double d = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j)
      d = std::max(d, (points[i] - points[j]).norm());
  }
  return d;
}

// The complete mesh's sharp edges (between two regions) whose faces are both removed,
// chained into polylines.
std::vector<std::vector<Point>> missing_sharp_edges(const Mesh& complete,
                                                    const std::vector<char>& removed) {
  std::map<int, std::vector<int>> adjacency;
  for (auto e : complete.edges()) {
    if (e.is_boundary())
      continue;
    const auto f0 = e.h0().face(), f1 = e.h1().face();
    if (!removed[f0.idx()] || !removed[f1.idx()] || region(complete, f0) == region(complete, f1))
      continue;
    adjacency[e.v0().idx()].push_back(e.v1().idx());
    adjacency[e.v1().idx()].push_back(e.v0().idx());
  }
  std::vector<std::vector<Point>> polylines;
  std::set<std::pair<int, int>> used;
  auto walk = [&](int start, int next) {
    std::vector<Point> line{complete.point(VertexHandle(start))};
    int previous = start, current = next;
    for (;;) {
      used.insert({std::min(previous, current), std::max(previous, current)});
      line.push_back(complete.point(VertexHandle(current)));
      const auto& around = adjacency[current];
      if (around.size() != 2 || current == start)
        break;
      const int following = around[0] == previous ? around[1] : around[0];
      if (used.count({std::min(current, following), std::max(current, following)}))
        break;
      previous = current;
      current = following;
    }
    polylines.push_back(std::move(line));
  };
  for (int pass = 0; pass < 2; ++pass) {  // open chains first, then cycles
    for (const auto& [v, around] : adjacency) {
      if (pass == 0 && around.size() == 2)
        continue;
      for (int w : around) {
        if (!used.count({std::min(v, w), std::max(v, w)}))
          walk(v, w);
      }
    }
  }
  return polylines;
}

// Index of the loop (among `loops`) with a vertex nearest to p.
std::size_t nearest_loop(const std::vector<std::vector<Point>>& loops, const Point& p) {
  std::size_t best = 0;
  double best_distance = HUGE_VAL;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    for (const Point& q : loops[i]) {
      const double d = (q - p).sqrnorm();
      if (d < best_distance) {
        best_distance = d;
        best = i;
      }
    }
  }
  return best;
}

Decision decide(const HoleLabels& labels) {
  const bool closable = labels.orientation == Orientation::Inner && labels.k <= 3 &&
                        !labels.linearly_dependent_faces && labels.size < labels.structure_size;
  return closable ? Decision::CloseAutomatically : Decision::Guide;
}

// Whether the planes of `faces` have no single common point (their normals have rank < 3).
bool linearly_dependent(const PolyhedronTopology& topology, const std::vector<int>& faces) {
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      for (std::size_t l = j + 1; l < faces.size(); ++l) {
        const double det =
            OpenMesh::dot(OpenMesh::cross(topology.normal(faces[i]), topology.normal(faces[j])),
                          topology.normal(faces[l]));
        if (std::abs(det) > 1e-6)
          return false;
      }
    }
  }
  return true;
}

void check_combo(const Recipe& recipe, const HoleLabels& labels) {
  const std::string combo = combo_of(labels);
  if (combo != recipe.combo)
    throw std::logic_error(fmt::format("brep case {}: construction gives {}, recipe claims {}",
                                       recipe.stem, combo, recipe.combo));
}

void check_decision(const Recipe& recipe, const HoleLabels& labels, bool large) {
  if ((labels.size < labels.structure_size) == large)
    throw std::logic_error(fmt::format("brep case {}: size {} is on the wrong side of {}",
                                       recipe.stem, labels.size, labels.structure_size));
}

// ---- the two constructions ------------------------------------------------------------

Case make_ball_case(const Recipe& recipe, const BallSpec& spec, bool large) {
  const Polyhedron polyhedron = spec.model();
  const PolyhedronTopology topology(polyhedron);
  Case result;
  result.complete = tessellate(polyhedron, {kBallSpacing});

  HoleLabels labels;
  HoleTruth truth;
  truth.target = recipe.target;
  Point edge_a, edge_b;
  switch (spec.target) {
    case Target::Face:
      labels.regions = {face_containing(polyhedron, spec.center)};
      break;
    case Target::Edge: {
      // The polygon edge through the centre, seen from its first face.
      bool found = false;
      for (int f = 0; f < static_cast<int>(polyhedron.faces.size()) && !found; ++f) {
        const auto& loop = polyhedron.faces[f].outer;
        for (int i = 0; i < static_cast<int>(loop.size()) && !found; ++i) {
          const LoopEdge edge{f, 0, i};
          const Point a = topology.from(edge), b = topology.to(edge);
          const double t = OpenMesh::dot(spec.center - a, b - a) / (b - a).sqrnorm();
          if (t <= 0.0 || t >= 1.0 || distance_to_line(spec.center, a, b) > 1e-12)
            continue;
          const auto other = topology.twin(edge);
          labels.regions = {f, other->face};
          const Convexity c = topology.convexity(edge);
          labels.transitions = {c, c};
          edge_a = a;
          edge_b = b;
          found = true;
        }
      }
      if (!found)
        throw std::logic_error("brep case: no edge through the centre");
      break;
    }
    case Target::Vertex:
      for (const LoopEdge& edge : topology.edges_around(spec.center)) {
        labels.regions.push_back(edge.face);
        labels.transitions.push_back(topology.convexity(topology.previous(edge)));
      }
      truth.missing_corners.push_back(spec.center);
      break;
  }
  labels.k = static_cast<int>(labels.regions.size());
  labels.orientation = Orientation::Inner;
  labels.structure_size = kStructureSize;
  labels.known_weak_spot = recipe.weak_spot;

  PunchResult punched = punch_faces(
      result.complete,
      faces_in_ball(result.complete, spec.center, large ? spec.large_radius : spec.small_radius));
  result.input = std::move(punched.holed);
  const auto loops = find_boundary_loops(result.input);
  if (loops.size() != 1)
    throw std::logic_error("brep case " + recipe.stem + ": the ball leaves several loops");
  const auto points = loop_points(result.input, loops[0]);
  // CASES.md sizes: largest diameter (k = 1 and k > 3), largest distance to the missing edge
  // (k = 2), largest distance to the missing corner (k = 3).
  labels.size = 0.0;
  for (const Point& p : points) {
    if (labels.k == 2)
      labels.size = std::max(labels.size, distance_to_line(p, edge_a, edge_b));
    else if (labels.k == 3)
      labels.size = std::max(labels.size, (p - spec.center).norm());
  }
  if (labels.k == 1 || labels.k > 3)
    labels.size = diameter(points);
  labels.expected_decision = decide(labels);
  check_combo(recipe, labels);
  if (labels.k <= 3)
    check_decision(recipe, labels, large);

  std::vector<char> removed(result.complete.n_faces(), 0);
  for (int f : punched.removed_faces)
    removed[f] = 1;
  truth.missing_edges = missing_sharp_edges(result.complete, removed);
  truth.removed_faces = std::move(punched.removed_faces);
  truth.labels = labels;
  result.holes.push_back(std::move(truth));
  return result;
}

Case make_removal_case(const Recipe& recipe, const RemovalSpec& spec, bool large) {
  const Polyhedron unit = spec.model();
  std::vector<char> removed(unit.faces.size(), spec.keep ? 1 : 0);
  for (const Point& p : spec.faces)
    removed[face_containing(unit, p)] = spec.keep ? 0 : 1;
  const PolyhedronTopology unit_topology(unit);
  const auto brep_loops = brep_hole_loops(unit_topology, removed);

  // Labels per B-Rep loop; the recipe's combination must be one of them (the first such
  // loop sets the scale).
  std::vector<HoleLabels> all_labels;
  int primary = -1;
  for (const auto& loop : brep_loops) {
    HoleLabels labels;
    labels.k = static_cast<int>(loop.regions.size());
    labels.regions = loop.regions;
    labels.transitions = loop.transitions;
    labels.orientation = Orientation::Outer;
    for (int face_loop : loop.face_loops)
      labels.boundary_kinds.push_back(face_loop == 0 ? BoundaryKind::Outer : BoundaryKind::Inner);
    labels.linearly_dependent_faces =
        labels.k >= 3 && linearly_dependent(unit_topology, loop.regions);
    labels.structure_size = kStructureSize;
    // A loop along two or more inner boundaries is the paper's "multiple inner boundaries"
    // weak spot whatever the recipe; the recipe's own weak spot applies to its other loops
    // unless it is that one.
    const auto inner_kinds =
        std::count(labels.boundary_kinds.begin(), labels.boundary_kinds.end(), BoundaryKind::Inner);
    if (inner_kinds >= 2)
      labels.known_weak_spot = "multiple_inner_boundaries";
    else if (recipe.weak_spot != "multiple_inner_boundaries")
      labels.known_weak_spot = recipe.weak_spot;
    if (primary < 0 && combo_of(labels) == recipe.combo)
      primary = static_cast<int>(all_labels.size());
    all_labels.push_back(std::move(labels));
  }
  if (primary < 0) {
    std::string found;
    for (const auto& labels : all_labels)
      found += " " + combo_of(labels);
    throw std::logic_error(fmt::format("brep case {}: construction gives{}, recipe claims {}",
                                       recipe.stem, found, recipe.combo));
  }
  const double scale =
      (large ? kLargeScale : kSmallScale) * kStructureSize / diameter(brep_loops[primary].points);
  const Polyhedron polyhedron = scaled(unit, scale);
  const PolyhedronTopology topology(polyhedron);

  Case result;
  result.complete = tessellate(polyhedron, {kRemovalSpacing * scale});
  std::vector<int> removed_faces;
  std::vector<char> removed_mesh(result.complete.n_faces(), 0);
  for (auto f : result.complete.faces()) {
    if (removed[region(result.complete, f)]) {
      removed_faces.push_back(f.idx());
      removed_mesh[f.idx()] = 1;
    }
  }
  PunchResult punched = punch_faces(result.complete, removed_faces);
  if (punched.removed_faces != removed_faces)
    throw std::logic_error("brep case " + recipe.stem + ": the kept faces are not manifold");
  result.input = std::move(punched.holed);

  // Holes in the order of the input's boundary loops; each B-Rep loop is matched by its
  // first point.
  const auto loops = find_boundary_loops(result.input);
  if (loops.size() != brep_loops.size())
    throw std::logic_error("brep case " + recipe.stem + ": loop count differs from the B-Rep");
  std::vector<std::vector<Point>> mesh_loop_points;
  for (const auto& loop : loops)
    mesh_loop_points.push_back(loop_points(result.input, loop));
  for (std::size_t i = 0; i < loops.size(); ++i) {
    HoleTruth truth;
    truth.target = recipe.target;
    for (std::size_t j = 0; j < brep_loops.size(); ++j) {
      const Point first = brep_loops[j].points[0] * scale;
      if (std::find(mesh_loop_points[i].begin(), mesh_loop_points[i].end(), first) ==
          mesh_loop_points[i].end())
        continue;
      HoleLabels labels = all_labels[j];
      std::vector<Point> points;
      for (const Point& p : brep_loops[j].points)
        points.push_back(p * scale);
      labels.size = diameter(points);
      labels.expected_decision = decide(labels);
      if (static_cast<int>(j) == primary)
        check_decision(recipe, labels, large);
      else
        truth.target = "secondary_loop";
      truth.labels = labels;
    }
    if (!truth.labels)
      throw std::logic_error("brep case " + recipe.stem + ": unmatched boundary loop");
    result.holes.push_back(std::move(truth));
  }
  // Removed faces, missing edges and corners go to the hole whose loop is nearest.
  for (int f : removed_faces) {
    const Point c = result.complete.calc_face_centroid(FaceHandle(f));
    result.holes[nearest_loop(mesh_loop_points, c)].removed_faces.push_back(f);
  }
  for (auto& line : missing_sharp_edges(result.complete, removed_mesh)) {
    const Point middle = line[line.size() / 2];
    result.holes[nearest_loop(mesh_loop_points, middle)].missing_edges.push_back(std::move(line));
  }
  for (const Point& v : topology.vertices()) {
    std::vector<int> faces;
    bool all_removed = true;
    for (const LoopEdge& edge : topology.edges_around(v)) {
      faces.push_back(edge.face);
      all_removed = all_removed && removed[edge.face];
    }
    if (all_removed && !linearly_dependent(topology, faces))
      result.holes[nearest_loop(mesh_loop_points, v)].missing_corners.push_back(v);
  }
  return result;
}

// ---- the catalogue -------------------------------------------------------------------

Recipe ball(std::string stem, std::string target, std::string combo,
            std::function<Polyhedron()> model, Point center, Target kind, std::string description,
            double small_radius = 0.5, double large_radius = 1.5) {
  Recipe r;
  r.stem = std::move(stem);
  r.target = std::move(target);
  r.combo = std::move(combo);
  r.description = std::move(description);
  r.spec = BallSpec{std::move(model), center, kind, small_radius, large_radius};
  return r;
}

Recipe removal(std::string stem, std::string target, std::string combo,
               std::function<Polyhedron()> model, std::vector<Point> faces, bool keep,
               std::string description) {
  Recipe r;
  r.stem = std::move(stem);
  r.target = std::move(target);
  r.combo = std::move(combo);
  r.description = std::move(description);
  r.spec = RemovalSpec{std::move(model), std::move(faces), keep};
  return r;
}

std::vector<Recipe> make_recipes() {
  std::vector<Recipe> r;
  // Inner holes: a ball around a face point (k = 1), an edge point (k = 2), a vertex (k = 3).
  r.push_back(ball("k1/inner", "face_interior", "k1/inner", make_box_model, {3, 3, 6}, Target::Face,
                   "box, face interior", 0.25, 1.0));
  r.push_back(ball("k2/inner/convex", "edge", "k2/inner/convex", make_box_model, {3.5, 0, 6},
                   Target::Edge, "box, convex edge"));
  r.push_back(ball("k2/inner/reflex", "edge", "k2/inner/reflex", make_corner_notch_model,
                   {5, 5, 7.5}, Target::Edge, "corner notch, reflex edge"));
  r.push_back(ball("k3/inner/convex-convex-convex", "corner", "k3/inner/convex-convex-convex",
                   make_box_model, {6, 6, 6}, Target::Vertex, "box corner"));
  r.push_back(ball("k3/inner/convex-convex-reflex", "corner", "k3/inner/convex-convex-reflex",
                   make_corner_notch_model, {5, 5, 10}, Target::Vertex,
                   "corner notch, outer vertex"));
  r.push_back(ball("k3/inner/convex-reflex-reflex", "corner", "k3/inner/convex-reflex-reflex",
                   make_block_on_plate_model, {3, 3, 2}, Target::Vertex,
                   "block on a plate, foot of a vertical block edge"));
  r.push_back(ball("k3/inner/reflex-reflex-reflex", "corner", "k3/inner/reflex-reflex-reflex",
                   make_corner_notch_model, {5, 5, 5}, Target::Vertex,
                   "corner notch, inner vertex"));

  // Outer holes: whole faces removed.
  r.push_back(removal("k1/outer/outer", "faces", "k1/outer/outer", make_box_model, {{3, 3, 6}},
                      true, "box with only its top face kept"));
  r.push_back(removal("k2/outer/convex/outer-outer", "faces", "k2/outer/convex/outer-outer",
                      make_box_model, {{3, 3, 6}, {3, 0, 3}}, true,
                      "box with only two faces along a convex edge (a ridge) kept"));
  r.push_back(removal("k2/outer/reflex/outer-outer", "faces", "k2/outer/reflex/outer-outer",
                      make_valley_model, {{3, 4, 2}, {3, 2, 4}}, true,
                      "L profile with only the two faces along its reflex edge (a valley) kept"));
  r.push_back(removal("k2/outer/convex/inner-outer", "faces", "k2/outer/convex/inner-outer",
                      make_pocket_model, {{5, 5, 1}, {3, 5, 2}, {7, 5, 2}, {5, 7, 2}}, false,
                      "plate with a pocket: floor and three walls removed"));
  r.push_back(removal("k2/outer/reflex/inner-outer", "faces", "k2/outer/reflex/inner-outer",
                      make_block_on_plate_model, {{5, 5, 6}, {3, 5, 4}, {7, 5, 4}, {5, 7, 4}},
                      false, "block on a plate: top and three walls removed"));
  // k = 3, every face on its outer boundary: the three faces at a vertex kept.
  r.push_back(removal("k3/outer/convex-convex-convex/outer-outer-outer", "faces",
                      "k3/outer/convex-convex-convex/outer-outer-outer", make_box_model,
                      {{3, 3, 6}, {6, 3, 3}, {3, 6, 3}}, true,
                      "box, three faces of a corner kept"));
  r.push_back(removal("k3/outer/convex-convex-reflex/outer-outer-outer", "faces",
                      "k3/outer/convex-convex-reflex/outer-outer-outer", make_corner_notch_model,
                      {{2, 2, 10}, {5, 7, 7}, {7, 5, 7}}, true,
                      "corner notch, the three faces of its outer vertex kept"));
  r.push_back(removal("k3/outer/convex-reflex-reflex/outer-outer-outer", "faces",
                      "k3/outer/convex-reflex-reflex/outer-outer-outer", make_corner_block_model,
                      {{7, 7, 5}, {4, 2, 7}, {2, 4, 7}}, true,
                      "block on a plate's corner, the three faces at its foot kept"));
  r.push_back(removal("k3/outer/reflex-reflex-reflex/outer-outer-outer", "faces",
                      "k3/outer/reflex-reflex-reflex/outer-outer-outer", make_corner_notch_model,
                      {{7, 7, 5}, {5, 7, 7}, {7, 5, 7}}, true,
                      "corner notch, the three faces of its inner vertex kept"));
  // k = 3, one face on its inner boundary: a pocket or a block with two adjacent walls kept.
  r.push_back(removal("k3/outer/convex-convex-convex/inner-outer-outer", "faces",
                      "k3/outer/convex-convex-convex/inner-outer-outer", make_l_pocket_model,
                      {{3, 3, 1}, {2, 4, 2}, {4, 2, 2}, {8, 3, 2}, {3, 8, 2}}, false,
                      "L-shaped pocket: floor and all walls but the two at its convex inner "
                      "corner removed"));
  r.push_back(removal("k3/outer/convex-convex-reflex/inner-outer-outer", "faces",
                      "k3/outer/convex-convex-reflex/inner-outer-outer", make_pocket_model,
                      {{5, 5, 1}, {7, 5, 2}, {5, 7, 2}}, false,
                      "pocket: floor and two adjacent walls removed"));
  r.push_back(removal("k3/outer/convex-reflex-reflex/inner-outer-outer", "faces",
                      "k3/outer/convex-reflex-reflex/inner-outer-outer", make_block_on_plate_model,
                      {{5, 5, 6}, {7, 5, 4}, {5, 7, 4}}, false,
                      "block on a plate: top and two adjacent walls removed"));
  r.push_back(removal("k3/outer/reflex-reflex-reflex/inner-outer-outer", "faces",
                      "k3/outer/reflex-reflex-reflex/inner-outer-outer", make_l_boss_model,
                      {{4, 4, 6}, {2, 4, 4}, {4, 2, 4}, {8, 3, 4}, {3, 8, 4}}, false,
                      "L-shaped block: top and all walls but the two at its reflex inner corner "
                      "removed"));

  // Outer holes on two inner boundaries: a rib standing in a pocket, with a tunnel through it
  // (floor flush with the plate top) or an L-shaped beam from the pocket's front rim into it
  // (top flush with the plate top). The rib keeps its front away from the plate top except
  // along the tunnel floor's / the beam top's edge, so that the two faces meet along one
  // edge only.
  r.push_back(removal("k2/outer/convex/inner-inner", "faces", "k2/outer/convex/inner-inner",
                      make_tunnel_rib_model, {{0.5, 0.5, 3}, {2.5, 4, 2}}, true,
                      "rib in a pocket, tunnel through the rib: only the plate top (its pocket "
                      "rim and the tunnel floor) and the rib front (its mouth) kept"));
  r.push_back(removal(
      "k3/outer/convex-convex-reflex/inner-inner-outer", "faces",
      "k3/outer/convex-convex-reflex/inner-inner-outer", make_tunnel_rib_model,
      {{0.5, 0.5, 3}, {2.5, 4, 2}, {3, 4.5, 4}}, true,
      "rib in a pocket, tunnel through the rib: plate top, rib front and the tunnel's left wall "
      "kept (mouth corner on the tunnel floor)"));
  r.push_back(removal(
      "k3/outer/convex-convex-convex/inner-inner-outer", "faces",
      "k3/outer/convex-convex-convex/inner-inner-outer", make_tunnel_rib_model,
      {{0.5, 0.5, 3}, {2.5, 4, 2}, {5, 4.5, 2.5}}, true,
      "rib in a pocket, tunnel through the rib with a trench in its floor: plate top, rib front "
      "and the trench's left wall kept (the mouth's reflex corner at the trench's edge)"));
  r.push_back(removal("k2/outer/reflex/inner-inner", "faces", "k2/outer/reflex/inner-inner",
                      make_beam_rib_model, {{0.5, 0.5, 3}, {3.5, 4, 2}}, true,
                      "rib in a pocket, beam from the pocket rim into the rib: only the plate "
                      "top (its pocket rim and the beam top) and the rib front kept"));
  r.push_back(removal(
      "k3/outer/convex-reflex-reflex/inner-inner-outer", "faces",
      "k3/outer/convex-reflex-reflex/inner-inner-outer", make_beam_rib_model,
      {{0.5, 0.5, 3}, {3.5, 4, 2}, {4, 2.5, 2.5}}, true,
      "rib in a pocket, beam from the pocket rim into the rib: plate top, rib front and the "
      "beam's left side kept"));
  r.push_back(removal(
      "k3/outer/reflex-reflex-reflex/inner-inner-outer", "faces",
      "k3/outer/reflex-reflex-reflex/inner-inner-outer", make_beam_rib_model,
      {{0.5, 0.5, 3}, {3.5, 4, 2}, {6, 2.5, 3.5}}, true,
      "rib in a pocket, L-shaped beam from the pocket rim into the rib: plate top, rib front and "
      "the face of the beam's raised bar above the beam top kept (reflex corner of the beam's "
      "cross-section)"));

  // Outer holes on three inner boundaries: three thin frames through one corner V, each
  // with a tongue reaching into its window, the tongues meeting at V; each frame crosses the
  // other two planes only in their windows or beyond their borders. The same three faces with
  // the material behind or in front of them give the convex and the reflex signatures.
  r.push_back(removal(
      "k3/outer/convex-convex-convex/inner-inner-inner", "faces",
      "k3/outer/convex-convex-convex/inner-inner-inner",
      [] { return make_corner_frames_model(false); }, {{-2, -2, 0}, {0, -2, -2}, {-2, 0, -2}}, true,
      "three thin frames through a convex corner, each with a tongue into its window, the "
      "tongues meeting at the corner: only the three faces at the corner kept"));
  r.push_back(removal(
      "k3/outer/convex-convex-reflex/inner-inner-inner", "faces",
      "k3/outer/convex-convex-reflex/inner-inner-inner",
      [] { return make_notch_frames_model(false); }, {{-2, -2, 0}, {0, 2, -2}, {2, 0, -2}}, true,
      "three thin frames through a notch's outer corner (an L-shaped tongue and two square "
      "tongues): only the three faces at the corner kept"));
  r.push_back(removal(
      "k3/outer/convex-reflex-reflex/inner-inner-inner", "faces",
      "k3/outer/convex-reflex-reflex/inner-inner-inner",
      [] { return make_notch_frames_model(true); }, {{-2, -2, 0}, {0, 2, -2}, {2, 0, -2}}, true,
      "three thin frames through a notch's corner, the material in front of the faces (an "
      "L-shaped tongue and two square tongues): only the three faces at the corner kept"));
  r.push_back(removal(
      "k3/outer/reflex-reflex-reflex/inner-inner-inner", "faces",
      "k3/outer/reflex-reflex-reflex/inner-inner-inner",
      [] { return make_corner_frames_model(true); }, {{-2, -2, 0}, {0, -2, -2}, {-2, 0, -2}}, true,
      "three thin frames through a reflex corner (the material in front of the faces), each "
      "with a tongue into its window: only the three faces at the corner kept"));

  // Variants.
  r.push_back(removal(
      "weak/multiple-inner-boundaries", "faces", "k2/outer/convex/inner-inner",
      make_tunnel_rib_model,
      {{1.5, 2, 1},
       {5, 1, 2},
       {1, 3, 2},
       {10, 3, 2},
       {1.5, 5, 2},
       {9.5, 5, 2},
       {2.5, 5, 4},
       {2, 4.5, 4},
       {9, 4.5, 4},
       {3, 4.5, 4},
       {5, 4.5, 5},
       {8, 4.5, 4},
       {6.5, 4.5, 2},
       {5, 4.5, 2.5},
       {6.5, 5, 2.5}},
      false,
      "rib in a pocket, tunnel through the rib, as a scan from the front sees it: the pocket, "
      "the tunnel, the trench and the rib's back and sides missing, everything else kept"));
  r.back().weak_spot = "multiple_inner_boundaries";
  r.push_back(removal("k3/linearly-dependent", "faces",
                      "k3/outer/convex-convex-convex/outer-outer-outer",
                      make_triangular_prism_model, {{8, 2, 1}}, false,
                      "triangular prism, one end cap removed: three faces whose planes share no "
                      "point"));
  r.push_back(removal("k4/step-parallel-faces", "faces",
                      "k4/outer/convex-convex-reflex-reflex/outer-outer-outer-outer",
                      make_step_model, {{5, 2, 6}, {5, 5, 4}, {5, 7, 3}}, true,
                      "step: only upper top, riser and lower top kept; the riser is visited "
                      "twice"));
  r.push_back(removal(
      "weak/twisted-face", "faces", "k2/outer/convex-reflex/inner-outer", make_twisted_model,
      {{0.5, 0.5, 3}, {3, 4, 4}, {0, 5, 1}, {10, 5, 1}, {5, 0, 1}, {5, 10, 1}, {5, 5, 0}}, true,
      "plate top twisted around a vertical face: they meet reflex at a block and "
      "convex at a pocket rim on the same line"));
  r.back().weak_spot = "twisted_face";
  for (int sides : {4, 5, 6}) {
    std::string conv;
    for (int i = 0; i < sides; ++i)
      conv += i == 0 ? "convex" : "-convex";
    r.push_back(ball(
        fmt::format("k{}/pyramid-apex", sides), "apex", fmt::format("k{}/inner/{}", sides, conv),
        [sides] { return make_pyramid_model(sides); }, {0, 0, 6}, Target::Vertex,
        fmt::format("apex of a pyramid with {} sides", sides), 0.3, 1.5));
  }
  for (auto& recipe : r) {
    const auto slash = recipe.stem.find('/');
    recipe.kind = recipe.stem.substr(0, slash) + "/" +
                  recipe.stem.substr(slash + 1, recipe.stem.find('/', slash + 1) - slash - 1);
  }
  return r;
}

const std::vector<Recipe>& recipes() {
  static const std::vector<Recipe> all = make_recipes();
  return all;
}

}  // namespace

std::vector<CaseDescriptor> list_brep_cases() {
  std::vector<CaseDescriptor> descriptors;
  for (const auto& recipe : recipes()) {
    for (const char* size : {"small", "large"}) {
      descriptors.push_back(
          {"brep/" + recipe.stem + "/" + size, "brep", recipe.kind,
           fmt::format("{} ({}, {} than the structure size)", recipe.description, recipe.combo,
                       size == std::string("small") ? "smaller" : "larger")});
    }
  }
  return descriptors;
}

Case make_brep_case(const std::string& id) {
  for (const auto& recipe : recipes()) {
    const std::string base = "brep/" + recipe.stem + "/";
    if (id != base + "small" && id != base + "large")
      continue;
    const bool large = id == base + "large";
    Case result = std::visit(
        [&](const auto& spec) {
          using Spec = std::decay_t<decltype(spec)>;
          if constexpr (std::is_same_v<Spec, BallSpec>)
            return make_ball_case(recipe, spec, large);
          else
            return make_removal_case(recipe, spec, large);
        },
        recipe.spec);
    result.id = id;
    result.family = "brep";
    result.kind = recipe.kind;
    return result;
  }
  throw std::invalid_argument("unknown B-Rep case id '" + id + "'");
}

}  // namespace holebench::generators
