#include "methods/brep_guidance/closing_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace holebench::brep_guidance {

bool same_corner(const PolygonCorner& a, const PolygonCorner& b) {
  return a.vertex.is_valid() ? a.vertex == b.vertex : a.new_index == b.new_index;
}

namespace {

// The hole's loop as the plan reads it.
struct HoleLoop {
  std::vector<VertexHandle> vertices;  // in the faces' order
  std::vector<int> run_start;          // run i starts at vertices[run_start[i]], transition i
  double spacing = 0.0;                // the hole's mean edge length: the new points' spacing
  double exact = 0.0;                  // 1e-9 of the loop's extent (at least 1e-9)
  int size() const { return static_cast<int>(vertices.size()); }
};

double mean_edge_length(const Mesh& mesh, const Hole& hole) {
  double sum = 0.0;
  for (auto h : hole.halfedges)
    sum += mesh.calc_edge_length(h);
  return sum / static_cast<double>(hole.halfedges.size());
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

HoleLoop loop_of(const Mesh& mesh, const Hole& hole) {
  HoleLoop loop;
  loop.spacing = mean_edge_length(mesh, hole);
  for (const auto& run : hole.runs) {
    loop.run_start.push_back(loop.size());
    for (auto h : run)
      loop.vertices.push_back(mesh.from_vertex_handle(h));
  }
  loop.exact = 1e-9 * std::max(1.0, bounding_box_diagonal_of_points(mesh, loop.vertices));
  return loop;
}

// New points strictly between a and b, at about `spacing`.
std::vector<Point> interior_points(const Point& a, const Point& b, double spacing) {
  const int pieces = std::max(1, static_cast<int>(std::round((b - a).norm() / spacing)));
  std::vector<Point> points;
  for (int j = 1; j < pieces; ++j)
    points.push_back(a + (b - a) * (static_cast<double>(j) / pieces));
  return points;
}

PolygonCorner add_new_point(ClosingPlan& plan, const Point& p) {
  plan.new_points.push_back(p);
  return PolygonCorner{VertexHandle(), p, static_cast<int>(plan.new_points.size()) - 1};
}

// The whole loop as one part of face `region`.
PlannedFace whole_loop(const Mesh& mesh, const HoleLoop& loop, int region,
                       std::optional<Plane> plane) {
  PlannedFace face{region, {}, plane};
  for (auto v : loop.vertices)
    face.polygon.push_back({v, mesh.point(v)});
  return face;
}

// The one_plane attempt. The faces' common lines are ill-defined where the loop lies in one
// plane within their noise (two nearly parallel planes of one segmented face; a face's plane
// edge-on to the hole): the whole loop is one part in the loop's own plane. Its faces are
// those of the face with the longest run. False where the loop is not in one plane.
bool plan_in_one_plane(const Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                       const HoleLoop& loop, ClosingPlan& plan) {
  const int k = hole.k();
  std::vector<Point> points;
  for (auto v : loop.vertices)
    points.push_back(mesh.point(v));
  const PlaneFit fit = fit_plane(points);
  double noise = 0.0;
  for (int face : hole.faces)
    noise = std::max(noise, faces.planes[face].plane.rms_residual);
  if (k < 2 || !fit.valid || fit.plane.rms_residual > 3.0 * noise)
    return false;
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
  plan.note = "the loop closed as one part in its own least-squares plane (RMS residual " +
              std::string(residuals) + "), its faces those of face " +
              std::to_string(hole.faces[longest]);
  plan.faces.push_back(whole_loop(mesh, loop, hole.faces[longest], fit.plane));
  return true;
}

// L_i: the line where the fitted planes of f_{i-1} and f_i meet, the paper's rebuilt edge. A
// loop vertex counts as lying on it within the planes' noise (three times their RMS
// residual, at most a quarter of the hole's mean edge length, at least 1e-9 of the hole's
// extent).
struct CommonLine {
  Point point, direction;
  double tolerance = 0.0;
  Point project(const Point& p) const {
    return point + direction * OpenMesh::dot(p - point, direction);
  }
  bool holds(const Point& p) const { return (p - project(p)).norm() <= tolerance; }
};

std::vector<CommonLine> common_lines(const BrepFaces& faces, const Hole& hole,
                                     const HoleLoop& loop) {
  const int k = hole.k();
  std::vector<CommonLine> lines(k);
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
    const double noise = 3.0 * std::max(a.rms_residual, b.rms_residual);
    lines[i] = {T + a.normal * alpha + b.normal * beta, direction,
                std::max(loop.exact, std::min(noise, 0.25 * loop.spacing))};
  }
  return lines;
}

// Where a hole runs along the faces' common line for a while (one face's triangles are kept
// there, the other's removed), those edges still exist: the rebuilt edge starts where the
// loop leaves the line. E_i is that vertex, found from T_i forward through run i or else
// backward through run i-1; the loop between E_i and E_{i+1} is then the part face f_i
// extends. The E_i as indices into the loop.
std::vector<int> rebuilt_edge_starts(const Mesh& mesh, const HoleLoop& loop,
                                     const std::vector<CommonLine>& lines) {
  const int k = static_cast<int>(lines.size()), n = loop.size();
  const auto on_line = [&](int index, int i) {
    return lines[i].holds(mesh.point(loop.vertices[index]));
  };
  std::vector<int> split(k);
  for (int i = 0; i < k; ++i) {
    const int index = loop.run_start[i];
    const int run_end = i + 1 < k ? loop.run_start[i + 1] : n;
    int forward = index;
    while (forward + 1 < run_end && on_line(forward + 1, i))
      ++forward;
    if (forward != index) {
      split[i] = forward;
      continue;
    }
    const int previous_start = loop.run_start[(i + k - 1) % k];
    int backward = index;
    while (backward != previous_start && on_line((backward + n - 1) % n, i))
      backward = (backward + n - 1) % n;
    split[i] = backward;
  }
  return split;
}

// The parts of a closing on rebuilt edges: part i is the loop from E_i (split[i]) to E_{i+1},
// on face faces[i], between the rebuilt edges on lines[i] and lines[i + 1].
struct Parts {
  std::vector<int> split;
  std::vector<CommonLine> lines;
  std::vector<int> faces;
  int count() const { return static_cast<int>(split.size()); }
};

// A face whose part is at most one loop edge (E_j to E_{j+1}) barely borders the hole: where
// the three planes' corner S lies beyond that edge, outside the hole, the plan's rebuilt
// edges run out to S and back and cross the mesh there. The absorbing attempt gives that run
// to a neighbouring face and closes the hole as k = 2 on the common line of the other two
// faces (L_b, the line of faces a = j + 1 and b = j + 2), without S: E_b and, on the run's
// other side, E_{j+1} (into the previous face b) or E_j (into the next face a) are the
// rebuilt edge's ends. False where the attempt does not apply.
bool absorb_face(const Hole& hole, const ClosingAttempt& attempt, int n, Parts& parts,
                 std::string& note) {
  const int k = hole.k();
  const std::vector<int>& split = parts.split;
  const int j = attempt.absorbed_face, a = (j + 1) % k, b = (j + 2) % k;
  const int run_edges = (split[a] - split[j] + n) % n;
  if (k != 3 || run_edges > 1 || (!attempt.into_previous && run_edges == 0))
    return false;
  const int receiver = attempt.into_previous ? b : a;
  note = "face " + std::to_string(hole.faces[j]) + "'s run of " + std::to_string(run_edges) +
         (run_edges == 1 ? " edge" : " edges") + " given to face " +
         std::to_string(hole.faces[receiver]) + ", closed as k = 2 on the common line of faces " +
         std::to_string(hole.faces[a]) + " and " + std::to_string(hole.faces[b]) +
         " without the corner S";
  const CommonLine line_b = parts.lines[b];
  parts.split = {attempt.into_previous ? split[a] : split[j], split[b]};
  parts.lines = {line_b, line_b};
  parts.faces = {hole.faces[a], hole.faces[b]};
  return true;
}

// The corners strictly between `from` and `to` on `line`: new points at about the loop's
// spacing, and (loop_vertices_on_edges) the loop vertices on the segment other than `ends`,
// without the new points within half a spacing of them; by distance from `from`.
std::vector<PolygonCorner> edge_corners(const Mesh& mesh, const HoleLoop& loop,
                                        const CommonLine& line, const Point& from, const Point& to,
                                        const std::vector<VertexHandle>& ends,
                                        bool loop_vertices_on_edges, ClosingPlan& plan) {
  const double spacing = loop.spacing;
  std::vector<std::pair<double, PolygonCorner>> on_edge;  // by distance from `from`
  const double length = (to - from).norm();
  if (loop_vertices_on_edges && length > 0.0) {
    const Point along = (to - from) / length;
    for (auto v : loop.vertices) {
      if (std::find(ends.begin(), ends.end(), v) != ends.end() || !line.holds(mesh.point(v)))
        continue;
      const double t = OpenMesh::dot(mesh.point(v) - from, along);
      if (t > 0.25 * spacing && t < length - 0.25 * spacing)
        on_edge.push_back({t, PolygonCorner{v, mesh.point(v)}});
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
    on_edge.push_back({t, add_new_point(plan, p)});
  std::stable_sort(on_edge.begin(), on_edge.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<PolygonCorner> corners;
  for (const auto& e : on_edge)
    corners.push_back(e.second);
  return corners;
}

// The rebuilt edges' inner corners, shared by the two faces along each: inner[i] runs from
// Q_i towards the common end (S for three parts; for two, inner[1] from Q_2 to Q_1). With
// three parts, v_s.
struct RebuiltEdges {
  std::vector<std::vector<PolygonCorner>> inner;
  PolygonCorner vs;
};

// Q_i: E_i projected onto L_i. The rebuilt edge runs on L_i from Q_i on; its end corner is
// E_i itself, which is input and stays where it is (on L_i on clean input; off it by the
// noise otherwise). A new end vertex at Q_i would need a short edge E_i -> Q_i that crosses
// the rebuilt edge's side whenever noise puts E_i beyond the line, so it is not made.
RebuiltEdges rebuild_edges(const Mesh& mesh, const Hole& hole, const HoleLoop& loop,
                           const Parts& parts, bool loop_vertices_on_edges, ClosingPlan& plan) {
  const int count = parts.count();
  std::vector<Point> q(count);
  for (int i = 0; i < count; ++i)
    q[i] = parts.lines[i].project(mesh.point(loop.vertices[parts.split[i]]));
  RebuiltEdges edges;
  edges.inner.resize(count);
  std::vector<VertexHandle> ends;  // the E_i: never corners inside a rebuilt edge
  for (int i = 0; i < count; ++i)
    ends.push_back(loop.vertices[parts.split[i]]);
  const auto corners_between = [&](int i, const Point& from, const Point& to) {
    return edge_corners(mesh, loop, parts.lines[i], from, to, ends, loop_vertices_on_edges, plan);
  };
  if (count != 3) {
    edges.inner[1] = corners_between(1, q[1], q[0]);  // Q_2 to Q_1
    return edges;
  }
  // v_s is a new vertex at S, unless the loop already passes through the corner (a face whose
  // run lies on its two common lines): then that vertex is v_s.
  const double near =
      std::min({parts.lines[0].tolerance, parts.lines[1].tolerance, parts.lines[2].tolerance});
  VertexHandle corner;
  for (auto v : loop.vertices) {
    if ((mesh.point(v) - *hole.S).norm() <= near)
      corner = v;
  }
  edges.vs =
      corner.is_valid() ? PolygonCorner{corner, mesh.point(corner)} : add_new_point(plan, *hole.S);
  if (corner.is_valid())
    ends.push_back(corner);
  for (int i = 0; i < 3; ++i) {
    // Q_i and S both lie on L_i: the points between them do too.
    edges.inner[i] = corners_between(i, q[i], *hole.S);
  }
  return edges;
}

// A corner met twice in a row (E_i = E_{i+1}, or v_s on the loop) is one corner.
std::vector<PolygonCorner> without_repeated_corners(const std::vector<PolygonCorner>& polygon) {
  std::vector<PolygonCorner> corners;
  for (const PolygonCorner& c : polygon) {
    if (corners.empty() || !same_corner(corners.back(), c))
      corners.push_back(c);
  }
  while (corners.size() > 1 && same_corner(corners.back(), corners.front()))
    corners.pop_back();
  return corners;
}

// Part i's polygon: the loop from E_i to E_{i+1}, both included, then back along the rebuilt
// edges (through v_s for three parts).
std::vector<PolygonCorner> part_polygon(const Mesh& mesh, const HoleLoop& loop, const Parts& parts,
                                        const RebuiltEdges& edges, int i) {
  const int count = parts.count(), n = loop.size();
  const int next = (i + 1) % count;
  std::vector<PolygonCorner> polygon;
  for (int j = parts.split[i];; j = (j + 1) % n) {
    polygon.push_back({loop.vertices[j], mesh.point(loop.vertices[j])});
    if (j == parts.split[next])
      break;
  }
  const auto& inner = edges.inner;
  if (count == 3) {
    polygon.insert(polygon.end(), inner[next].begin(), inner[next].end());
    polygon.push_back(edges.vs);
    polygon.insert(polygon.end(), inner[i].rbegin(), inner[i].rend());
  } else if (i == 0) {
    polygon.insert(polygon.end(), inner[1].begin(), inner[1].end());  // Q_2 -> Q_1
  } else {
    polygon.insert(polygon.end(), inner[1].rbegin(), inner[1].rend());  // Q_1 -> Q_2
  }
  return without_repeated_corners(polygon);
}

// k = 2, 3: the parts between the rebuilt edges (figure 4). False where the attempt does not
// apply.
bool plan_on_rebuilt_edges(const Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                           const HoleLoop& loop, const ClosingAttempt& attempt, ClosingPlan& plan) {
  Parts parts;
  parts.lines = common_lines(faces, hole, loop);
  parts.split = rebuilt_edge_starts(mesh, loop, parts.lines);
  parts.faces = hole.faces;
  if (attempt.absorbed_face >= 0 && !absorb_face(hole, attempt, loop.size(), parts, plan.note))
    return false;
  const RebuiltEdges edges =
      rebuild_edges(mesh, hole, loop, parts, attempt.loop_vertices_on_edges, plan);
  for (int i = 0; i < parts.count(); ++i) {
    PlannedFace face{parts.faces[i], part_polygon(mesh, loop, parts, edges, i), std::nullopt};
    // At most two corners: the part is at most an edge (on the common line, or E_i -> v_s
    // when E_i = E_{i+1}), which the neighbouring faces' parts close; nothing to fill.
    if (face.polygon.size() <= 2)
      continue;
    plan.faces.push_back(std::move(face));
  }
  return true;
}

}  // namespace

ClosingPlan plan_closing(const Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                         const ClosingAttempt& attempt) {
  ClosingPlan plan;
  const HoleLoop loop = loop_of(mesh, hole);
  if (attempt.one_plane)
    plan.applicable = plan_in_one_plane(mesh, faces, hole, loop, plan);
  else if (hole.k() == 1)
    plan.faces.push_back(whole_loop(mesh, loop, hole.faces[0], std::nullopt));
  else
    plan.applicable = plan_on_rebuilt_edges(mesh, faces, hole, loop, attempt, plan);
  return plan;
}

}  // namespace holebench::brep_guidance
