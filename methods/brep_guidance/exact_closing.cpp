#include "methods/brep_guidance/exact_closing.h"

#include "methods/common/planar_polygon_triangulation.h"

#include <algorithm>
#include <cmath>

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

}  // namespace

ClosingResult close_hole_exactly(Mesh& mesh, const BrepFaces& faces, const Hole& hole) {
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
      for (int i = 0; i < 3; ++i) {
        // Q_i and S both lie on L_i: the points between them do too.
        for (const Point& p : interior_points(q[i].position, *hole.S, spacing))
          edge_points[i].push_back(add_new(p));
      }
    } else {
      for (const Point& p : interior_points(q[1].position, q[0].position, spacing))
        edge_points[1].push_back(add_new(p));  // from Q_2 to Q_1
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
      auto same = [](const Corner& a, const Corner& b) {
        return a.vertex.is_valid() ? a.vertex == b.vertex : a.new_index == b.new_index;
      };
      std::vector<Corner> corners;
      for (const Corner& c : face.polygon) {
        if (corners.empty() || !same(corners.back(), c))
          corners.push_back(c);
      }
      while (corners.size() > 1 && same(corners.back(), corners.front()))
        corners.pop_back();
      face.polygon = std::move(corners);
      // At most two input vertices: the part is at most an edge on the common line, which
      // the other face's part closes; nothing to fill.
      if (face.polygon.size() <= 2 &&
          std::all_of(face.polygon.begin(), face.polygon.end(),
                      [](const Corner& c) { return c.vertex.is_valid(); }))
        continue;
      planned.push_back(std::move(face));
    }
  }

  // Triangulate every face polygon first; touch the mesh only when all succeeded.
  std::vector<std::vector<std::array<int, 3>>> triangles;
  for (const auto& face : planned) {
    std::vector<Point> points;
    for (const auto& c : face.polygon)
      points.push_back(c.position);
    const auto triangulation = triangulate_planar_polygon(points, faces.planes[face.region].plane);
    if (!triangulation.ok) {
      result.error = "face " + std::to_string(face.region) + " (" + std::to_string(points.size()) +
                     " corners): " + triangulation.error;
      return result;
    }
    triangles.push_back(triangulation.triangles);
  }
  // A triangle edge between two existing vertices that the mesh already joins (outside the
  // hole) would be used three times.
  for (std::size_t f = 0; f < planned.size(); ++f) {
    const auto& polygon = planned[f].polygon;
    const int size = static_cast<int>(polygon.size());
    for (const auto& t : triangles[f]) {
      for (int e = 0; e < 3; ++e) {
        const int a = t[e], b = t[(e + 1) % 3];
        if ((a + 1) % size == b || (b + 1) % size == a)
          continue;  // a side of the polygon
        const VertexHandle va = polygon[a].vertex, vb = polygon[b].vertex;
        if (va.is_valid() && vb.is_valid() && mesh.find_halfedge(va, vb).is_valid()) {
          result.error = "face " + std::to_string(planned[f].region) +
                         ": a closing triangle's diagonal is an existing edge of the mesh "
                         "(non-manifold)";
          return result;
        }
      }
    }
  }

  const Mesh backup = mesh;
  std::vector<VertexHandle> new_vertices;
  for (const Point& p : new_points)
    new_vertices.push_back(mesh.add_vertex(p));
  for (std::size_t f = 0; f < planned.size(); ++f) {
    const auto& polygon = planned[f].polygon;
    auto handle = [&](int index) {
      const Corner& c = polygon[index];
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
      ++result.new_faces;
    }
  }
  result.new_vertices = new_points.size();
  result.closed = true;
  return result;
}

}  // namespace holebench::brep_guidance
