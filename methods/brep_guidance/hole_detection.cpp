#include "methods/brep_guidance/hole_detection.h"

#include <Eigen/Dense>

#include <cmath>

namespace holebench::brep_guidance {
namespace {

// A half-edge "has a twin" in the B-Rep sense when the half-edge opposite it belongs to a
// face; the hole half-edges are face half-edges whose opposite is a mesh boundary.
bool has_twin(const Mesh& mesh, HalfedgeHandle c) {
  return !mesh.is_boundary(mesh.opposite_halfedge_handle(c));
}

// successor(c): the half-edge after c in its face's loop.
HalfedgeHandle successor(const Mesh& mesh, HalfedgeHandle c) {
  return mesh.next_halfedge_handle(c);
}

// Algorithm 1. The listing's line 9 reads "c = twin(c)  (return to the hole)"; taken
// literally the next iteration would step back to c. We read it as c = successor(twin(c)),
// which turns around the vertex, face by face, until the next half-edge without twin.
std::vector<std::vector<HalfedgeHandle>> algorithm_1(const Mesh& mesh) {
  std::vector<std::vector<HalfedgeHandle>> holes;
  std::vector<char> visited(mesh.n_halfedges(), 0);
  for (auto start : mesh.halfedges()) {
    // line 2-3: an unvisited half-edge without twin (that belongs to a face)
    if (visited[start.idx()] || mesh.is_boundary(start) || has_twin(mesh, start))
      continue;
    visited[start.idx()] = 1;
    std::vector<HalfedgeHandle> hole{start};
    HalfedgeHandle c = successor(mesh, start);
    std::size_t guard = 0;
    while (c != start && guard++ <= 4 * mesh.n_halfedges()) {
      if (has_twin(mesh, c)) {
        c = successor(mesh, mesh.opposite_halfedge_handle(c));  // return to the hole
      } else {
        hole.push_back(c);
        visited[c.idx()] = 1;
        c = successor(mesh, c);
      }
    }
    holes.push_back(std::move(hole));
  }
  return holes;
}

Point plane_normal(const BrepFaces& faces, int region) {
  return faces.planes[region].plane.normal;
}

Point unit(const Point& d) {
  const double length = d.norm();
  return length > 0.0 ? d / length : Point(0, 0, 0);
}

bool in_region(const Mesh& mesh, const BrepFaces& faces, HalfedgeHandle h, int region) {
  return !mesh.is_boundary(h) && faces.face_region[mesh.face_handle(h).idx()] == region;
}

// How many boundary half-edges of a face, from t on, give the transition half-edge's
// direction: their chord smooths the staircase of a segmented region's boundary.
constexpr int kTransitionEdges = 3;

// The half-edge of `region`'s boundary before h (both ending / starting at h's from vertex):
// turn around that vertex through the region's triangles.
HalfedgeHandle previous_on_boundary(const Mesh& mesh, const BrepFaces& faces, HalfedgeHandle h,
                                    int region) {
  HalfedgeHandle g = mesh.prev_halfedge_handle(h);
  for (std::size_t guard = 0; guard < mesh.n_halfedges(); ++guard) {
    const HalfedgeHandle o = mesh.opposite_halfedge_handle(g);
    if (!in_region(mesh, faces, o, region))
      return g;
    g = mesh.prev_halfedge_handle(o);
  }
  return HalfedgeHandle();
}

// The half-edge of `region`'s boundary after h.
HalfedgeHandle next_on_boundary(const Mesh& mesh, const BrepFaces& faces, HalfedgeHandle h,
                                int region) {
  HalfedgeHandle g = mesh.next_halfedge_handle(h);
  for (std::size_t guard = 0; guard < mesh.n_halfedges(); ++guard) {
    const HalfedgeHandle o = mesh.opposite_halfedge_handle(g);
    if (!in_region(mesh, faces, o, region))
      return g;
    g = mesh.next_halfedge_handle(o);
  }
  return HalfedgeHandle();
}

int region_across(const Mesh& mesh, const BrepFaces& faces, HalfedgeHandle h) {
  const HalfedgeHandle o = mesh.opposite_halfedge_handle(h);
  return mesh.is_boundary(o) ? -1 : faces.face_region[mesh.face_handle(o).idx()];
}

// The unit chord of up to kTransitionEdges consecutive boundary half-edges of `region` along
// the same neighbouring face, from the transition vertex t outwards: walking back from
// `hole_edge` (`into` t: the half-edges before it, ending in t) or on from it (out of t).
Point transition_chord(const Mesh& mesh, const BrepFaces& faces, HalfedgeHandle hole_edge,
                       int region, bool into) {
  auto step = [&](HalfedgeHandle h) {
    return into ? previous_on_boundary(mesh, faces, h, region)
                : next_on_boundary(mesh, faces, h, region);
  };
  auto far_end = [&](HalfedgeHandle h) {
    return mesh.point(into ? mesh.from_vertex_handle(h) : mesh.to_vertex_handle(h));
  };
  HalfedgeHandle h = step(hole_edge);
  if (!h.is_valid())
    return Point(0, 0, 0);
  const Point at_t = mesh.point(into ? mesh.to_vertex_handle(h) : mesh.from_vertex_handle(h));
  const int neighbour = region_across(mesh, faces, h);
  Point far = far_end(h);
  for (int e = 1; e < kTransitionEdges && neighbour >= 0; ++e) {
    h = step(h);
    if (!h.is_valid() || region_across(mesh, faces, h) != neighbour)
      break;
    far = far_end(h);
  }
  return into ? unit(at_t - far) : unit(far - at_t);
}

// h_i: the boundary of f_i (`region`) that ends in t, before `first` (the first hole
// half-edge of f_i, starting in t).
Point transition_into(const Mesh& mesh, const BrepFaces& faces, HalfedgeHandle first, int region) {
  return transition_chord(mesh, faces, first, region, true);
}

// The boundary of f_{i-1} (`region`) that starts in t, after `last` (its last hole half-edge,
// ending in t).
Point transition_out_of(const Mesh& mesh, const BrepFaces& faces, HalfedgeHandle last, int region) {
  return transition_chord(mesh, faces, last, region, false);
}

// The point common to three planes, or nothing when they are (nearly) dependent.
std::optional<Point> intersect_planes(const BrepFaces& faces, int a, int b, int c,
                                      double tolerance) {
  Eigen::Matrix3d normals;
  Eigen::Vector3d offsets;
  int row = 0;
  for (int region : {a, b, c}) {
    const Plane& p = faces.planes[region].plane;
    normals.row(row) << p.normal[0], p.normal[1], p.normal[2];
    offsets[row] = OpenMesh::dot(p.normal, p.point);
    ++row;
  }
  if (std::abs(normals.determinant()) < tolerance)
    return std::nullopt;
  const Eigen::Vector3d x = normals.partialPivLu().solve(offsets);
  return Point(x[0], x[1], x[2]);
}

}  // namespace

std::vector<Hole> detect_holes(const Mesh& mesh, const BrepFaces& faces,
                               double dependence_tolerance) {
  std::vector<Hole> holes;
  for (auto& loop : algorithm_1(mesh)) {
    Hole hole;
    auto region_of = [&](HalfedgeHandle h) { return faces.face_region[mesh.face_handle(h).idx()]; };
    // Start the loop where it enters a new face, so that runs are contiguous.
    const std::size_t n = loop.size();
    std::size_t first = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (region_of(loop[i]) != region_of(loop[(i + n - 1) % n])) {
        first = i;
        break;
      }
    }
    std::rotate(loop.begin(), loop.begin() + first, loop.end());
    hole.halfedges = loop;
    for (auto h : loop) {
      if (hole.runs.empty() || region_of(h) != hole.faces.back()) {
        hole.faces.push_back(region_of(h));
        hole.runs.emplace_back();
      }
      hole.runs.back().push_back(h);
      hole.centroid += mesh.point(mesh.from_vertex_handle(h));
    }
    hole.centroid /= static_cast<double>(n);
    const int k = hole.k();
    if (k >= 2) {
      for (int i = 0; i < k; ++i) {
        Transition t;
        t.vertex = mesh.from_vertex_handle(hole.runs[i].front());
        t.position = mesh.point(t.vertex);
        t.direction = transition_into(mesh, faces, hole.runs[i].front(), hole.faces[i]);
        t.direction_previous = transition_out_of(mesh, faces, hole.runs[(i + k - 1) % k].back(),
                                                 hole.faces[(i + k - 1) % k]);
        hole.transitions.push_back(t);
      }
      for (int i = 0; i < k; ++i) {
        hole.v.push_back(hole.transitions[(i + 1) % k].position - hole.transitions[i].position);
      }
    }
    if (k == 2) {
      const Point cross =
          OpenMesh::cross(plane_normal(faces, hole.faces[0]), plane_normal(faces, hole.faces[1]));
      hole.linearly_dependent = cross.norm() < dependence_tolerance;
    }
    if (k == 3) {
      hole.S = intersect_planes(faces, hole.faces[0], hole.faces[1], hole.faces[2],
                                dependence_tolerance);
      hole.linearly_dependent = !hole.S.has_value();
      if (hole.S) {
        for (const auto& t : hole.transitions)
          hole.s.push_back(*hole.S - t.position);
      }
    }
    holes.push_back(std::move(hole));
  }
  return holes;
}

}  // namespace holebench::brep_guidance
