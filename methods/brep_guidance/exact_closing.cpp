#include "methods/brep_guidance/exact_closing.h"

#include "core/polygon.h"
#include "methods/common/patch_intersections.h"
#include "methods/common/planar_polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <set>

namespace holebench::brep_guidance {
namespace {

// A polygon to triangulate: its corners as existing vertices or new points.
struct Corner {
  VertexHandle vertex;  // invalid for a new point
  Point position;
  int new_index = -1;  // index into the new points (shared between faces)
};

struct PlannedFace {
  int region;
  std::vector<Corner> polygon;
  std::optional<Plane> plane;  ///< the plane to triangulate in, if not the region's
};

double mean_edge_length(const Mesh& mesh, const Hole& hole) {
  double sum = 0.0;
  for (auto h : hole.halfedges)
    sum += mesh.calc_edge_length(h);
  return sum / static_cast<double>(hole.halfedges.size());
}

// New points strictly between a and b, at about `spacing`.
std::vector<Point> interior_points(const Point& a, const Point& b, double spacing) {
  const int pieces = std::max(1, static_cast<int>(std::round((b - a).norm() / spacing)));
  std::vector<Point> points;
  for (int j = 1; j < pieces; ++j)
    points.push_back(a + (b - a) * (static_cast<double>(j) / pieces));
  return points;
}

double bounding_box_diagonal_of_points(const Mesh& mesh,
                                       const std::vector<VertexHandle>& vertices) {
  Point lo = mesh.point(vertices.front()), hi = lo;
  for (auto v : vertices) {
    lo.minimize(mesh.point(v));
    hi.maximize(mesh.point(v));
  }
  return (hi - lo).norm();
}

bool same_corner(const Corner& a, const Corner& b) {
  return a.vertex.is_valid() ? a.vertex == b.vertex : a.new_index == b.new_index;
}

// An undirected edge between two corners, as a key (existing vertex v: v; new point i: -1 - i).
std::pair<int, int> edge_key(const Corner& a, const Corner& b) {
  auto id = [](const Corner& c) { return c.vertex.is_valid() ? c.vertex.idx() : -1 - c.new_index; };
  return std::minmax(id(a), id(b));
}

// A polygon that passes a corner twice (a loop vertex on a rebuilt edge) is two polygons
// touching there: the cycles between repeated corners, as indices into `polygon`. Cycles of
// fewer than three corners (an edge walked there and back) enclose nothing and are dropped.
std::vector<std::vector<int>> split_at_repeated_corners(const std::vector<Corner>& polygon) {
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

// One attempt at the closing: the plan, or the plan with the changes an attempt asks for.
struct Attempt {
  // Loop vertices that lie on a rebuilt edge (within the lines' tolerance, strictly between
  // its ends) become corners of that edge instead of the new points near them; the part that
  // passes them twice is then split there into polygons that touch.
  bool loop_vertices_on_edges = false;
  // A part whose Delaunay triangulation in its face's plane fails is triangulated in the
  // loop's order (triangulate_in_loop_order); otherwise the attempt fails there.
  bool loop_order = false;
  // A part whose Delaunay triangulation in its face's plane fails is first triangulated by a
  // Delaunay triangulation in its own least-squares plane (the plane of its corners).
  bool own_plane = false;
  // k = 3 only: the face (index into the hole's faces) whose part is at most one loop edge
  // gives its run to a neighbouring face, and the hole is closed as k = 2 on the common line
  // of the other two faces, without the corner S; -1: not used.
  int absorbed_face = -1;
  // The run goes to the previous face (f_{j-1}, whose run it follows) or to the next.
  bool into_previous = true;
  // k >= 2: where the whole loop lies in one plane within its faces' noise (the RMS residual
  // of the loop's least-squares plane at most three times the largest of its faces' planes),
  // it is one part in that plane, closed like a k = 1 hole, without rebuilt edges.
  bool one_plane = false;
};

ClosingResult close_hole(Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                         const Attempt& attempt, bool* applicable = nullptr) {
  const bool loop_vertices_on_edges = attempt.loop_vertices_on_edges;
  const bool loop_order = attempt.loop_order;
  if (applicable != nullptr)
    *applicable = true;
  ClosingResult result;
  const int k = hole.k();
  const double spacing = mean_edge_length(mesh, hole);
  std::vector<Point> new_points;
  std::vector<PlannedFace> planned;
  auto add_new = [&](const Point& p) {
    new_points.push_back(p);
    return Corner{VertexHandle(), p, static_cast<int>(new_points.size()) - 1};
  };
  if (k > 3 || (k == 3 && !hole.S) || (k == 2 && hole.linearly_dependent)) {
    result.error = "only inner holes with k <= 3 and independent planes are closed";
    return result;
  }

  // The loop's vertices in the faces' order; run i starts at transition i.
  std::vector<VertexHandle> loop;
  std::vector<int> run_start;
  for (const auto& run : hole.runs) {
    run_start.push_back(static_cast<int>(loop.size()));
    for (auto h : run)
      loop.push_back(mesh.from_vertex_handle(h));
  }
  const int n = static_cast<int>(loop.size());
  const double exact = 1e-9 * std::max(1.0, bounding_box_diagonal_of_points(mesh, loop));

  if (attempt.one_plane) {
    // The faces' common lines are ill-defined where the loop lies in one plane within their
    // noise (two nearly parallel planes of one segmented face; a face's plane edge-on to the
    // hole): the whole loop is one part in the loop's own plane. Its faces are those of the
    // face with the longest run.
    std::vector<Point> points;
    for (auto v : loop)
      points.push_back(mesh.point(v));
    const PlaneFit fit = fit_plane(points);
    double noise = 0.0;
    for (int face : hole.faces)
      noise = std::max(noise, faces.planes[face].plane.rms_residual);
    if (k < 2 || !fit.valid || fit.plane.rms_residual > 3.0 * noise) {
      if (applicable != nullptr)
        *applicable = false;
      result.error = "not applicable";
      return result;
    }
    int longest = 0;
    double longest_length = -1.0;
    for (int i = 0; i < k; ++i) {
      double length = 0.0;
      for (auto h : hole.runs[i])
        length += mesh.calc_edge_length(h);
      if (length > longest_length) {
        longest_length = length;
        longest = i;
      }
    }
    char residuals[96];
    std::snprintf(residuals, sizeof residuals, "%.3g of its faces' %.3g", fit.plane.rms_residual,
                  noise);
    result.note = "the loop closed as one part in its own least-squares plane (RMS residual " +
                  std::string(residuals) + "), its faces those of face " +
                  std::to_string(hole.faces[longest]);
    PlannedFace face{hole.faces[longest], {}, fit.plane};
    for (auto v : loop)
      face.polygon.push_back({v, mesh.point(v)});
    planned.push_back(std::move(face));
  } else if (k == 1) {
    PlannedFace face{hole.faces[0], {}, std::nullopt};
    for (auto v : loop)
      face.polygon.push_back({v, mesh.point(v)});
    planned.push_back(std::move(face));
  } else {
    // L_i: the line where the fitted planes of f_{i-1} and f_i meet, the paper's rebuilt
    // edge. A loop vertex counts as lying on it within the planes' noise (three times their
    // RMS residual, at most a quarter of the hole's mean edge length, at least 1e-9 of the
    // hole's extent).
    struct Line {
      Point point, direction;
      Point project(const Point& p) const {
        return point + direction * OpenMesh::dot(p - point, direction);
      }
    };
    std::vector<Line> lines(k);
    std::vector<double> tolerance(k);
    for (int i = 0; i < k; ++i) {
      const Plane& a = faces.planes[hole.faces[(i + k - 1) % k]].plane;
      const Plane& b = faces.planes[hole.faces[i]].plane;
      Point direction = OpenMesh::cross(a.normal, b.normal);
      direction /= direction.norm();
      // The point of both planes nearest T_i (the minimum-norm solution of the two plane
      // equations, relative to T_i).
      const Point T = hole.transitions[i].position;
      const double da = -a.signed_distance(T), db = -b.signed_distance(T);
      const double c = OpenMesh::dot(a.normal, b.normal);
      const double det = 1.0 - c * c;
      const double alpha = (da - c * db) / det, beta = (db - c * da) / det;
      lines[i] = {T + a.normal * alpha + b.normal * beta, direction};
      const double noise = 3.0 * std::max(a.rms_residual, b.rms_residual);
      tolerance[i] = std::max(exact, std::min(noise, 0.25 * spacing));
    }
    auto on_line = [&](VertexHandle v, int i) {
      const Point& p = mesh.point(v);
      return (p - lines[i].project(p)).norm() <= tolerance[i];
    };
    // Where a hole runs along the faces' common line for a while (one face's triangles are
    // kept there, the other's removed), those edges still exist: the rebuilt edge starts
    // where the loop leaves the line. E_i is that vertex, found from T_i forward through
    // run i or else backward through run i-1; the loop between E_i and E_{i+1} is then the
    // part face f_i extends.
    std::vector<int> split(k);
    for (int i = 0; i < k; ++i) {
      const int index = run_start[i];
      const int run_end = i + 1 < k ? run_start[i + 1] : n;
      int forward = index;
      while (forward + 1 < run_end && on_line(loop[forward + 1], i))
        ++forward;
      if (forward != index) {
        split[i] = forward;
        continue;
      }
      const int previous_start = run_start[(i + k - 1) % k];
      int backward = index;
      while (backward != previous_start && on_line(loop[(backward + n - 1) % n], i))
        backward = (backward + n - 1) % n;
      split[i] = backward;
    }
    // A face whose part is at most one loop edge (E_j to E_{j+1}) barely borders the hole:
    // where the three planes' corner S lies beyond that edge, outside the hole, the plan's
    // rebuilt edges run out to S and back and cross the mesh there. The absorbing attempt
    // gives that run to a neighbouring face and closes the hole as k = 2 on the common line
    // of the other two faces (L_b, the line of faces a = j + 1 and b = j + 2), without S:
    // E_b and, on the run's other side, E_{j+1} (into the previous face b) or E_j (into the
    // next face a) are the rebuilt edge's ends.
    int parts = k;
    std::vector<int> part_faces = hole.faces;
    if (attempt.absorbed_face >= 0) {
      const int j = attempt.absorbed_face, a = (j + 1) % k, b = (j + 2) % k;
      const int run_edges = (split[a] - split[j] + n) % n;
      if (k != 3 || run_edges > 1 || (!attempt.into_previous && run_edges == 0)) {
        if (applicable != nullptr)
          *applicable = false;
        result.error = "not applicable";
        return result;
      }
      const int receiver = attempt.into_previous ? b : a;
      result.note = "face " + std::to_string(hole.faces[j]) + "'s run of " +
                    std::to_string(run_edges) + (run_edges == 1 ? " edge" : " edges") +
                    " given to face " + std::to_string(hole.faces[receiver]) +
                    ", closed as k = 2 on the common line of faces " +
                    std::to_string(hole.faces[a]) + " and " + std::to_string(hole.faces[b]) +
                    " without the corner S";
      split = {attempt.into_previous ? split[a] : split[j], split[b]};
      lines = {lines[b], lines[b]};
      tolerance = {tolerance[b], tolerance[b]};
      part_faces = {hole.faces[a], hole.faces[b]};
      parts = 2;
    }
    // Q_i: E_i projected onto L_i. The rebuilt edge runs on L_i from Q_i on; its end corner
    // is E_i itself, which is input and stays where it is (on L_i on clean input; off it by
    // the noise otherwise). A new end vertex at Q_i would need a short edge E_i -> Q_i that
    // crosses the rebuilt edge's side whenever noise puts E_i beyond the line, so it is not
    // made.
    std::vector<Corner> q(parts);
    for (int i = 0; i < parts; ++i)
      q[i] = {loop[split[i]], lines[i].project(mesh.point(loop[split[i]]))};
    // The rebuilt edges' inner points, shared by the two faces along each.
    std::vector<std::vector<Corner>> edge_points(parts);  // from Q_i towards the common end
    // The corners strictly between `from` and `to` on L_i: new points at about `spacing`,
    // and (loop_vertices_on_edges) the loop vertices on the segment, without the new points
    // within half a spacing of them.
    auto edge_corners = [&](int i, const Point& from, const Point& to,
                            const std::vector<VertexHandle>& ends) {
      std::vector<std::pair<double, Corner>> on_edge;  // by distance from `from`
      const double length = (to - from).norm();
      if (loop_vertices_on_edges && length > 0.0) {
        const Point along = (to - from) / length;
        for (auto v : loop) {
          if (std::find(ends.begin(), ends.end(), v) != ends.end() || !on_line(v, i))
            continue;
          const double t = OpenMesh::dot(mesh.point(v) - from, along);
          if (t > 0.25 * spacing && t < length - 0.25 * spacing)
            on_edge.push_back({t, Corner{v, mesh.point(v)}});
        }
      }
      std::vector<std::pair<double, Point>> fresh;
      for (const Point& p : interior_points(from, to, spacing)) {
        const double t = (p - from).norm();
        if (std::none_of(on_edge.begin(), on_edge.end(),
                         [&](const auto& e) { return std::abs(e.first - t) < 0.5 * spacing; }))
          fresh.push_back({t, p});
      }
      for (const auto& [t, p] : fresh)
        on_edge.push_back({t, add_new(p)});
      std::stable_sort(on_edge.begin(), on_edge.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
      std::vector<Corner> corners;
      for (const auto& e : on_edge)
        corners.push_back(e.second);
      return corners;
    };
    std::vector<VertexHandle> ends;  // the E_i: never corners inside a rebuilt edge
    for (int i = 0; i < parts; ++i)
      ends.push_back(loop[split[i]]);
    Corner vs;
    if (parts == 3) {
      // v_s is a new vertex at S, unless the loop already passes through the corner (a face
      // whose run lies on its two common lines): then that vertex is v_s.
      const double near = std::min({tolerance[0], tolerance[1], tolerance[2]});
      VertexHandle corner;
      for (auto v : loop) {
        if ((mesh.point(v) - *hole.S).norm() <= near)
          corner = v;
      }
      vs = corner.is_valid() ? Corner{corner, mesh.point(corner)} : add_new(*hole.S);
      if (corner.is_valid())
        ends.push_back(corner);
      for (int i = 0; i < 3; ++i) {
        // Q_i and S both lie on L_i: the points between them do too.
        edge_points[i] = edge_corners(i, q[i].position, *hole.S, ends);
      }
    } else {
      edge_points[1] = edge_corners(1, q[1].position, q[0].position, ends);  // Q_2 to Q_1
    }
    for (int i = 0; i < parts; ++i) {
      const int next = (i + 1) % parts;
      PlannedFace face{part_faces[i], {}, std::nullopt};
      // The loop from E_i to E_{i+1}, both included.
      for (int j = split[i];; j = (j + 1) % n) {
        face.polygon.push_back({loop[j], mesh.point(loop[j])});
        if (j == split[next])
          break;
      }
      if (parts == 3) {
        face.polygon.insert(face.polygon.end(), edge_points[next].begin(), edge_points[next].end());
        face.polygon.push_back(vs);
        face.polygon.insert(face.polygon.end(), edge_points[i].rbegin(), edge_points[i].rend());
      } else if (i == 0) {
        face.polygon.insert(face.polygon.end(), edge_points[1].begin(),
                            edge_points[1].end());  // Q_2 -> Q_1
      } else {
        face.polygon.insert(face.polygon.end(), edge_points[1].rbegin(),
                            edge_points[1].rend());  // Q_1 -> Q_2
      }
      // A corner met twice in a row (E_i = E_{i+1}, or v_s on the loop) is one corner.
      std::vector<Corner> corners;
      for (const Corner& c : face.polygon) {
        if (corners.empty() || !same_corner(corners.back(), c))
          corners.push_back(c);
      }
      while (corners.size() > 1 && same_corner(corners.back(), corners.front()))
        corners.pop_back();
      face.polygon = std::move(corners);
      // At most two corners: the part is at most an edge (on the common line, or E_i -> v_s
      // when E_i = E_{i+1}), which the neighbouring faces' parts close; nothing to fill.
      if (face.polygon.size() <= 2)
        continue;
      planned.push_back(std::move(face));
    }
  }

  // Triangulate every face polygon first; touch the mesh only when all succeeded. A polygon
  // that passes a corner twice is split there. Each polygon is triangulated by a constrained
  // Delaunay triangulation in its face's plane; where its projection is not simple, or that
  // triangulation would use an edge the mesh or another part already has (an edge of three
  // faces), by the triangulation in the loop's own order (triangulate_in_loop_order).
  std::set<std::pair<int, int>> used;  // the parts' sides and the diagonals chosen so far
  for (const auto& face : planned) {
    for (std::size_t i = 0; i < face.polygon.size(); ++i)
      used.insert(edge_key(face.polygon[i], face.polygon[(i + 1) % face.polygon.size()]));
  }
  std::vector<std::vector<std::array<Corner, 3>>> triangles(planned.size());
  for (std::size_t f = 0; f < planned.size(); ++f) {
    const Plane& plane =
        planned[f].plane ? *planned[f].plane : faces.planes[planned[f].region].plane;
    const Point normal = plane.normal / plane.normal.norm();
    const Point helper = std::abs(normal[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0);
    Point u = OpenMesh::cross(normal, helper);
    u /= u.norm();
    const Point w = OpenMesh::cross(normal, u);  // (u, w) counter-clockwise about the normal
    for (const auto& cycle : split_at_repeated_corners(planned[f].polygon)) {
      std::vector<Corner> corners;
      std::vector<Point> points;
      std::vector<std::array<double, 2>> flat;
      double area = 0.0;
      for (int index : cycle) {
        corners.push_back(planned[f].polygon[index]);
        points.push_back(corners.back().position);
        const Point d = points.back() - plane.point;
        flat.push_back({OpenMesh::dot(d, u), OpenMesh::dot(d, w)});
      }
      const int size = static_cast<int>(corners.size());
      for (int i = 0; i < size; ++i)
        area += orientation({0, 0}, flat[i], flat[(i + 1) % size]);
      auto forbidden = [&](int a, int b) {
        const Corner &ca = corners[a], &cb = corners[b];
        if (same_corner(ca, cb) || used.count(edge_key(ca, cb)))
          return true;
        return ca.vertex.is_valid() && cb.vertex.is_valid() &&
               mesh.find_halfedge(ca.vertex, cb.vertex).is_valid();
      };
      std::vector<std::array<int, 3>> chosen;
      // Whether a Delaunay triangulation uses no diagonal the mesh or another part has.
      auto usable_in = [&](const PolygonTriangulation& triangulation) {
        bool usable = triangulation.ok;
        for (const auto& t : triangulation.triangles) {
          for (int e = 0; e < 3 && usable; ++e) {
            const int a = t[e], b = t[(e + 1) % 3];
            if ((a + 1) % size != b && (b + 1) % size != a && forbidden(a, b))
              usable = false;  // a diagonal the mesh or another part already has
          }
        }
        return usable;
      };
      // Counter-clockwise about the plane's normal; the mesh runs against the loop, which is
      // clockwise about the normal unless the part is turned over in its plane (`loop_area`:
      // twice the loop's signed area in the plane's frame).
      auto take = [&](const PolygonTriangulation& triangulation, double loop_area) {
        for (auto t : triangulation.triangles) {
          if (loop_area > 0.0)
            std::swap(t[1], t[2]);
          chosen.push_back(t);
        }
      };
      const auto triangulation = triangulate_planar_polygon(points, plane);
      const bool usable = usable_in(triangulation);
      const std::string reason = triangulation.ok
                                     ? std::string(
                                           "the Delaunay triangulation used an edge the mesh "
                                           "already has")
                                     : triangulation.error;
      bool own = false;
      if (!usable && attempt.own_plane) {
        // The part's own plane: on a segmented curved face or under noise the part can lie
        // in a plane far from its face's fitted plane (nearly edge-on to it), and its
        // projection onto the face's plane folds where the projection onto its own does not.
        const PlaneFit fit = fit_plane(points);
        if (fit.valid) {
          const auto in_own_plane = triangulate_planar_polygon(points, fit.plane);
          if (usable_in(in_own_plane)) {
            // Only the sign counts: Newell's normal points the way the loop runs counter-clockwise.
            take(in_own_plane, OpenMesh::dot(newell_normal(points), fit.plane.normal));
            own = true;
            const double cosine = std::min(1.0, std::abs(OpenMesh::dot(fit.plane.normal, normal)) /
                                                    std::max(fit.plane.normal.norm(), 1e-300));
            char angle[64];
            std::snprintf(angle, sizeof angle, "%.3g", std::acos(cosine) * 180.0 / std::acos(-1.0));
            if (!result.note.empty())
              result.note += "; ";
            result.note += "face " + std::to_string(planned[f].region) + " (" +
                           std::to_string(size) +
                           " corners) triangulated in its own "
                           "least-squares plane (" +
                           reason + " in the face's plane), at " + angle + " degrees to the face's";
          }
        }
      }
      if (usable) {
        take(triangulation, area);
      } else if (!own) {
        const PartTriangles fallback =
            loop_order ? triangulate_in_loop_order(flat, forbidden) : PartTriangles{};
        if (!fallback.ok) {
          result.error = "face " + std::to_string(planned[f].region) + " (" + std::to_string(size) +
                         " corners): " +
                         (triangulation.ok ? std::string("its triangulation would use an edge "
                                                         "the mesh already has")
                                           : triangulation.error);
          if (loop_order)
            result.error += ", and no triangulation in the loop's order avoids the mesh's edges";
          return result;
        }
        chosen = fallback.triangles;
        const double fraction = fallback.folded_area / std::max(std::abs(area) / 2.0, 1e-300);
        char folded[64];
        std::snprintf(folded, sizeof folded, "%.3g", fraction);
        if (!result.note.empty())
          result.note += "; ";
        result.note += "face " + std::to_string(planned[f].region) + " (" + std::to_string(size) +
                       " corners) triangulated in the loop's order (" + reason + "), folded area " +
                       folded + " of the part's";
      }
      for (const auto& t : chosen) {
        triangles[f].push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
        for (int e = 0; e < 3; ++e)
          used.insert(edge_key(corners[t[e]], corners[t[(e + 1) % 3]]));
      }
    }
  }

  const Mesh backup = mesh;
  std::vector<VertexHandle> new_vertices;
  std::vector<FaceHandle> added_faces;
  for (const Point& p : new_points)
    new_vertices.push_back(mesh.add_vertex(p));
  for (std::size_t f = 0; f < planned.size(); ++f) {
    auto handle = [&](const Corner& c) {
      return c.vertex.is_valid() ? c.vertex : new_vertices[c.new_index];
    };
    for (const auto& t : triangles[f]) {
      const FaceHandle added = mesh.add_face(handle(t[0]), handle(t[1]), handle(t[2]));
      if (!added.is_valid()) {
        mesh = backup;
        result.error = "a closing triangle would make the mesh non-manifold";
        return result;
      }
      set_region(mesh, added, planned[f].region);
      added_faces.push_back(added);
      ++result.new_faces;
    }
  }
  // A part split at the loop's vertices, triangulated in the loop's order or turned over in
  // its plane need not be embedded: the closing is kept only if it intersects neither itself
  // nor the mesh around it.
  if (const std::size_t pairs = patch_intersections(mesh, added_faces); pairs > 0) {
    mesh = backup;
    result.error = "the closing would intersect itself or the mesh around it (" +
                   std::to_string(pairs) + " face pairs)";
    result.new_faces = 0;
    return result;
  }
  result.new_vertices = new_points.size();
  result.closed = true;
  return result;
}

}  // namespace

ClosingResult close_hole_exactly(Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                                 bool later_attempts) {
  // First as planned; then with the loop's vertices on the rebuilt edges as its corners (the
  // loop touches the faces' common line between the edge's ends); then with parts whose
  // projection is not simple triangulated in the loop's order; then with such parts first
  // triangulated in their own least-squares planes; then (k = 3) with a face whose part is at
  // most one loop edge given to a neighbour and the hole closed as k = 2 without S; then
  // (k >= 2) the loop as one part in its own plane, where it lies in one within its faces'
  // noise. The first that closes counts; the error is the first attempt's, followed by the
  // last error of each later kind that applied.
  ClosingResult first = close_hole(mesh, faces, hole, Attempt{});
  if (first.closed || !later_attempts)
    return first;
  struct Try {
    Attempt attempt;
    const char* note;
    const char* error_label;  // the failure reported after the first attempt's, if any
  };
  const char* on_edges = "loop vertices on the rebuilt edges used as its corners";
  std::vector<Try> tries{
      {Attempt{true, false, false}, on_edges, nullptr},
      {Attempt{true, true, false}, on_edges,
       "split at the loop's vertices and in the loop's order"},
      {Attempt{false, true, false}, "", nullptr},
      {Attempt{false, true, true}, "", nullptr},
      {Attempt{true, true, true}, on_edges, "in the parts' own planes"},
  };
  if (hole.k() == 3) {
    for (int j = 0; j < 3; ++j) {
      for (bool into_previous : {true, false}) {
        for (bool vertices_on_edges : {false, true}) {
          tries.push_back({Attempt{vertices_on_edges, true, true, j, into_previous},
                           vertices_on_edges ? on_edges : "",
                           "with a face's run of at most one edge given to a neighbour (k = 2)"});
        }
      }
    }
  }
  if (hole.k() >= 2) {
    Attempt one_plane{false, true, true};
    one_plane.one_plane = true;
    tries.push_back({one_plane, "", "as one part in the loop's plane"});
  }
  std::vector<std::pair<std::string, std::string>> errors;  // by label, the last of each
  for (const Try& t : tries) {
    if (t.attempt.loop_vertices_on_edges && hole.k() < 2)
      continue;
    bool applicable = true;
    ClosingResult result = close_hole(mesh, faces, hole, t.attempt, &applicable);
    if (!applicable)
      continue;
    if (!result.closed) {
      if (t.error_label != nullptr) {
        const auto same = std::find_if(errors.begin(), errors.end(),
                                       [&](const auto& e) { return e.first == t.error_label; });
        if (same != errors.end())
          same->second = result.error;
        else
          errors.push_back({t.error_label, result.error});
      }
      continue;
    }
    std::string note = t.note;
    if (!result.note.empty())
      note += (note.empty() ? "" : "; ") + result.note;
    result.note = note;
    return result;
  }
  for (const auto& [label, error] : errors)
    first.error += "; " + label + ": " + error;
  return first;
}

}  // namespace holebench::brep_guidance
