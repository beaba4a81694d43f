// Trimming (4.5) and faceting and sewing (4.6); the triangulation is the methods' shared
// constrained Delaunay (methods/common/planar_polygon_triangulation.h).
#include "methods/slice_loft/trimming_and_sewing.h"

#include "methods/common/planar_polygon_triangulation.h"

#include <cmath>
#include <unordered_map>

namespace holebench::slice_loft {
namespace {

struct Vec2 {
  double x = 0.0, y = 0.0;
};

bool inside(const std::vector<Vec2>& polygon, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      in = !in;
  }
  return in;
}

double distance_to_loop(const std::vector<Vec2>& loop, Vec2 p) {
  double best = 1e300;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const double dx = loop[i].x - loop[j].x, dy = loop[i].y - loop[j].y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - loop[j].x) * dx + (p.y - loop[j].y) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    best = std::min(best, std::hypot(loop[j].x + t * dx - p.x, loop[j].y + t * dy - p.y));
  }
  return best;
}

double signed_area(const std::vector<Vec2>& loop) {
  double area = 0.0;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
    area += loop[j].x * loop[i].y - loop[i].x * loop[j].y;
  return 0.5 * area;
}

}  // namespace

namespace {

PatchTessellation tessellate_in(TrimmingDomain domain, const Portion& portion,
                                const LoftedPatch& patch, double edge_length,
                                const TessellationOptions& options) {
  PatchTessellation result;
  result.domain = domain;
  // The parameters of a point near the surface in the chosen domain, and the surface point
  // of a parameter pair (section 4.5: trimming in the parameter domain).
  auto parameters = [&](const Point& p) {
    if (domain == TrimmingDomain::PortionPlane)
      return Vec2{patch.u_of(p), patch.w_of(p)};
    const auto [u, s] = patch.parameters(p);
    return Vec2{u, s};
  };
  auto surface_point = [&](Vec2 q) {
    return domain == TrimmingDomain::PortionPlane ? patch.point_over_plane(q.x, q.y)
                                                  : patch.evaluate(q.x, q.y);
  };
  std::vector<std::vector<Vec2>> loops(1);
  for (const auto& node : portion.boundary)
    loops[0].push_back(parameters(node.position));
  for (const auto& island : portion.islands) {
    loops.emplace_back();
    for (const auto& node : island)
      loops.back().push_back(parameters(node.position));
  }
  const double spacing = options.spacing_edges * edge_length;
  const double clearance = options.clearance * spacing;
  auto admissible = [&](Vec2 p) {
    if (!inside(loops[0], p))
      return false;
    for (std::size_t k = 1; k < loops.size(); ++k) {
      if (inside(loops[k], p))
        return false;
    }
    for (const auto& loop : loops) {
      if (distance_to_loop(loop, p) < clearance)
        return false;
    }
    return true;
  };

  // Trimming: the candidate points inside the hole's and outside the islands' boundaries.
  std::vector<Vec2> interior_2d;
  if (options.direct) {
    for (const auto& section : patch.sections) {
      for (const Point& p : section.traced) {
        const Vec2 q = parameters(p);
        if (!admissible(q))
          continue;
        bool crowded = false;
        for (const Vec2& r : interior_2d)
          crowded = crowded || std::hypot(q.x - r.x, q.y - r.y) < 0.5 * spacing;
        if (crowded)
          continue;
        interior_2d.push_back(q);
        result.interior.push_back(p);
      }
    }
  } else {
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
        if (!admissible({u, w}))
          continue;
        interior_2d.push_back({u, w});
        result.interior.push_back(surface_point({u, w}));
      }
    }
  }

  // Faceting: constrained Delaunay triangulation with the boundary edges as constraints.
  std::vector<std::vector<std::array<double, 2>>> loops_2d;
  for (const auto& loop : loops) {
    loops_2d.emplace_back();
    for (const Vec2& p : loop)
      loops_2d.back().push_back({p.x, p.y});
  }
  std::vector<std::array<double, 2>> interior_points;
  for (const Vec2& p : interior_2d)
    interior_points.push_back({p.x, p.y});
  const PolygonTriangulation2d facets = triangulate_polygon_2d(loops_2d, interior_points);
  result.failure = facets.failure;
  switch (facets.failure) {
    case TriangulationFailure::None:
      break;
    case TriangulationFailure::ShortLoop:
      result.error = "a boundary with fewer than three points";
      return result;
    case TriangulationFailure::SharedPoint:
      result.error = "two boundary points share a parameter point";
      return result;
    case TriangulationFailure::SelfIntersection:
      result.error =
          "the boundary intersects itself in the parameter domain (" + facets.detail + ")";
      return result;
    case TriangulationFailure::ForeignPoint:
    case TriangulationFailure::NoTriangle:
      result.error = "no facet inside the trimmed patch";
      return result;
  }
  std::vector<Point> kept;  // interior points the triangulation did not merge
  for (int i : facets.kept_interior)
    kept.push_back(result.interior[i]);
  result.interior = std::move(kept);
  const bool flip = signed_area(loops[0]) < 0.0;
  for (auto tri : facets.triangles) {
    if (flip)
      std::swap(tri[1], tri[2]);
    result.triangles.push_back(tri);
  }
  result.ok = true;
  return result;
}

}  // namespace

PatchTessellation tessellate_trimmed_patch(const Portion& portion, const LoftedPatch& patch,
                                           double edge_length, const TessellationOptions& options) {
  // The portion's plane first: exact for the planar portions most holes consist of. Where the
  // boundary folds over in that plane, on the surface itself.
  PatchTessellation in_plane =
      tessellate_in(TrimmingDomain::PortionPlane, portion, patch, edge_length, options);
  if (in_plane.ok || in_plane.failure == TriangulationFailure::ShortLoop)
    return in_plane;
  PatchTessellation on_surface =
      tessellate_in(TrimmingDomain::Surface, portion, patch, edge_length, options);
  if (on_surface.ok)
    return on_surface;
  on_surface.error = in_plane.error + "; on the surface too: " + on_surface.error;
  return on_surface;
}

SewingResult sew_patches(Mesh& mesh, const std::vector<Portion>& portions,
                         const std::vector<PatchTessellation>& tessellations,
                         const MissingFeatures& features) {
  SewingResult result;
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
    for (const Point& q : facets.interior)
      handles.push_back(mesh.add_vertex(q));
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
  result.ok = true;
  return result;
}

}  // namespace holebench::slice_loft
