#include "generators/punch_targets.h"

#include "core/coplanar_regions.h"
#include "core/geometry.h"
#include "core/planar_regions.h"
#include "core/plane_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <stdexcept>

namespace holebench::generators {

AnalysedModel analyse_model(std::string name, Mesh mesh, const FeatureOptions& options) {
  AnalysedModel model;
  model.name = std::move(name);
  model.features = analyse_features(mesh, options);
  assign_regions(mesh, model.features.segmentation);
  model.diagonal = bounding_box_diagonal(mesh);
  const auto planes = fit_region_planes(mesh);
  model.region_is_planar = planar_regions(planes, 1e-6 * model.diagonal);
  CoplanarRegionsOptions coplanar;
  coplanar.distance = 1e-6 * model.diagonal;
  model.coplanar_group = coplanar_region_groups(mesh, planes, model.region_is_planar, coplanar);
  model.mesh = std::move(mesh);
  return model;
}

namespace {

bool is_apex(const Mesh& mesh, VertexHandle v);
int single_region(const Mesh& mesh, VertexHandle v);

// Graph distance (along edges) from every vertex to the nearest vertex on a sharp edge or
// at an apex.
std::vector<double> distance_to_sharp_edges(const AnalysedModel& model) {
  const Mesh& mesh = model.mesh;
  std::vector<double> distance(mesh.n_vertices(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (auto e : mesh.edges()) {
    if (!model.features.edge_is_sharp[e.idx()])
      continue;
    for (auto v : {e.v0(), e.v1()}) {
      if (distance[v.idx()] == 0.0)
        continue;
      distance[v.idx()] = 0.0;
      queue.push({0.0, v.idx()});
    }
  }
  for (auto v : mesh.vertices()) {
    // Only a curved region comes to a tip; planar regions are skipped cheaply.
    const int id = single_region(mesh, v);
    if (distance[v.idx()] != 0.0 && id != kNoRegion && !model.region_is_planar[id] &&
        is_apex(mesh, v)) {
      distance[v.idx()] = 0.0;
      queue.push({0.0, v.idx()});
    }
  }
  while (!queue.empty()) {
    const auto [d, index] = queue.top();
    queue.pop();
    if (d > distance[index])
      continue;
    const auto v = mesh.vertex_handle(index);
    for (auto h : mesh.voh_range(v)) {
      const auto w = mesh.to_vertex_handle(h);
      const double nd = d + mesh.calc_edge_length(h);
      if (nd < distance[w.idx()]) {
        distance[w.idx()] = nd;
        queue.push({nd, w.idx()});
      }
    }
  }
  return distance;
}

// The region of a vertex whose faces all lie in one region, or kNoRegion.
int single_region(const Mesh& mesh, VertexHandle v) {
  int id = kNoRegion;
  for (auto f : mesh.vf_range(v)) {
    if (id == kNoRegion)
      id = region(mesh, f);
    if (region(mesh, f) != id)
      return kNoRegion;
  }
  return id;
}

// Whether the normals of the faces around `v` spread over more than 90 degrees: a point
// where a smooth region comes to a tip (a cone's apex).
bool is_apex(const Mesh& mesh, VertexHandle v) {
  for (auto f : mesh.vf_range(v)) {
    for (auto g : mesh.vf_range(v)) {
      if (OpenMesh::dot(face_normal(mesh, f), face_normal(mesh, g)) < 0.0)
        return true;
    }
  }
  return false;
}

VertexHandle farthest_interior_vertex(const AnalysedModel& model,
                                      const std::vector<double>& distance, bool planar) {
  VertexHandle best;
  double best_distance = 0.0;
  for (auto v : model.mesh.vertices()) {
    const int id = single_region(model.mesh, v);
    if (id == kNoRegion || static_cast<bool>(model.region_is_planar[id]) != planar)
      continue;
    if (!planar && is_apex(model.mesh, v))
      continue;
    if (std::isfinite(distance[v.idx()]) && distance[v.idx()] > best_distance) {
      best_distance = distance[v.idx()];
      best = v;
    }
  }
  return best;
}

VertexHandle chain_middle(const Mesh& mesh, const SharpEdgeChain& chain) {
  double walked = 0.0;
  for (std::size_t i = 0; i < chain.edges.size(); ++i) {
    walked += mesh.calc_edge_length(chain.edges[i]);
    if (walked >= 0.5 * chain.length)
      return chain.vertices[i + 1];
  }
  return chain.vertices.front();
}

// Whether every face around `v` lies in a planar region. The labels of CASES.md are defined
// for planar faces only, so where a model offers a choice the targets sit between planes:
// their holes then carry labels and classification accuracy is measured on them.
bool planar_around(const AnalysedModel& model, VertexHandle v) {
  for (auto f : model.mesh.vf_range(v)) {
    const int id = region(model.mesh, f);
    if (id == kNoRegion || !model.region_is_planar[id])
      return false;
  }
  return true;
}

bool between_planes(const AnalysedModel& model, const SharpEdgeChain& chain) {
  for (int id : chain.regions) {
    if (id == kNoRegion || !model.region_is_planar[id])
      return false;
  }
  return true;
}

VertexHandle cone_apex(const AnalysedModel& model) {
  const Mesh& mesh = model.mesh;
  for (auto v : mesh.vertices()) {
    const int id = single_region(mesh, v);
    if (id == kNoRegion || model.region_is_planar[id])
      continue;
    if (is_apex(mesh, v))
      return v;
  }
  return VertexHandle();
}

// Two chains that share no end vertex, at their closest approach (a few percent of the
// diagonal at most): the vertex nearest the midpoint of the closest pair.
PunchTarget multi_feature_target(const AnalysedModel& model) {
  const Mesh& mesh = model.mesh;
  const auto& chains = model.features.chains;
  double best = 0.08 * model.diagonal;
  Point midpoint;
  bool found = false;
  for (std::size_t a = 0; a < chains.size(); ++a) {
    for (std::size_t b = a + 1; b < chains.size(); ++b) {
      const std::set<int> ends{chains[a].vertices.front().idx(), chains[a].vertices.back().idx()};
      if (ends.count(chains[b].vertices.front().idx()) ||
          ends.count(chains[b].vertices.back().idx()))
        continue;
      for (auto va : chains[a].vertices) {
        for (auto vb : chains[b].vertices) {
          const double d = (mesh.point(va) - mesh.point(vb)).norm();
          if (d > 0.0 && d < best) {
            best = d;
            midpoint = (mesh.point(va) + mesh.point(vb)) * 0.5;
            found = true;
          }
        }
      }
    }
  }
  if (!found)
    return {};
  VertexHandle nearest;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (auto v : mesh.vertices()) {
    const double d = (mesh.point(v) - midpoint).norm();
    if (d < nearest_distance) {
      nearest_distance = d;
      nearest = v;
    }
  }
  // Large enough to reach both chains from the midpoint.
  return {"multi_feature", nearest, 0.75 * best};
}

}  // namespace

std::vector<PunchTarget> find_punch_targets(const AnalysedModel& model) {
  std::vector<PunchTarget> targets;
  const auto distance = distance_to_sharp_edges(model);
  const VertexHandle planar = farthest_interior_vertex(model, distance, true);
  if (planar.is_valid())
    targets.push_back({"face_interior", planar});

  // Edges: the longest chain of each convexity between two planar regions, else the longest.
  for (Convexity convexity : {Convexity::Convex, Convexity::Reflex}) {
    const SharpEdgeChain* longest = nullptr;
    for (const bool planar_only : {true, false}) {
      for (const auto& chain : model.features.chains) {
        if (chain.convexity != convexity || (planar_only && !between_planes(model, chain)))
          continue;
        if (!longest || chain.length > longest->length)
          longest = &chain;
      }
      if (longest)
        break;
    }
    if (longest) {
      targets.push_back(
          {std::string("edge_") + to_string(convexity), chain_middle(model.mesh, *longest)});
    }
  }

  // Corners: one per signature (in the order the signatures first appear), the first
  // corner of that signature with only planar faces around it, else the first.
  std::vector<std::string> signatures;
  std::map<std::string, VertexHandle> corner_of;
  for (const auto& corner : model.features.corners) {
    const std::string signature = corner.signature();
    const auto it = corner_of.find(signature);
    if (it == corner_of.end()) {
      signatures.push_back(signature);
      corner_of[signature] = corner.vertex;
    } else if (!planar_around(model, it->second) && planar_around(model, corner.vertex)) {
      it->second = corner.vertex;
    }
  }
  for (const auto& signature : signatures)
    targets.push_back({"corner_" + signature, corner_of[signature]});

  const PunchTarget multi = multi_feature_target(model);
  if (multi.vertex.is_valid())
    targets.push_back(multi);
  const VertexHandle curved = farthest_interior_vertex(model, distance, false);
  if (curved.is_valid())
    targets.push_back({"curved_face", curved});
  const VertexHandle apex = cone_apex(model);
  if (apex.is_valid())
    targets.push_back({"cone_apex", apex});
  if (planar.is_valid()) {
    // An island needs room: its inside must keep whole triangles, so the hole spans several
    // edge lengths whatever the size class.
    double length = 0.0;
    for (auto e : model.mesh.edges())
      length += model.mesh.calc_edge_length(e);
    targets.push_back({"island", planar, 8.0 * length / model.mesh.n_edges()});
  }
  return targets;
}

}  // namespace holebench::generators

namespace holebench::generators {

PunchTarget find_gear_tooth_target(const AnalysedModel& model) {
  const Mesh& mesh = model.mesh;
  // The axis: the coordinate axis the faces' normals point along least (area-weighted), the
  // direction of a prism's extrusion; through the bounding box's centre.
  double normal_mass[3] = {0.0, 0.0, 0.0};
  for (const auto f : mesh.faces()) {
    auto v = mesh.cfv_begin(f);
    const Point a = mesh.point(*v), b = mesh.point(*++v), c = mesh.point(*++v);
    const Point n = OpenMesh::cross(b - a, c - a);
    for (int k = 0; k < 3; ++k)
      normal_mass[k] += std::abs(n[k]);
  }
  const int axis = static_cast<int>(std::min_element(normal_mass, normal_mass + 3) - normal_mass);
  const BoundingBox box = bounding_box(mesh);
  const Point centre = box.center();
  const double length = box.max[axis] - box.min[axis];
  PunchTarget target{"gear_tooth", VertexHandle(), 0.0};
  double farthest = -1.0;
  for (const auto v : mesh.vertices()) {
    const Point p = mesh.point(v) - centre;
    if (std::abs(p[axis]) > 0.1 * length)
      continue;  // near the middle of the length only
    Point radial = p;
    radial[axis] = 0.0;
    if (radial.norm() > farthest) {  // the first of equals, by vertex index
      farthest = radial.norm();
      target.vertex = v;
    }
  }
  if (!target.vertex.is_valid())
    throw std::invalid_argument("model '" + model.name + "' has no vertex near its middle");
  return target;
}

}  // namespace holebench::generators
