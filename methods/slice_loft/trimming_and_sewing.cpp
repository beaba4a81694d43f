// Trimming (4.5) and faceting and sewing (4.6); the triangulation is the methods' shared
// constrained Delaunay (methods/common/planar_polygon_triangulation.h).
#include "methods/slice_loft/trimming_and_sewing.h"

#include "core/polygon_2d.h"
#include "methods/common/planar_polygon_triangulation.h"
#include "methods/slice_loft/developed_disc.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <unordered_map>

namespace holebench::slice_loft {
namespace {

using Vec2 = Point2d;

}  // namespace

namespace {

// The boundary nodes in the order the triangulation numbers them: the portion's boundary,
// then its islands'.
std::vector<const BoundaryNode*> numbered_nodes(const Portion& portion) {
  std::vector<const BoundaryNode*> nodes;
  for (const auto& node : portion.boundary)
    nodes.push_back(&node);
  for (const auto& island : portion.islands) {
    for (const auto& node : island)
      nodes.push_back(&node);
  }
  return nodes;
}

// The triangles' edges that must not become mesh edges as they are, each once: between
// two boundary vertices that the mesh already joins by an edge other than a boundary edge
// of the loops (a facet there would give that edge a third face); and, on the developed
// disc, where a node stands at two points (the two sides of a bridge to an island), an
// edge between two points of the same node, and every edge other than the loops' own
// between two points that three or more triangles join (it would be non-manifold).
// `nodes[k]` is the node of loop point k; points from nodes.size() on are interior points.
std::vector<std::array<int, 2>> chords_to_split(const Mesh& mesh,
                                                const std::vector<const BoundaryNode*>& nodes,
                                                const std::set<std::array<int, 2>>& loop_edges,
                                                const std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(nodes.size());
  // What a point becomes in the mesh: its node, or itself for an interior point.
  auto identity = [&](int k) {
    return k < n ? reinterpret_cast<std::uintptr_t>(nodes[k]) : static_cast<std::uintptr_t>(k);
  };
  auto identity_pair = [&](int a, int b) {
    const std::uintptr_t x = identity(a), y = identity(b);
    return std::make_pair(std::min(x, y), std::max(x, y));
  };
  std::map<std::pair<std::uintptr_t, std::uintptr_t>, int> uses;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k)
      ++uses[identity_pair(t[k], t[(k + 1) % 3])];
  }
  std::vector<std::array<int, 2>> chords;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
      if (loop_edges.count({a, b}))
        continue;
      bool split = identity(a) == identity(b) || uses[identity_pair(a, b)] > 2;
      if (!split && b < n && nodes[a]->vertex.is_valid() && nodes[b]->vertex.is_valid()) {
        const HalfedgeHandle h = mesh.find_halfedge(nodes[a]->vertex, nodes[b]->vertex);
        split = h.is_valid() && !mesh.is_boundary(h) &&
                !mesh.is_boundary(mesh.opposite_halfedge_handle(h));
      }
      const std::array<int, 2> chord{a, b};
      if (split && std::find(chords.begin(), chords.end(), chord) == chords.end())
        chords.push_back(chord);
    }
  }
  return chords;
}

// The loops a patch is trimmed by, in one domain: 2D points, and for each the index of its
// node in numbered_nodes order (the developed disc visits some nodes twice).
struct TrimmingPolygon {
  std::vector<std::vector<Vec2>> loops;
  std::vector<int> node_index;  ///< per point, loops in order
  /// Developed disc only: the surface parameters (u, s) of each point of loops[0].
  std::vector<Vec2> surface_parameters;
};

// The portion's plane (u, w) or the surface's (u, s): each boundary and island node at its
// parameters.
TrimmingPolygon polygon_by_parameters(TrimmingDomain domain, const Portion& portion,
                                      const LoftedPatch& patch) {
  auto parameters = [&](const Point& p) {
    if (domain == TrimmingDomain::PortionPlane)
      return Vec2{patch.u_of(p), patch.w_of(p)};
    const auto [u, s] = patch.parameters(p);
    return Vec2{u, s};
  };
  TrimmingPolygon polygon;
  int index = 0;
  polygon.loops.emplace_back();
  for (const auto& node : portion.boundary) {
    polygon.loops[0].push_back(parameters(node.position));
    polygon.node_index.push_back(index++);
  }
  for (const auto& island : portion.islands) {
    polygon.loops.emplace_back();
    for (const auto& node : island) {
      polygon.loops.back().push_back(parameters(node.position));
      polygon.node_index.push_back(index++);
    }
  }
  return polygon;
}

// The developed disc: one loop, each island joined to the boundary by a bridge (a slit
// from the island's node nearest the loop so far, round the island in its own direction and
// back), developed onto the circle by arc length.
TrimmingPolygon polygon_on_disc(const Portion& portion, const LoftedPatch& patch,
                                double& spacing_scale) {
  const std::vector<const BoundaryNode*> nodes = numbered_nodes(portion);
  std::vector<int> loop;
  for (std::size_t i = 0; i < portion.boundary.size(); ++i)
    loop.push_back(static_cast<int>(i));
  int first = static_cast<int>(portion.boundary.size());
  for (const auto& island : portion.islands) {
    const int n = static_cast<int>(island.size());
    std::size_t at = 0;
    int from = 0;
    double best = 1e300;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      for (int i = 0; i < n; ++i) {
        const double d = (nodes[loop[k]]->position - island[i].position).norm();
        if (d < best) {
          best = d;
          at = k;
          from = i;
        }
      }
    }
    std::vector<int> detour;
    for (int i = 0; i <= n; ++i)
      detour.push_back(first + (from + i) % n);
    detour.push_back(loop[at]);
    loop.insert(loop.begin() + static_cast<long>(at) + 1, detour.begin(), detour.end());
    first += n;
  }
  std::vector<Point> points;
  TrimmingPolygon polygon;
  for (int index : loop) {
    points.push_back(nodes[index]->position);
    const auto [u, s] = patch.parameters(nodes[index]->position);
    polygon.surface_parameters.push_back({u, s});
  }
  const DevelopedDisc disc = develop_onto_disc(points);
  polygon.loops.emplace_back();
  for (const auto& q : disc.points)
    polygon.loops[0].push_back({q[0], q[1]});
  polygon.node_index = loop;
  spacing_scale = disc.spacing_scale;
  return polygon;
}

// The portion's loops in a trimming domain (section 4.5: trimming in the parameter domain).
struct DomainPolygon {
  TrimmingDomain domain;
  TrimmingPolygon polygon;
  double spacing_scale = 1.0;                      // the disc's scale of the spacing
  std::vector<std::array<double, 2>> disc_points;  // developed disc only: loops[0]
};

DomainPolygon domain_polygon(TrimmingDomain domain, const Portion& portion,
                             const LoftedPatch& patch) {
  DomainPolygon result;
  result.domain = domain;
  result.polygon = domain == TrimmingDomain::DevelopedDisc
                       ? polygon_on_disc(portion, patch, result.spacing_scale)
                       : polygon_by_parameters(domain, portion, patch);
  if (domain == TrimmingDomain::DevelopedDisc) {
    for (const Vec2& p : result.polygon.loops[0])
      result.disc_points.push_back({p.x, p.y});
  }
  return result;
}

// The surface point of a point q of the domain.
Point surface_point(const DomainPolygon& domain, const LoftedPatch& patch, Vec2 q) {
  if (domain.domain == TrimmingDomain::PortionPlane)
    return patch.point_over_plane(q.x, q.y);
  if (domain.domain == TrimmingDomain::Surface)
    return patch.evaluate(q.x, q.y);
  // The disc: the boundary's surface parameters interpolated by mean value coordinates.
  const std::vector<double> weights = mean_value_coordinates(domain.disc_points, {q.x, q.y});
  double u = 0.0, s = 0.0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    u += weights[i] * domain.polygon.surface_parameters[i].x;
    s += weights[i] * domain.polygon.surface_parameters[i].y;
  }
  return patch.evaluate(u, s);
}

// Whether p lies inside the hole's boundary (loops[0]), outside the islands' and at least
// `clearance` from every loop.
bool admissible(const std::vector<std::vector<Vec2>>& loops, Vec2 p, double clearance) {
  if (!inside_polygon_2d(loops[0], p))
    return false;
  for (std::size_t k = 1; k < loops.size(); ++k) {
    if (inside_polygon_2d(loops[k], p))
      return false;
  }
  for (const auto& loop : loops) {
    if (distance_to_polygon_2d(loop, p) < clearance)
      return false;
  }
  return true;
}

// The candidate points of the project's `direct` option: the sections' traced points that
// are admissible, none within half a spacing of one taken before. Their domain points are
// returned, their surface points appended to `interior`.
std::vector<Vec2> section_points_inside(const DomainPolygon& domain, const LoftedPatch& patch,
                                        double spacing, double clearance,
                                        std::vector<Point>& interior) {
  std::vector<Vec2> interior_2d;
  for (const auto& section : patch.sections) {
    for (const Point& p : section.traced) {
      const auto [u, s] = domain.domain == TrimmingDomain::PortionPlane
                              ? std::array<double, 2>{patch.u_of(p), patch.w_of(p)}
                              : patch.parameters(p);
      const Vec2 q{u, s};
      if (!admissible(domain.polygon.loops, q, clearance))
        continue;
      bool crowded = false;
      for (const Vec2& r : interior_2d)
        crowded = crowded || std::hypot(q.x - r.x, q.y - r.y) < 0.5 * spacing;
      if (crowded)
        continue;
      interior_2d.push_back(q);
      interior.push_back(p);
    }
  }
  return interior_2d;
}

// The candidate points on a triangular grid of `spacing` over the hole's box in the domain,
// the admissible ones kept. Their domain points are returned, their surface points appended
// to `interior`.
std::vector<Vec2> grid_points_inside(const DomainPolygon& domain, const LoftedPatch& patch,
                                     double spacing, double clearance,
                                     std::vector<Point>& interior) {
  const auto& loops = domain.polygon.loops;
  std::vector<Vec2> interior_2d;
  double u0 = 1e300, u1 = -1e300, w0 = 1e300, w1 = -1e300;
  for (const Vec2& p : loops[0]) {
    u0 = std::min(u0, p.x);
    u1 = std::max(u1, p.x);
    w0 = std::min(w0, p.y);
    w1 = std::max(w1, p.y);
  }
  const double row = spacing * std::sqrt(3.0) / 2.0;
  int r = 0;
  for (double w = w0 + 0.5 * row; w < w1; w += row, ++r) {
    for (double u = u0 + (r % 2 ? 0.5 : 0.25) * spacing; u < u1; u += spacing) {
      if (!admissible(loops, {u, w}, clearance))
        continue;
      interior_2d.push_back({u, w});
      interior.push_back(surface_point(domain, patch, {u, w}));
    }
  }
  return interior_2d;
}

// The point pairs of the loops' own edges, as the triangulation numbers the points.
std::set<std::array<int, 2>> loop_edges_of(const std::vector<std::vector<Vec2>>& loops) {
  std::set<std::array<int, 2>> loop_edges;
  for (std::size_t l = 0, first = 0; l < loops.size(); first += loops[l].size(), ++l) {
    const int size = static_cast<int>(loops[l].size());
    for (int i = 0; i < size; ++i) {
      const int a = static_cast<int>(first) + i, b = static_cast<int>(first) + (i + 1) % size;
      loop_edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return loop_edges;
}

// Faceting: constrained Delaunay triangulation with the boundary edges as constraints. Chords
// the mesh already has get a point at their middle (a Steiner point on the surface), and the
// patch is triangulated again, at most max_chord_splits times. The chords' points are
// appended to `result.interior`, and counted.
PolygonTriangulation2d facets_with_chords_split(const Mesh& mesh, const DomainPolygon& domain,
                                                const LoftedPatch& patch,
                                                const std::vector<const BoundaryNode*>& numbered,
                                                const std::vector<Vec2>& interior_2d,
                                                const TessellationOptions& options,
                                                PatchTessellation& result) {
  const auto& loops = domain.polygon.loops;
  std::vector<std::vector<std::array<double, 2>>> loops_2d;
  std::vector<std::array<double, 2>> all_points;
  for (const auto& loop : loops) {
    loops_2d.emplace_back();
    for (const Vec2& p : loop) {
      loops_2d.back().push_back({p.x, p.y});
      all_points.push_back({p.x, p.y});
    }
  }
  std::vector<std::array<double, 2>> interior_points;
  for (const Vec2& p : interior_2d)
    interior_points.push_back({p.x, p.y});
  PolygonTriangulation2d facets = triangulate_polygon_2d(loops_2d, interior_points);
  std::vector<const BoundaryNode*> nodes;  // per polygon point
  for (int index : domain.polygon.node_index)
    nodes.push_back(numbered[index]);
  const std::set<std::array<int, 2>> loop_edges = loop_edges_of(loops);
  for (int round = 0; facets.ok() && round < options.max_chord_splits; ++round) {
    const auto chords = chords_to_split(mesh, nodes, loop_edges, facets.triangles);
    if (chords.empty())
      break;
    // The points as the triangulation numbers them: the loops', then the kept interior.
    std::vector<std::array<double, 2>> point_2d = all_points;
    std::vector<Point> point_3d;
    for (const auto* node : nodes)
      point_3d.push_back(node->position);
    for (int i : facets.kept_interior) {
      point_2d.push_back(interior_points[i]);
      point_3d.push_back(result.interior[i]);
    }
    for (const auto& [a, b] : chords) {
      const Vec2 middle{0.5 * (point_2d[a][0] + point_2d[b][0]),
                        0.5 * (point_2d[a][1] + point_2d[b][1])};
      interior_points.push_back({middle.x, middle.y});
      result.interior.push_back(options.direct ? (point_3d[a] + point_3d[b]) * 0.5
                                               : surface_point(domain, patch, middle));
      ++result.chords_split;
    }
    facets = triangulate_polygon_2d(loops_2d, interior_points);
  }
  return facets;
}

// Why the faceting failed.
std::string faceting_error(const PolygonTriangulation2d& facets) {
  switch (facets.failure) {
    case TriangulationFailure::None:
      break;
    case TriangulationFailure::ShortLoop:
      return "a boundary with fewer than three points";
    case TriangulationFailure::SharedPoint:
      return "two boundary points share a parameter point";
    case TriangulationFailure::SelfIntersection:
      return "the boundary intersects itself in the parameter domain (" + facets.detail + ")";
    case TriangulationFailure::ForeignPoint:
    case TriangulationFailure::NoTriangle:
      return "no facet inside the trimmed patch";
  }
  return "";
}

PatchTessellation tessellate_in(const Mesh& mesh, TrimmingDomain domain, const Portion& portion,
                                const LoftedPatch& patch, double edge_length,
                                const TessellationOptions& options) {
  PatchTessellation result;
  result.domain = domain;
  if (options.direct && domain == TrimmingDomain::DevelopedDisc) {
    result.failure = TriangulationFailure::SelfIntersection;
    result.error = "the section points cannot be placed on the developed disc";
    return result;
  }
  const DomainPolygon in_domain = domain_polygon(domain, portion, patch);
  const double spacing = options.spacing_edges * edge_length * in_domain.spacing_scale;
  const double clearance = options.clearance * spacing;
  // Trimming: the candidate points inside the hole's and outside the islands' boundaries.
  const std::vector<Vec2> interior_2d =
      options.direct ? section_points_inside(in_domain, patch, spacing, clearance, result.interior)
                     : grid_points_inside(in_domain, patch, spacing, clearance, result.interior);
  const std::vector<const BoundaryNode*> numbered = numbered_nodes(portion);
  const PolygonTriangulation2d facets =
      facets_with_chords_split(mesh, in_domain, patch, numbered, interior_2d, options, result);
  result.failure = facets.failure;
  if (facets.failure != TriangulationFailure::None) {
    result.error = faceting_error(facets);
    return result;
  }
  std::vector<Point> kept;  // interior points the triangulation did not merge
  for (int i : facets.kept_interior)
    kept.push_back(result.interior[i]);
  result.interior = std::move(kept);
  // Triangle indices in numbered_nodes order, then the interior points.
  int polygon_points = 0;
  for (const auto& loop : in_domain.polygon.loops)
    polygon_points += static_cast<int>(loop.size());
  const int node_count = static_cast<int>(numbered.size());
  auto renumber = [&](int k) {
    return k < polygon_points ? in_domain.polygon.node_index[k] : k - polygon_points + node_count;
  };
  const bool flip = signed_area_2d(in_domain.polygon.loops[0]) < 0.0;
  for (auto tri : facets.triangles) {
    if (flip)
      std::swap(tri[1], tri[2]);
    result.triangles.push_back({renumber(tri[0]), renumber(tri[1]), renumber(tri[2])});
  }
  result.ok = true;
  return result;
}

}  // namespace

PatchTessellation tessellate_trimmed_patch(const Mesh& mesh, const Portion& portion,
                                           const LoftedPatch& patch, double edge_length,
                                           const TessellationOptions& options) {
  // The paper trims the surface in its own parameter domain (section 4.5); the project's
  // option trims in the portion's plane first, a projection that is exact for the planar
  // portions most holes consist of. Where the boundary folds over in the first domain, the
  // other is tried.
  const TrimmingDomain first_domain =
      options.plane_first ? TrimmingDomain::PortionPlane : TrimmingDomain::Surface;
  const TrimmingDomain second_domain =
      options.plane_first ? TrimmingDomain::Surface : TrimmingDomain::PortionPlane;
  PatchTessellation first = tessellate_in(mesh, first_domain, portion, patch, edge_length, options);
  if (first.ok || first.failure == TriangulationFailure::ShortLoop)
    return first;
  PatchTessellation second =
      tessellate_in(mesh, second_domain, portion, patch, edge_length, options);
  if (second.ok || !options.developed_disc)
    return second;
  PatchTessellation on_disc =
      tessellate_in(mesh, TrimmingDomain::DevelopedDisc, portion, patch, edge_length, options);
  if (on_disc.ok)
    return on_disc;
  on_disc.error = first.error +
                  (options.plane_first ? "; on the surface too: " : "; in the plane too: ") +
                  second.error + "; on the developed disc too: " + on_disc.error;
  return on_disc;
}

SewingResult sew_patches(Mesh& mesh, const std::vector<Portion>& portions,
                         const std::vector<PatchTessellation>& tessellations,
                         const MissingFeatures& features,
                         const std::vector<HalfedgeHandle>& hole_boundary) {
  SewingResult result;
  std::vector<VertexHandle> new_vertices;
  const Mesh backup = mesh;
  std::unordered_map<int, VertexHandle> feature_vertex;
  for (std::size_t p = 0; p < portions.size(); ++p) {
    const Portion& portion = portions[p];
    const PatchTessellation& facets = tessellations[p];
    std::vector<VertexHandle> handles;
    auto add_node = [&](const BoundaryNode& node) {
      if (node.vertex.is_valid()) {
        handles.push_back(node.vertex);
        return;
      }
      auto [it, inserted] = feature_vertex.try_emplace(node.feature);
      if (inserted) {
        it->second = mesh.add_vertex(features.points[node.feature]);
        new_vertices.push_back(it->second);
        ++result.new_vertices;
      }
      handles.push_back(it->second);
    };
    for (const auto& node : portion.boundary)
      add_node(node);
    for (const auto& island : portion.islands) {
      for (const auto& node : island)
        add_node(node);
    }
    const std::size_t first_interior = handles.size();
    for (const Point& q : facets.interior) {
      handles.push_back(mesh.add_vertex(q));
      new_vertices.push_back(handles.back());
    }
    std::vector<char> used(handles.size(), 0);
    for (const auto& t : facets.triangles) {
      const FaceHandle f = mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
      if (!f.is_valid()) {
        mesh = backup;
        result = SewingResult{};
        result.error = "a facet would make the mesh non-manifold";
        return result;
      }
      used[t[0]] = used[t[1]] = used[t[2]] = 1;
      ++result.new_faces;
    }
    for (std::size_t i = first_interior; i < handles.size(); ++i) {
      if (!used[i]) {  // cannot happen: interior points lie inside the trimmed domain
        mesh = backup;
        result = SewingResult{};
        result.error = "an interior point outside every facet";
        return result;
      }
      ++result.new_vertices;
    }
  }
  // The patch closes the hole: no boundary edge of it is left, and no new vertex lies on a
  // boundary (every missing-feature path is shared by two portions).
  std::size_t open = 0;
  for (auto h : hole_boundary)
    open += mesh.is_boundary(h) ? 1 : 0;
  for (auto v : new_vertices)
    open += mesh.is_boundary(v) ? 1 : 0;
  if (open > 0) {
    mesh = backup;
    result = SewingResult{};
    result.error =
        "the facets leave " + std::to_string(open) + " boundary edge(s) or point(s) open";
    return result;
  }
  result.ok = true;
  return result;
}

}  // namespace holebench::slice_loft
