#include "methods/brep_guidance/exact_closing.h"

#include "methods/common/patch_intersections.h"
#include "methods/common/planar_polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
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

// One attempt at the closing. With `loop_vertices_on_edges`, loop vertices that lie on a
// rebuilt edge (within the lines' tolerance, strictly between its ends) become corners of that
// edge instead of the new points near them; the part that passes them twice is then split
// there into polygons that touch.
// Without `loop_order`, a part whose Delaunay triangulation fails is not closed.
ClosingResult close_hole(Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                         bool loop_vertices_on_edges, bool loop_order) {
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

  if (k == 1) {
    PlannedFace face{hole.faces[0], {}};
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
    // Q_i: E_i projected onto L_i. The rebuilt edge runs on L_i from Q_i on; its end corner
    // is E_i itself, which is input and stays where it is (on L_i on clean input; off it by
    // the noise otherwise). A new end vertex at Q_i would need a short edge E_i -> Q_i that
    // crosses the rebuilt edge's side whenever noise puts E_i beyond the line, so it is not
    // made.
    std::vector<Corner> q(k);
    for (int i = 0; i < k; ++i)
      q[i] = {loop[split[i]], lines[i].project(mesh.point(loop[split[i]]))};
    // The rebuilt edges' inner points, shared by the two faces along each.
    std::vector<std::vector<Corner>> edge_points(k);  // from Q_i towards the common end
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
    for (int i = 0; i < k; ++i)
      ends.push_back(loop[split[i]]);
    Corner vs;
    if (k == 3) {
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
    for (int i = 0; i < k; ++i) {
      const int next = (i + 1) % k;
      PlannedFace face{hole.faces[i], {}};
      // The loop from E_i to E_{i+1}, both included.
      for (int j = split[i];; j = (j + 1) % n) {
        face.polygon.push_back({loop[j], mesh.point(loop[j])});
        if (j == split[next])
          break;
      }
      if (k == 3) {
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
    const Plane& plane = faces.planes[planned[f].region].plane;
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
      const auto triangulation = triangulate_planar_polygon(points, plane);
      bool usable = triangulation.ok;
      for (const auto& t : triangulation.triangles) {
        for (int e = 0; e < 3 && usable; ++e) {
          const int a = t[e], b = t[(e + 1) % 3];
          if ((a + 1) % size != b && (b + 1) % size != a && forbidden(a, b))
            usable = false;  // a diagonal the mesh or another part already has
        }
      }
      if (usable) {
        // Counter-clockwise about the normal; the mesh runs against the loop, which is
        // clockwise about the normal unless the part is turned over in its plane.
        for (auto t : triangulation.triangles) {
          if (area > 0.0)
            std::swap(t[1], t[2]);
          chosen.push_back(t);
        }
      } else {
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
                       " corners) triangulated in the loop's order (" +
                       (triangulation.ok ? std::string("the Delaunay triangulation used an "
                                                       "edge the mesh already has")
                                         : triangulation.error) +
                       "), folded area " + folded + " of the part's";
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

ClosingResult close_hole_exactly(Mesh& mesh, const BrepFaces& faces, const Hole& hole) {
  // First as planned; then with the loop's vertices on the rebuilt edges as its corners (the
  // loop touches the faces' common line between the edge's ends); then with parts whose
  // projection is not simple triangulated in the loop's order. The first that closes counts;
  // the error is the first attempt's.
  ClosingResult first = close_hole(mesh, faces, hole, false, false);
  if (first.closed)
    return first;
  std::string last_error;
  struct Attempt {
    bool loop_vertices_on_edges, loop_order;
    const char* note;
  };
  for (const Attempt& attempt :
       {Attempt{true, false, "loop vertices on the rebuilt edges used as its corners"},
        Attempt{true, true, "loop vertices on the rebuilt edges used as its corners"},
        Attempt{false, true, ""}}) {
    if (attempt.loop_vertices_on_edges && hole.k() < 2)
      continue;
    ClosingResult result =
        close_hole(mesh, faces, hole, attempt.loop_vertices_on_edges, attempt.loop_order);
    if (!result.closed) {
      if (attempt.loop_vertices_on_edges && attempt.loop_order)
        last_error = result.error;
      continue;
    }
    std::string note = attempt.note;
    if (!result.note.empty())
      note += (note.empty() ? "" : "; ") + result.note;
    result.note = note;
    return result;
  }
  if (!last_error.empty())
    first.error += "; split at the loop's vertices and in the loop's order: " + last_error;
  return first;
}

}  // namespace holebench::brep_guidance
