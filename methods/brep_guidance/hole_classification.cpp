#include "methods/brep_guidance/hole_classification.h"

#include "core/polygon.h"

#include <algorithm>
#include <cmath>

namespace holebench::brep_guidance {
namespace {

Point normal_of(const BrepFaces& faces, int region) {
  return faces.planes[region].plane.normal;
}

// Twice the signed area of a closed polygon about `normal`.
double signed_area(const std::vector<Point>& polygon, const Point& normal) {
  Point sum(0, 0, 0);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    sum += OpenMesh::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  }
  return OpenMesh::dot(sum, normal);
}

// Figure3Rule::NearestHoleVertices: the sum of the vectors from T to the `count` hole
// vertices of a face next to T.
Point direction_into_face(const Mesh& mesh, const std::vector<HalfedgeHandle>& run, bool from_start,
                          int count, const Point& T) {
  Point sum(0, 0, 0);
  const int n = static_cast<int>(run.size());
  for (int j = 0; j < std::min(count, n); ++j) {
    const auto h = from_start ? run[j] : run[n - 1 - j];
    const auto v = from_start ? mesh.to_vertex_handle(h) : mesh.from_vertex_handle(h);
    sum += mesh.point(v) - T;
  }
  return sum;
}

std::pair<Convexity, bool> convexity_by_nearest_hole_vertices(const Mesh& mesh,
                                                              const BrepFaces& faces,
                                                              const Hole& hole, int i, int count) {
  const int k = hole.k();
  const int l = (i + k - 1) % k;
  const Point n_l = normal_of(faces, hole.faces[l]);
  const Point n_i = normal_of(faces, hole.faces[i]);
  const Point T = hole.transitions[i].position;
  Point axis = OpenMesh::cross(n_l, n_i);
  const double axis_length = axis.norm();
  auto project = [&](Point d) {
    if (axis_length > 0.0)
      d -= axis * (OpenMesh::dot(d, axis) / (axis_length * axis_length));
    return d;
  };
  const Point w_l = project(direction_into_face(mesh, hole.runs[l], false, count, T));
  const Point w_i = project(direction_into_face(mesh, hole.runs[i], true, count, T));
  const double side_i = OpenMesh::dot(w_i, n_l);
  const double side_l = OpenMesh::dot(w_l, n_i);
  if (side_i < 0.0 && side_l < 0.0)
    return {Convexity::Convex, false};
  if (side_i > 0.0 && side_l > 0.0)
    return {Convexity::Reflex, false};
  const double decisive = std::abs(side_i) >= std::abs(side_l) ? side_i : side_l;
  return {decisive < 0.0 ? Convexity::Convex : Convexity::Reflex, true};
}

}  // namespace

Figure3 figure_3(const Point& T, const Point& n_i, const Point& n_j, const Point& h_i,
                 const Point& h_j, const std::vector<Point>& path_i,
                 const std::vector<Point>& path_j, int halfedges) {
  Figure3 f;
  // pi has the normal m = n_i x n_j.
  Point m = OpenMesh::cross(n_i, n_j);
  const double m_length = m.norm();
  if (m_length > 0.0)
    m /= m_length;
  auto project = [&](const Point& p) {
    const Point d = p - T;
    return d - m * OpenMesh::dot(d, m);
  };
  // Each face lies to the left of its transition half-edge; the offset of that direction
  // along the other face's normal is unchanged by the projection onto pi.
  auto side = [](const Point& n, const Point& h, const Point& n_other) {
    const double offset = OpenMesh::dot(OpenMesh::cross(n, h), n_other);
    return offset < 0.0 ? -1 : offset > 0.0 ? 1 : 0;
  };
  // The overlap: the length, in pi, of the projected hole half-edges on `side` of g_other.
  auto overlap = [&](const std::vector<Point>& path, const Point& n_other, int side) {
    double sum = 0.0;
    Point previous = T;
    const std::size_t count =
        halfedges > 0 ? std::min<std::size_t>(path.size(), halfedges) : path.size();
    for (std::size_t e = 0; e < count; ++e) {
      const Point a = project(previous), b = project(path[e]);
      previous = path[e];
      const double da = side * OpenMesh::dot(a, n_other);
      const double db = side * OpenMesh::dot(b, n_other);
      const double length = (b - a).norm();
      if (da >= 0.0 && db >= 0.0)
        sum += length;
      else if (da > 0.0 || db > 0.0)
        sum += length * std::max(da, db) / (std::abs(da) + std::abs(db));
    }
    return sum;
  };
  // Without a transition half-edge (0), the face's first hole half-edge at t whose
  // projection is more than a point stands in for its ray.
  auto side_of_path = [&](const std::vector<Point>& path, const Point& n_other) {
    Point previous = T;
    for (const Point& p : path) {
      const Point a = project(previous), b = project(p);
      if ((b - a).norm() > 1e-3 * (p - previous).norm()) {
        const double offset = OpenMesh::dot(b, n_other);
        if (offset != 0.0)
          return offset < 0.0 ? -1 : 1;
      }
      previous = p;
    }
    return 0;
  };
  f.side_i = side(n_i, h_i, n_j);
  if (f.side_i == 0 && h_i.norm() == 0.0)
    f.side_i = side_of_path(path_i, n_j);
  f.side_j = side(n_j, h_j, n_i);
  if (f.side_j == 0 && h_j.norm() == 0.0)
    f.side_j = side_of_path(path_j, n_i);
  if (f.side_i < 0 && f.side_j < 0) {
    f.convexity = Convexity::Convex;  // case (a)
    return f;
  }
  if (f.side_i > 0 && f.side_j > 0) {
    f.convexity = Convexity::Reflex;  // case (b)
    return f;
  }
  // Cases (c) and (d).
  f.decided_by_overlap = true;
  f.a_i = f.side_i != 0 ? overlap(path_i, n_j, f.side_i) : 0.0;
  f.a_j = f.side_j != 0 ? overlap(path_j, n_i, f.side_j) : 0.0;
  const int decisive = f.a_i >= f.a_j ? f.side_i : f.side_j;
  f.convexity = decisive <= 0 ? Convexity::Convex : Convexity::Reflex;
  return f;
}

Figure3 figure_3(const Mesh& mesh, const BrepFaces& faces, const Hole& hole, int i,
                 const ClassificationOptions& options) {
  const int k = hole.k();
  const int l = (i + k - 1) % k;
  // The loop passes from f_j = f_{i-1} (run l, ending in t_i) to f_i (run i, starting there).
  std::vector<Point> path_i, path_j;
  for (auto h : hole.runs[i])
    path_i.push_back(mesh.point(mesh.to_vertex_handle(h)));
  for (auto it = hole.runs[l].rbegin(); it != hole.runs[l].rend(); ++it)
    path_j.push_back(mesh.point(mesh.from_vertex_handle(*it)));
  const Transition& t = hole.transitions[i];
  return figure_3(t.position, normal_of(faces, hole.faces[i]), normal_of(faces, hole.faces[l]),
                  t.direction, t.direction_previous, path_i, path_j, options.projected_halfedges);
}

std::pair<Convexity, bool> transition_convexity(const Mesh& mesh, const BrepFaces& faces,
                                                const Hole& hole, int i,
                                                const ClassificationOptions& options) {
  if (options.figure_3_rule == Figure3Rule::NearestHoleVertices)
    return convexity_by_nearest_hole_vertices(mesh, faces, hole, i, options.nearest_hole_vertices);
  const Figure3 f = figure_3(mesh, faces, hole, i, options);
  return {f.convexity, f.decided_by_overlap};
}

BoundaryKind boundary_kind(const Mesh& mesh, const BrepFaces& faces, const Hole& hole, int i) {
  const int region = hole.faces[i];
  // Walk the region's boundary from the run's first half-edge, the region on the left: the
  // next boundary half-edge of the region is found by turning around the end vertex through
  // the region's own triangles.
  const HalfedgeHandle start = hole.runs[i].front();
  auto in_region = [&](HalfedgeHandle h) {
    return !mesh.is_boundary(h) && faces.face_region[mesh.face_handle(h).idx()] == region;
  };
  std::vector<Point> polygon;
  HalfedgeHandle h = start;
  std::size_t guard = 0;
  do {
    polygon.push_back(mesh.point(mesh.from_vertex_handle(h)));
    HalfedgeHandle next = mesh.next_halfedge_handle(h);
    while (in_region(mesh.opposite_halfedge_handle(next)) && guard++ < 4 * mesh.n_halfedges()) {
      next = mesh.next_halfedge_handle(mesh.opposite_halfedge_handle(next));
    }
    h = next;
  } while (h != start && guard++ < 4 * mesh.n_halfedges());
  // A face's outer boundary runs counter-clockwise about its normal, an inner one clockwise.
  return signed_area(polygon, normal_of(faces, region)) > 0.0 ? BoundaryKind::Outer
                                                              : BoundaryKind::Inner;
}

Classification classify_hole(const Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                             const ClassificationOptions& options) {
  Classification c;
  const int k = hole.k();
  for (int i = 0; k >= 2 && i < k; ++i) {
    const auto [convexity, by_overlap] = transition_convexity(mesh, faces, hole, i, options);
    c.convexity.push_back(convexity);
    c.decided_by_overlap.push_back(by_overlap);
  }

  std::vector<Point> loop;
  for (auto h : hole.halfedges)
    loop.push_back(mesh.point(mesh.from_vertex_handle(h)));

  // Orientation.
  if (k == 1) {
    // Inner iff enlarging the face closes the hole, i.e. the loop is an inner boundary of
    // the face: the face's half-edges around it run clockwise about the normal.
    c.orientation = signed_area(loop, normal_of(faces, hole.faces[0])) < 0.0 ? Orientation::Inner
                                                                             : Orientation::Outer;
  } else if (hole.linearly_dependent) {
    // "a hole with linear depending faces is an outer hole"
    c.orientation = Orientation::Outer;
  } else if (k == 2) {
    // Equation 1: outer <=> (n1 x n2) . v12 < 0 for convex faces, > 0 for reflex ones.
    const double product = OpenMesh::dot(
        OpenMesh::cross(normal_of(faces, hole.faces[0]), normal_of(faces, hole.faces[1])),
        hole.v[0]);
    const bool outer = c.convexity[0] == Convexity::Convex ? product < 0.0 : product > 0.0;
    c.orientation = outer ? Orientation::Outer : Orientation::Inner;
  } else if (k == 3) {
    // Equation 2: outer <=> for all i, j = (i - 1 + k) mod k:
    // (n_i x n_j) . s_i < 0 if f_i, f_j convex, > 0 if reflex.
    bool outer = true;
    for (int i = 0; i < 3; ++i) {
      const int j = (i - 1 + k) % k;
      const double product = OpenMesh::dot(
          OpenMesh::cross(normal_of(faces, hole.faces[i]), normal_of(faces, hole.faces[j])),
          hole.s[i]);
      outer = outer && (c.convexity[i] == Convexity::Convex ? product < 0.0 : product > 0.0);
    }
    c.orientation = outer ? Orientation::Outer : Orientation::Inner;
  } else {
    // k > 3: "The calculation of the orientation fails, because no intersection point is
    // available." Such holes are guided whatever their orientation.
    c.orientation = Orientation::Outer;
    c.orientation_known = false;
  }

  if (c.orientation == Orientation::Outer && c.orientation_known) {
    for (int i = 0; i < k; ++i)
      c.boundary_kinds.push_back(boundary_kind(mesh, faces, hole, i));
  }

  // Size: the largest diameter (k = 1), the largest distance to the missing edge (k = 2),
  // the distance to the missing corner (k = 3); the largest diameter otherwise.
  if (c.orientation == Orientation::Inner && k == 2 && !hole.linearly_dependent) {
    const Plane& a = faces.planes[hole.faces[0]].plane;
    const Plane& b = faces.planes[hole.faces[1]].plane;
    Point direction = OpenMesh::cross(a.normal, b.normal);
    direction /= direction.norm();
    // A point on both planes: T_1 moved onto the line by two orthogonal corrections.
    Point on_line = hole.transitions[0].position;
    for (int pass = 0; pass < 8; ++pass) {
      on_line -= a.normal * a.signed_distance(on_line);
      on_line -= b.normal * b.signed_distance(on_line);
    }
    for (const Point& p : loop) {
      const Point d = p - on_line;
      c.size = std::max(c.size, (d - direction * OpenMesh::dot(d, direction)).norm());
    }
  } else if (c.orientation == Orientation::Inner && k == 3 && hole.S) {
    for (const Point& p : loop)
      c.size = std::max(c.size, (p - *hole.S).norm());
  } else {
    c.size = diameter(loop);
  }

  c.decision = c.orientation == Orientation::Inner && c.orientation_known && k <= 3 &&
                       !hole.linearly_dependent && c.size < options.structure_size
                   ? Decision::CloseAutomatically
                   : Decision::Guide;
  return c;
}

HoleLabels to_labels(const Hole& hole, const Classification& c, double structure_size) {
  HoleLabels labels;
  const int k = hole.k();
  labels.k = k;
  // Faces' order f_1..f_k reversed; transitions[j] of the labels lies between their
  // regions[j] and regions[j + 1] = our f_{k-1-j} and f_{k-2-j}: our convexity[k-1-j].
  for (int j = 0; j < k; ++j)
    labels.regions.push_back(hole.faces[k - 1 - j]);
  if (k >= 2) {
    for (int j = 0; j < k; ++j)
      labels.transitions.push_back(c.convexity[k - 1 - j]);
  }
  labels.orientation = c.orientation;
  labels.orientation_known = c.orientation_known;
  if (!c.boundary_kinds.empty()) {
    for (int j = 0; j < k; ++j)
      labels.boundary_kinds.push_back(c.boundary_kinds[k - 1 - j]);
  }
  labels.linearly_dependent_faces = hole.linearly_dependent;
  labels.size = c.size;
  labels.structure_size = structure_size;
  labels.expected_decision = c.decision;
  return labels;
}

}  // namespace holebench::brep_guidance
