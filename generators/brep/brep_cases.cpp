#include "generators/brep/brep_cases.h"

#include "core/boundary_loops.h"
#include "core/distances.h"
#include "core/labels_summary.h"
#include "core/polygon.h"
#include "generators/brep/brep_catalogue.h"
#include "generators/brep/brep_hole_loops.h"
#include "generators/brep/polyhedron.h"
#include "generators/hole_punch.h"
#include "generators/missing_sharp_edges.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
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

// ---- labels as text ---------------------------------------------------------------

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
  Point edge_a(0, 0, 0), edge_b(0, 0, 0);
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
  truth.missing_edges = missing_sharp_edges(result.complete, removed, RegionBorderEdges{});
  truth.removed_faces = std::move(punched.removed_faces);
  truth.labels = labels;
  result.holes.push_back(std::move(truth));
  return result;
}

Case make_removal_case(const Recipe& recipe, const RemovalSpec& spec, bool large) {
  const Polyhedron unit = spec.model();
  const bool named_kept = spec.named == NamedFaces::Kept;
  std::vector<char> removed(unit.faces.size(), named_kept ? 1 : 0);
  for (const Point& p : spec.faces)
    removed[face_containing(unit, p)] = named_kept ? 0 : 1;
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
  for (auto& line : missing_sharp_edges(result.complete, removed_mesh, RegionBorderEdges{})) {
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

}  // namespace

std::vector<CaseDescriptor> list_brep_cases() {
  std::vector<CaseDescriptor> descriptors;
  for (const auto& recipe : brep_recipes()) {
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
  for (const auto& recipe : brep_recipes()) {
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
