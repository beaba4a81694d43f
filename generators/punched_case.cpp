#include "generators/punched_case.h"
#include "core/portable_math.h"  // the same bits on every machine

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "generators/hole_punch.h"
#include "generators/missing_sharp_edges.h"
#include "generators/random.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace holebench::generators {
namespace {

// A tangent frame at the target, for the angle around the hole.
struct Frame {
  Point normal, u, v;
};

Frame frame_at(const Mesh& mesh, VertexHandle vertex) {
  Point n(0, 0, 0);
  for (auto f : mesh.vf_range(vertex))
    n += face_normal(mesh, f) * face_area(mesh, f);
  n = n.norm() > 0 ? n / n.norm() : Point(0, 0, 1);
  const Point helper = std::abs(n[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0);
  Point u = OpenMesh::cross(n, helper);
  u /= u.norm();
  return {n, u, OpenMesh::cross(n, u)};
}

// The radius in direction `angle`: r (1 + irregularity * w), w in [-1, 1] a sum of two
// harmonics with seeded phases, so that boundaries are not clean discs.
struct IrregularRadius {
  double radius, irregularity, phase3, phase5;
  double at(double angle) const {
    const double w =
        (portable_sin(3.0 * angle + phase3) + 0.5 * portable_sin(5.0 * angle + phase5)) / 1.5;
    return radius * (1.0 + irregularity * w);
  }
};

// Faces whose centroid is in the shape, grown from the target through such faces only.
std::vector<int> select_faces(const Mesh& mesh, VertexHandle target, const Frame& frame,
                              const IrregularRadius& outer, double inner_ratio) {
  const Point centre = mesh.point(target);
  auto inside = [&](FaceHandle f) {
    const Point d = face_centroid(mesh, f) - centre;
    const double angle = portable_atan2(OpenMesh::dot(d, frame.v), OpenMesh::dot(d, frame.u));
    const double r = outer.at(angle);
    const double dist = d.norm();
    return dist <= r && dist >= inner_ratio * r;
  };
  std::vector<char> chosen(mesh.n_faces(), 0);
  std::vector<FaceHandle> stack;
  // Seeds: for a disc the faces at the target; for an annulus every face of the ring
  // reachable from the ones nearest the target.
  if (inner_ratio == 0.0) {
    for (auto f : mesh.vf_range(target))
      stack.push_back(f);
  } else {
    FaceHandle nearest;
    double best = std::numeric_limits<double>::infinity();
    for (auto f : mesh.faces()) {
      if (!inside(f))
        continue;
      const double d = (face_centroid(mesh, f) - centre).norm();
      if (d < best) {
        best = d;
        nearest = f;
      }
    }
    if (nearest.is_valid())
      stack.push_back(nearest);
  }
  for (auto f : stack)
    chosen[f.idx()] = 1;
  while (!stack.empty()) {
    const FaceHandle f = stack.back();
    stack.pop_back();
    for (auto g : mesh.ff_range(f)) {
      if (chosen[g.idx()] || !inside(g))
        continue;
      chosen[g.idx()] = 1;
      stack.push_back(g);
    }
  }
  std::vector<int> faces;
  for (auto f : mesh.faces()) {
    if (chosen[f.idx()])
      faces.push_back(f.idx());
  }
  return faces;
}

// Why a punched hole has no labels, where a smaller hole at the same target may have them.
enum class LabelFailure { None, SeveralLoops, FaceInsideTheHole, Other };

// The labels, where the hole is one loop along planar regions (coplanar regions that meet
// counted as one face: AnalysedModel::taxonomy_face) whose missing part lies in
// those regions (inner by construction); otherwise none, and `why` says which condition failed.
std::optional<HoleLabels> planar_labels(const AnalysedModel& model, const PunchResult& punched,
                                        const HoleTruth& truth, const PunchedCaseOptions& options,
                                        std::string& why, LabelFailure& failure) {
  failure = LabelFailure::Other;
  const auto loops = find_boundary_loops(punched.holed);
  if (loops.size() != 1) {
    why = fmt::format("{} boundary loops", loops.size());
    failure = LabelFailure::SeveralLoops;
    return std::nullopt;
  }
  const Mesh& holed = punched.holed;
  const Mesh& complete = model.mesh;
  HoleLabels labels;
  std::vector<VertexHandle> transition_vertices;
  for (std::size_t i = 0; i < loops[0].size(); ++i) {
    const auto h = loops[0].halfedges[i];
    const int id = model.taxonomy_face(region(holed, holed.opposite_face_handle(h)));
    if (labels.regions.empty() || labels.regions.back() != id) {
      labels.regions.push_back(id);
      transition_vertices.push_back(holed.from_vertex_handle(h));
    }
  }
  // transition_vertices[j] is where run j of the loop starts. If the loop started inside
  // a run, its first and last runs are one: merge them, and the first start is no
  // transition. Otherwise the first start is the transition from the last run to the first.
  const bool started_inside_a_run =
      labels.regions.size() > 1 && labels.regions.front() == labels.regions.back();
  if (started_inside_a_run) {
    labels.regions.pop_back();
    transition_vertices.erase(transition_vertices.begin());
  } else {
    std::rotate(transition_vertices.begin(), transition_vertices.begin() + 1,
                transition_vertices.end());
  }
  // Now transition_vertices[i] is where the loop passes from regions[i] to regions[i + 1].
  labels.k = static_cast<int>(labels.regions.size());
  std::set<int> loop_regions(labels.regions.begin(), labels.regions.end());
  const auto removed_face_on = [&](const auto& region_test) {
    return std::any_of(truth.removed_faces.begin(), truth.removed_faces.end(), [&](int f) {
      return region_test(region(complete, complete.face_handle(f)));
    });
  };
  if (removed_face_on([&](int id) { return !model.region_is_planar[id]; })) {
    why = "a removed face lies on a curved region";
    return std::nullopt;
  }
  if (removed_face_on([&](int id) { return !loop_regions.count(model.taxonomy_face(id)); })) {
    why = "a removed face lies on a region the loop does not cross";
    failure = LabelFailure::FaceInsideTheHole;
    return std::nullopt;
  }
  // Convexity at a transition: the sharp edge of the complete model at the transition
  // vertex between the two regions (that very edge: at a corner other sharp edges meet the
  // vertex too).
  if (labels.k > 1) {
    for (std::size_t i = 0; i < transition_vertices.size(); ++i) {
      const auto v =
          complete.vertex_handle(punched.vertex_to_complete[transition_vertices[i].idx()]);
      const int from = labels.regions[i];
      const int to = labels.regions[(i + 1) % labels.regions.size()];
      std::optional<Convexity> convexity;
      for (auto h : complete.voh_range(v)) {
        const auto e = complete.edge_handle(h);
        if (!model.features.edge_is_sharp[e.idx()] || complete.is_boundary(e))
          continue;
        const int a = model.taxonomy_face(region(complete, complete.face_handle(h)));
        const int b = model.taxonomy_face(region(complete, complete.opposite_face_handle(h)));
        if ((a == from && b == to) || (a == to && b == from))
          convexity = model.features.edge_convexity[e.idx()];
      }
      if (!convexity) {
        why = "no sharp edge between two regions where the loop passes from one to the other";
        return std::nullopt;
      }
      labels.transitions.push_back(*convexity);
    }
  }
  labels.orientation = Orientation::Inner;
  // Size per CASES.md: largest diameter (k = 1), largest distance to the missing edge
  // (k = 2), distance to the missing corner (k = 3).
  const auto loop_points = [&] {
    std::vector<Point> p;
    for (auto v : loop_vertices(holed, loops[0]))
      p.push_back(holed.point(v));
    return p;
  }();
  double size = 0.0;
  if (labels.k == 3 && truth.missing_corners.size() == 1) {
    for (const Point& p : loop_points)
      size = std::max(size, (p - truth.missing_corners[0]).norm());
  } else if (labels.k == 2 && truth.missing_edges.size() == 1) {
    const auto& edge = truth.missing_edges[0];
    const Point a = edge.front(), b = edge.back();
    const Point axis = (b - a) / (b - a).norm();
    for (const Point& p : loop_points) {
      const Point d = p - a;
      size = std::max(size, (d - axis * OpenMesh::dot(d, axis)).norm());
    }
  } else {
    for (const Point& p : loop_points) {
      for (const Point& q : loop_points)
        size = std::max(size, (p - q).norm());
    }
  }
  labels.size = size;
  labels.structure_size = options.structure_size_rel_diag * model.diagonal;
  labels.expected_decision = labels.k <= 3 && size < labels.structure_size
                                 ? Decision::CloseAutomatically
                                 : Decision::Guide;
  failure = LabelFailure::None;
  return labels;
}

// One punch at `radius`: the holed mesh and the hole's ground truth.
struct Punch {
  PunchResult punched;
  HoleTruth truth;
  /// Several boundary loops, a whole face of the model removed, or (shrink_to_target) more
  /// features taken away than the target's kind names (takes_more_than_its_target).
  bool cuts_through = false;
};

// A face-interior hole that takes a sharp edge or a corner away, an edge hole more than its
// edge, a corner hole more than its corner's three edges (on a part thinner than the hole:
// the helical sweep's square section).
bool takes_more_than_its_target(const std::string& kind, const HoleTruth& truth) {
  if (kind == "face_interior")
    return !truth.missing_edges.empty() || !truth.missing_corners.empty();
  if (kind == "edge_convex" || kind == "edge_reflex")
    return truth.missing_edges.size() > 1 || !truth.missing_corners.empty();
  if (kind.rfind("corner_", 0) == 0)
    return truth.missing_edges.size() > 3 || truth.missing_corners.size() > 1;
  return false;
}

Punch punch_at(const AnalysedModel& model, const PunchTarget& target, const Frame& frame,
               const PunchedCaseOptions& options, const IrregularRadius& outer) {
  const Mesh& mesh = model.mesh;
  const double inner_ratio = target.kind == "island" ? options.island_ratio : 0.0;
  Punch punch;
  punch.punched = punch_faces(mesh, select_faces(mesh, target.vertex, frame, outer, inner_ratio));
  HoleTruth& truth = punch.truth;
  truth.target = target.kind;
  truth.removed_faces = punch.punched.removed_faces;
  std::vector<char> removed(mesh.n_faces(), 0);
  for (int f : truth.removed_faces)
    removed[f] = 1;
  truth.missing_edges = missing_sharp_edges(mesh, removed, FeatureChainEdges{model.features});
  truth.missing_corners = missing_corners(mesh, removed, model.features);
  if (target.kind == "island") {
    truth.unlabelled_because = "an island (two boundary loops) is outside the taxonomy";
    return punch;
  }
  LabelFailure failure = LabelFailure::None;
  truth.labels =
      planar_labels(model, punch.punched, truth, options, truth.unlabelled_because, failure);
  punch.cuts_through = failure == LabelFailure::SeveralLoops ||
                       failure == LabelFailure::FaceInsideTheHole ||
                       (options.shrink_to_target && takes_more_than_its_target(target.kind, truth));
  return punch;
}

}  // namespace

Case make_punched_case(const AnalysedModel& model, const PunchTarget& target,
                       const PunchedCaseOptions& options) {
  Random random(options.shape_seed);
  IrregularRadius outer{std::max(options.radius_rel_diag * model.diagonal, target.min_radius),
                        options.irregularity, random.uniform(0.0, 2.0 * M_PI),
                        random.uniform(0.0, 2.0 * M_PI)};
  const Frame frame = frame_at(model.mesh, target.vertex);
  Punch punch = punch_at(model, target, frame, options, outer);
  // A hole that cuts through a thin part (several loops) or takes a whole face away is
  // outside the taxonomy, and with shrink_to_target one that takes more features than its
  // target names is not that target's hole: punched again, smaller, while it stays at least
  // min_radius. The same shape (phases), only the radius changes, so the case is still one
  // id's alone.
  for (int step = 0; step < options.shrink_steps && punch.cuts_through; ++step) {
    const double radius = outer.radius * options.shrink_factor;
    if (radius < target.min_radius)
      break;
    outer.radius = radius;
    Punch smaller = punch_at(model, target, frame, options, outer);
    if (smaller.punched.removed_faces.empty())
      break;
    punch = std::move(smaller);
  }

  Case c;
  c.complete = model.mesh;
  c.kind = target.kind;
  c.holes.push_back(std::move(punch.truth));
  c.input = std::move(punch.punched.holed);
  if (!options.keep_input_regions) {
    for (auto f : c.input.faces())
      set_region(c.input, f, kNoRegion);
  }
  return c;
}

}  // namespace holebench::generators
