#include "methods/brep_guidance/closing_triangulation.h"

#include "core/polygon.h"
#include "methods/common/planar_polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <set>
#include <utility>

namespace holebench::brep_guidance {
namespace {

// An undirected edge between two corners, as a key (existing vertex v: v; new point i: -1 - i).
using EdgeKey = std::pair<int, int>;
EdgeKey edge_key(const PolygonCorner& a, const PolygonCorner& b) {
  auto id = [](const PolygonCorner& c) {
    return c.vertex.is_valid() ? c.vertex.idx() : -1 - c.new_index;
  };
  return std::minmax(id(a), id(b));
}

// A polygon that passes a corner twice (a loop vertex on a rebuilt edge) is two polygons
// touching there: the cycles between repeated corners, as indices into `polygon`. Cycles of
// fewer than three corners (an edge walked there and back) enclose nothing and are dropped.
std::vector<std::vector<int>> split_at_repeated_corners(const std::vector<PolygonCorner>& polygon) {
  std::vector<std::vector<int>> cycles;
  std::vector<int> path;
  auto keep = [&](std::vector<int> cycle) {
    if (cycle.size() >= 3)
      cycles.push_back(std::move(cycle));
  };
  for (int i = 0; i < static_cast<int>(polygon.size()); ++i) {
    const auto again = std::find_if(path.begin(), path.end(),
                                    [&](int j) { return same_corner(polygon[j], polygon[i]); });
    if (again != path.end()) {
      keep(std::vector<int>(again, path.end()));
      path.erase(again + 1, path.end());
      continue;
    }
    path.push_back(i);
  }
  keep(std::move(path));
  return cycles;
}

// Twice the signed area of the triangle (a, b, c) in the plane's (u, v) frame.
double orientation(const std::array<double, 2>& a, const std::array<double, 2>& b,
                   const std::array<double, 2>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

struct PartTriangles {
  std::vector<std::array<int, 3>> triangles;  ///< in the mesh's orientation (against the loop)
  double folded_area = 0.0;  ///< projected area of triangles turned against the polygon
  bool ok = false;
};

// The triangulation of a polygon (a cycle of corners, no corner twice) whose projection onto
// its plane is not simple: every triangulation of the n-gon that uses only its corners, in the
// loop's own order, is a candidate (dynamic programming over the diagonals, as for Liepa's
// minimum-weight triangulation). Forbidden diagonals are never used. Chosen first by the least
// folded area (triangles turned against the polygon's orientation in the plane: none when
// the polygon is simple), then by the least sum of the triangles' aspect (sum of squared
// sides over area), which avoids slivers.
PartTriangles triangulate_in_loop_order(const std::vector<std::array<double, 2>>& points,
                                        const std::function<bool(int, int)>& forbidden) {
  const int n = static_cast<int>(points.size());
  PartTriangles result;
  double area = 0.0;
  for (int i = 0; i < n; ++i)
    area += orientation({0, 0}, points[i], points[(i + 1) % n]);
  const double sign = area < 0.0 ? -1.0 : 1.0;
  struct Cost {
    double folded = std::numeric_limits<double>::infinity();
    double aspect = std::numeric_limits<double>::infinity();
    bool operator<(const Cost& o) const {
      return folded != o.folded ? folded < o.folded : aspect < o.aspect;
    }
  };
  auto triangle_cost = [&](int a, int b, int c) {
    const double signed_area = sign * orientation(points[a], points[b], points[c]);
    auto squared = [&](int i, int j) {
      const double dx = points[i][0] - points[j][0], dy = points[i][1] - points[j][1];
      return dx * dx + dy * dy;
    };
    const double sides = squared(a, b) + squared(b, c) + squared(c, a);
    Cost cost;  // infinite for a degenerate triangle
    if (std::abs(signed_area) <= 1e-12 * sides)
      return cost;
    cost.folded = std::max(0.0, -signed_area) / 2.0;
    cost.aspect = sides / std::max(std::abs(signed_area), 1e-300);
    return cost;
  };
  std::vector<std::vector<Cost>> best(n, std::vector<Cost>(n));
  std::vector<std::vector<int>> apex(n, std::vector<int>(n, -1));
  for (int i = 0; i + 1 < n; ++i)
    best[i][i + 1] = {0.0, 0.0};
  for (int length = 2; length < n; ++length) {
    for (int i = 0; i + length < n; ++i) {
      const int j = i + length;
      if (!(i == 0 && j == n - 1) && forbidden(i, j))
        continue;
      for (int m = i + 1; m < j; ++m) {
        const Cost t = triangle_cost(i, m, j);
        if (!std::isfinite(best[i][m].folded) || !std::isfinite(best[m][j].folded) ||
            !std::isfinite(t.folded))
          continue;
        const Cost total{best[i][m].folded + best[m][j].folded + t.folded,
                         best[i][m].aspect + best[m][j].aspect + t.aspect};
        if (total < best[i][j]) {
          best[i][j] = total;
          apex[i][j] = m;
        }
      }
    }
  }
  if (n < 3 || apex[0][n - 1] < 0)
    return result;
  std::vector<std::pair<int, int>> stack{{0, n - 1}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (j - i < 2)
      continue;
    const int m = apex[i][j];
    result.triangles.push_back({i, j, m});  // against the loop order i -> m -> j
    stack.push_back({i, m});
    stack.push_back({m, j});
  }
  result.folded_area = best[0][n - 1].folded;
  result.ok = true;
  return result;
}

// A plane's unit normal and a frame (u, w) of it, counter-clockwise about the normal.
struct PlaneFrame {
  Point normal, u, w;
};

PlaneFrame frame_of(const Plane& plane) {
  PlaneFrame frame;
  frame.normal = plane.normal / plane.normal.norm();
  const Point helper = std::abs(frame.normal[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0);
  frame.u = OpenMesh::cross(frame.normal, helper);
  frame.u /= frame.u.norm();
  frame.w = OpenMesh::cross(frame.normal, frame.u);
  return frame;
}

// A part to triangulate: a cycle of a planned face's polygon (no corner twice), its corners
// also in the plane's frame.
struct Part {
  int region = -1;
  std::vector<PolygonCorner> corners;
  std::vector<Point> points;
  std::vector<std::array<double, 2>> flat;
  double area = 0.0;  // twice the loop's signed area in the plane's frame
  int size() const { return static_cast<int>(corners.size()); }
};

Part part_of(const PlannedFace& face, const std::vector<int>& cycle, const Plane& plane,
             const PlaneFrame& frame) {
  Part part;
  part.region = face.region;
  for (int index : cycle) {
    part.corners.push_back(face.polygon[index]);
    part.points.push_back(part.corners.back().position);
    const Point d = part.points.back() - plane.point;
    part.flat.push_back({OpenMesh::dot(d, frame.u), OpenMesh::dot(d, frame.w)});
  }
  const int size = part.size();
  for (int i = 0; i < size; ++i)
    part.area += orientation({0, 0}, part.flat[i], part.flat[(i + 1) % size]);
  return part;
}

// The part's triangles as indices into its corners, in the mesh's orientation, with how they
// were found where not by the Delaunay triangulation in the face's plane.
struct PartTriangulation {
  std::vector<std::array<int, 3>> triangles;
  std::string note;
  bool ok = false;
  std::string error;
};

// What a part's triangles may not use: a diagonal that joins a corner to itself, or an edge
// the mesh or another part already has.
struct DiagonalRule {
  const Mesh& mesh;
  const Part& part;
  const std::set<EdgeKey>& used;  // the parts' sides and the diagonals chosen so far

  bool forbidden(int a, int b) const {
    const PolygonCorner &ca = part.corners[a], &cb = part.corners[b];
    if (same_corner(ca, cb) || used.count(edge_key(ca, cb)))
      return true;
    return ca.vertex.is_valid() && cb.vertex.is_valid() &&
           mesh.find_halfedge(ca.vertex, cb.vertex).is_valid();
  }
  // Whether a Delaunay triangulation uses no diagonal the mesh or another part has.
  bool usable(const PolygonTriangulation& triangulation) const {
    const int size = part.size();
    bool usable = triangulation.ok;
    for (const auto& t : triangulation.triangles) {
      for (int e = 0; e < 3 && usable; ++e) {
        const int a = t[e], b = t[(e + 1) % 3];
        if ((a + 1) % size != b && (b + 1) % size != a && forbidden(a, b))
          usable = false;  // a diagonal the mesh or another part already has
      }
    }
    return usable;
  }
};

// Counter-clockwise about the plane's normal; the mesh runs against the loop, which is
// clockwise about the normal unless the part is turned over in its plane (`loop_area`: twice
// the loop's signed area in the plane's frame).
std::vector<std::array<int, 3>> in_mesh_orientation(const PolygonTriangulation& triangulation,
                                                    double loop_area) {
  std::vector<std::array<int, 3>> triangles;
  for (auto t : triangulation.triangles) {
    if (loop_area > 0.0)
      std::swap(t[1], t[2]);
    triangles.push_back(t);
  }
  return triangles;
}

std::string part_name(const Part& part) {
  return "face " + std::to_string(part.region) + " (" + std::to_string(part.size()) + " corners)";
}

// The part's own plane: on a segmented curved face or under noise the part can lie in a plane
// far from its face's fitted plane (nearly edge-on to it), and its projection onto the face's
// plane folds where the projection onto its own does not. Not ok where that does not serve
// either. `reason`: why the face's plane did not serve.
PartTriangulation triangulate_in_own_plane(const Part& part, const DiagonalRule& rule,
                                           const Point& face_normal, const std::string& reason) {
  PartTriangulation result;
  const PlaneFit fit = fit_plane(part.points);
  if (!fit.valid)
    return result;
  const auto in_own_plane = triangulate_planar_polygon(part.points, fit.plane);
  if (!rule.usable(in_own_plane))
    return result;
  // Only the sign counts: Newell's normal points the way the loop runs counter-clockwise.
  result.triangles = in_mesh_orientation(
      in_own_plane, OpenMesh::dot(newell_normal(part.points), fit.plane.normal));
  result.ok = true;
  const double cosine = std::min(1.0, std::abs(OpenMesh::dot(fit.plane.normal, face_normal)) /
                                          std::max(fit.plane.normal.norm(), 1e-300));
  char angle[64];
  std::snprintf(angle, sizeof angle, "%.3g", std::acos(cosine) * 180.0 / std::acos(-1.0));
  result.note = part_name(part) + " triangulated in its own least-squares plane (" + reason +
                " in the face's plane), at " + angle + " degrees to the face's";
  return result;
}

// The part in the loop's order (triangulate_in_loop_order), where the attempt allows it.
// `delaunay`: the Delaunay triangulation in the face's plane, which did not serve; `reason`:
// why.
PartTriangulation triangulate_part_in_loop_order(const Part& part, const DiagonalRule& rule,
                                                 bool loop_order,
                                                 const PolygonTriangulation& delaunay,
                                                 const std::string& reason) {
  PartTriangulation result;
  const PartTriangles fallback =
      loop_order ? triangulate_in_loop_order(part.flat,
                                             [&rule](int a, int b) { return rule.forbidden(a, b); })
                 : PartTriangles{};
  if (!fallback.ok) {
    result.error = part_name(part) + ": " +
                   (delaunay.ok ? std::string("its triangulation would use an edge "
                                              "the mesh already has")
                                : delaunay.error);
    if (loop_order)
      result.error += ", and no triangulation in the loop's order avoids the mesh's edges";
    return result;
  }
  result.triangles = fallback.triangles;
  result.ok = true;
  const double fraction = fallback.folded_area / std::max(std::abs(part.area) / 2.0, 1e-300);
  char folded[64];
  std::snprintf(folded, sizeof folded, "%.3g", fraction);
  result.note = part_name(part) + " triangulated in the loop's order (" + reason +
                "), folded area " + folded + " of the part's";
  return result;
}

// A constrained Delaunay triangulation in the face's plane; where it fails or would use an
// edge the mesh or another part has, as the attempt allows: in the part's own plane, then in
// the loop's order.
PartTriangulation triangulate_part(const Part& part, const DiagonalRule& rule, const Plane& plane,
                                   const Point& face_normal, const ClosingAttempt& attempt) {
  const auto triangulation = triangulate_planar_polygon(part.points, plane);
  if (rule.usable(triangulation))
    return {in_mesh_orientation(triangulation, part.area), "", true, ""};
  const std::string reason = triangulation.ok
                                 ? std::string(
                                       "the Delaunay triangulation used an edge the mesh "
                                       "already has")
                                 : triangulation.error;
  if (attempt.own_plane) {
    PartTriangulation own = triangulate_in_own_plane(part, rule, face_normal, reason);
    if (own.ok)
      return own;
  }
  return triangulate_part_in_loop_order(part, rule, attempt.loop_order, triangulation, reason);
}

}  // namespace

// Every polygon first, the mesh is touched only when all succeeded.
ClosingTriangles triangulate_closing(const Mesh& mesh, const BrepFaces& faces,
                                     const ClosingPlan& plan, const ClosingAttempt& attempt) {
  ClosingTriangles result;
  std::set<EdgeKey> used;  // the parts' sides and the diagonals chosen so far
  for (const auto& face : plan.faces) {
    for (std::size_t i = 0; i < face.polygon.size(); ++i)
      used.insert(edge_key(face.polygon[i], face.polygon[(i + 1) % face.polygon.size()]));
  }
  result.triangles.resize(plan.faces.size());
  for (std::size_t f = 0; f < plan.faces.size(); ++f) {
    const PlannedFace& face = plan.faces[f];
    const Plane& plane = face.plane ? *face.plane : faces.planes[face.region].plane;
    const PlaneFrame frame = frame_of(plane);
    for (const auto& cycle : split_at_repeated_corners(face.polygon)) {
      const Part part = part_of(face, cycle, plane, frame);
      const DiagonalRule rule{mesh, part, used};
      PartTriangulation chosen = triangulate_part(part, rule, plane, frame.normal, attempt);
      if (!chosen.note.empty())
        result.notes.push_back(std::move(chosen.note));
      if (!chosen.ok) {
        result.error = std::move(chosen.error);
        return result;
      }
      for (const auto& t : chosen.triangles) {
        const auto& c = part.corners;
        result.triangles[f].push_back({c[t[0]], c[t[1]], c[t[2]]});
        for (int e = 0; e < 3; ++e)
          used.insert(edge_key(c[t[e]], c[t[(e + 1) % 3]]));
      }
    }
  }
  result.ok = true;
  return result;
}

}  // namespace holebench::brep_guidance
