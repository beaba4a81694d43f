// Test helpers: a hole's labels read off the meshes, independently of any generator. Shared
// by the B-Rep case tests and the punched (procedural and CAD) case tests.
#pragma once

#include "core/boundary_loops.h"
#include "core/case.h"
#include "core/coplanar_regions.h"
#include "core/geometry.h"
#include "core/mesh.h"
#include "core/planar_regions.h"
#include "core/plane_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace holebench::generators::label_geometry {

using Key = std::array<double, 3>;
inline Key key_of(const Point& p) {
  return {p[0], p[1], p[2]};
}

// One visit of a loop to a region: the region and the loop index where the visit starts.
struct Visit {
  int region;
  std::size_t first;
};

// The regions of the faces along the loop, consecutive repeats merged (cyclically).
// `region_of(face)` gives a face's region (by default the mesh's own region ids).
template <typename RegionOf>
std::vector<Visit> visits_along(const Mesh& mesh, const BoundaryLoop& loop, RegionOf region_of) {
  const std::size_t n = loop.size();
  auto region_at = [&](std::size_t i) {
    return region_of(mesh.opposite_face_handle(loop.halfedges[i % n]));
  };
  std::vector<Visit> visits;
  for (std::size_t i = 0; i < n; ++i) {
    if (region_at(i) != region_at(i + n - 1))
      visits.push_back({region_at(i), i});
  }
  if (visits.empty())
    visits.push_back({region_at(0), 0});
  return visits;
}

inline std::vector<Visit> visits_along(const Mesh& mesh, const BoundaryLoop& loop) {
  return visits_along(mesh, loop, [&mesh](FaceHandle f) { return region(mesh, f); });
}

// The rotation r with a[(i + r) % n] == b[i] for all i, or -1.
template <typename T>
int rotation_of(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size())
    return -1;
  for (std::size_t r = 0; r < a.size(); ++r) {
    bool same = true;
    for (std::size_t i = 0; i < a.size() && same; ++i)
      same = a[(i + r) % a.size()] == b[i];
    if (same)
      return static_cast<int>(r);
  }
  return -1;
}

// Signed dihedral sign of an edge of the complete mesh at `vertex` between regions a and b.
inline std::optional<Convexity> convexity_at(const Mesh& complete, VertexHandle vertex, int a,
                                             int b) {
  for (auto h : complete.voh_range(vertex)) {
    const auto e = complete.edge_handle(h);
    if (complete.is_boundary(e))
      continue;
    const int ra = region(complete, complete.face_handle(h));
    const int rb = region(complete, complete.opposite_face_handle(h));
    if ((ra == a && rb == b) || (ra == b && rb == a))
      return signed_dihedral_angle(complete, e) > 0.0 ? Convexity::Convex : Convexity::Reflex;
  }
  return std::nullopt;
}

// Whether the input's region `r` has the loop halfedge `boundary` (a hole halfedge) on its
// outer boundary: walk the region's own boundary (face side) from the halfedge opposite
// `boundary` and take the sign of its area about the region's normal.
inline BoundaryKind boundary_kind(const Mesh& input, HalfedgeHandle boundary, const Point& normal) {
  const int r = region(input, input.opposite_face_handle(boundary));
  auto on_region_boundary = [&](HalfedgeHandle h) {
    if (input.is_boundary(h) || region(input, input.face_handle(h)) != r)
      return false;
    const auto other = input.opposite_face_handle(h);
    return !other.is_valid() || region(input, other) != r;
  };
  const HalfedgeHandle start = input.opposite_halfedge_handle(boundary);
  Point twice_area(0.0, 0.0, 0.0);
  HalfedgeHandle h = start;
  for (std::size_t guard = 0; guard < input.n_halfedges(); ++guard) {
    twice_area += OpenMesh::cross(input.point(input.from_vertex_handle(h)),
                                  input.point(input.to_vertex_handle(h)));
    HalfedgeHandle next;
    for (auto out : input.voh_range(input.to_vertex_handle(h))) {
      if (on_region_boundary(out)) {
        next = out;
        break;
      }
    }
    h = next;
    if (!h.is_valid() || h == start)
      break;
  }
  return OpenMesh::dot(twice_area, normal) > 0.0 ? BoundaryKind::Outer : BoundaryKind::Inner;
}

using VertexOfPoint = std::map<Key, VertexHandle>;

/// The complete mesh's vertices by their exact points (the input keeps those points).
inline VertexOfPoint vertex_of_point(const Mesh& complete) {
  VertexOfPoint vertices;
  for (auto v : complete.vertices())
    vertices[key_of(complete.point(v))] = v;
  return vertices;
}

/// Each transition's convexity from the complete mesh's dihedral angle at the transition
/// vertex, against the labels; `rotation` maps the visits onto the labels' region order.
inline void expect_transitions_match(const Case& c, const BoundaryLoop& loop,
                                     const std::vector<Visit>& visits, int rotation,
                                     const HoleLabels& labels,
                                     const VertexOfPoint& complete_vertex) {
  ASSERT_EQ(labels.transitions.size(), labels.k > 1 ? visits.size() : 0u);
  for (std::size_t t = 0; t < labels.transitions.size(); ++t) {
    const std::size_t from = (t + rotation) % visits.size();
    const std::size_t to = (from + 1) % visits.size();
    const auto h = loop.halfedges[visits[to].first];
    const auto vertex = complete_vertex.at(key_of(c.input.point(c.input.from_vertex_handle(h))));
    const auto convexity = convexity_at(c.complete, vertex, visits[from].region, visits[to].region);
    ASSERT_TRUE(convexity.has_value()) << "no edge between the regions at transition " << t;
    EXPECT_EQ(*convexity, labels.transitions[t]) << "transition " << t;
  }
}

/// Every missing corner is a complete-mesh vertex the input lacks, with every face around
/// it removed (`removed` by complete face index).
inline void expect_missing_corners_removed(const Case& c, const HoleTruth& hole,
                                           const VertexOfPoint& complete_vertex,
                                           const std::vector<char>& removed) {
  std::set<Key> input_points;
  for (auto v : c.input.vertices())
    input_points.insert(key_of(c.input.point(v)));
  for (const Point& corner : hole.missing_corners) {
    ASSERT_TRUE(complete_vertex.count(key_of(corner)));
    EXPECT_FALSE(input_points.count(key_of(corner)));
    for (auto f : c.complete.vf_range(complete_vertex.at(key_of(corner))))
      EXPECT_TRUE(removed[f.idx()]);
  }
}

// The labels of a punched case with one hole and one loop (`loop`, of c.input), read a second
// way off the meshes as the B-Rep cases' are: k and the regions along the loop, each
// transition's convexity from the complete mesh's dihedral angle, the orientation from the
// fitted planes of the loop's regions, and the missing corners.
inline void expect_punched_labels_agree(const Case& punched_case, const BoundaryLoop& loop) {
  // Coplanar regions that meet are one face of the taxonomy (a planar B-Rep face split in
  // two): the complete model's regions are replaced by their coplanar groups.
  Case c = punched_case;
  std::vector<int> group;
  {
    const auto planes = fit_region_planes(c.complete);
    const double flat = 1e-6 * bounding_box_diagonal(c.complete);
    CoplanarRegionsOptions options;
    options.distance = flat;
    group = coplanar_region_groups(c.complete, planes, planar_regions(planes, flat), options);
    for (auto f : c.complete.faces()) {
      if (region(c.complete, f) != kNoRegion)
        set_region(c.complete, f, group[region(c.complete, f)]);
    }
  }
  const HoleLabels& labels = *c.holes[0].labels;
  const VertexOfPoint complete_vertex = vertex_of_point(c.complete);
  std::vector<char> removed(c.complete.n_faces(), 0);
  for (int f : c.holes[0].removed_faces)
    removed[f] = 1;

  // The input carries no region ids (a method segments it itself): each input face takes
  // the region of the complete model's face at the same three points.
  std::map<std::array<Key, 3>, int> region_of_corners;
  const auto corners_of = [](const Mesh& mesh, FaceHandle f) {
    std::array<Key, 3> corners;
    int k = 0;
    for (auto v : mesh.fv_range(f))
      corners[k++] = key_of(mesh.point(v));
    std::sort(corners.begin(), corners.end());
    return corners;
  };
  for (auto f : c.complete.faces())
    region_of_corners[corners_of(c.complete, f)] = region(c.complete, f);
  const auto visits = visits_along(
      c.input, loop, [&](FaceHandle f) { return region_of_corners.at(corners_of(c.input, f)); });
  std::vector<int> regions;
  for (const auto& v : visits)
    regions.push_back(v.region);
  ASSERT_EQ(static_cast<int>(regions.size()), labels.k);
  // The labels may name a face by any region of its coplanar group.
  std::vector<int> label_faces;
  for (int r : labels.regions)
    label_faces.push_back(group.at(r));
  const int rotation = rotation_of(regions, label_faces);
  ASSERT_GE(rotation, 0) << "regions differ up to rotation: " << ::testing::PrintToString(regions)
                         << " vs " << ::testing::PrintToString(label_faces);
  expect_transitions_match(c, loop, visits, rotation, labels, complete_vertex);

  // Inner: every removed face lies in the plane of one of the loop's regions.
  const auto planes = fit_region_planes(c.complete);
  const double tolerance = 1e-6 * bounding_box_diagonal(c.complete);
  bool all_in_planes = true;
  double worst = 0.0;
  for (int f : c.holes[0].removed_faces) {
    double best = std::numeric_limits<double>::infinity();
    for (int r : regions) {
      if (!planes[r].valid)
        continue;
      double farthest = 0.0;
      for (auto v : c.complete.fv_range(c.complete.face_handle(f)))
        farthest =
            std::max(farthest, std::abs(planes[r].plane.signed_distance(c.complete.point(v))));
      best = std::min(best, farthest);
    }
    worst = std::max(worst, best);
    all_in_planes = all_in_planes && best < tolerance;
  }
  SCOPED_TRACE("farthest removed vertex from the loop's planes: " +
               std::to_string(worst / bounding_box_diagonal(c.complete)) + " diag");
  EXPECT_EQ(all_in_planes ? Orientation::Inner : Orientation::Outer, labels.orientation);

  expect_missing_corners_removed(c, c.holes[0], complete_vertex, removed);
}

}  // namespace holebench::generators::label_geometry
